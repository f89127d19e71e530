#include "apps/cohesion_command.h"

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "apps/cli_checks.h"
#include "calibrate/cohesion_scaling.h"
#include "outputs/exit_codes.h"
#include "workflow/reproduce/cohesion_json.h"

namespace demcal::apps {
namespace {

struct CohesionOptions {
  calibrate::CohesionInputs in;
  bool json = false;
};

int Run(const CohesionOptions& o) {
  std::string error;
  if (!o.in.IsValid(&error)) {
    std::cerr << "error: " << error << "\n";
    return workflow::kExitInvalidInput;
  }
  const calibrate::CohesionReport r = calibrate::EvaluateCohesion(o.in);
  if (o.json) {
    nlohmann::ordered_json j{{"format", "demcal-cohesion/1"}};
    j.update(workflow::CohesionJson<nlohmann::ordered_json>(o.in, r));
    std::cout << j.dump(2) << "\n";
    return workflow::kExitOk;
  }
  std::cout << "Convention: " << workflow::kCohesionConvention << "\n"
            << "Cohesion number Coh = " << r.cohesion_number << " (with R* = R/2: "
            << r.cohesion_number_pair_radius << ")\n"
            << "Gamma at E = " << o.in.youngs_sim_Pa / 1e9 << " GPa (constant Coh): "
            << r.gamma_sim_J_m2 << " J/m2\n"
            << "The reference " << o.in.reference_gamma_sim_J_m2 << " J/m2 would need E = "
            << r.youngs_sim_for_reference_Pa / 1e9 << " GPa (Gamma ~ E*^(2/5))\n";
  return workflow::kExitOk;
}

}  // namespace

Command AddCohesionCommand(CLI::App& parent) {
  auto o = std::make_shared<CohesionOptions>();
  CLI::App* app = parent.add_subcommand(
      "cohesion", "Cohesion number of a coated granule and Gamma at a softer simulation stiffness");
  namespace limits = objectives::limits;
  app->add_option("--gamma-J-m2", o->in.gamma_J_m2, "interfacial energy at the real stiffness (2 gamma_PEG = 0.086)")
      ->check(InLimit(limits::kCohesionGamma, "J/m2"));
  app->add_option("--youngs-real-Pa", o->in.youngs_real_Pa, "real Young's modulus (1.6e9)")
      ->check(InLimit(limits::kCohesionYoungs, "Pa"));
  app->add_option("--youngs-sim-Pa", o->in.youngs_sim_Pa, "simulation Young's modulus (0.25e9)")
      ->check(InLimit(limits::kCohesionYoungs, "Pa"));
  app->add_option("--poisson-ratio", o->in.poisson_ratio, "Poisson ratio (0.25)")
      ->check(InLimit(limits::kCohesionPoisson));
  app->add_option("--radius-m", o->in.radius_m, "granule radius, used as R* (325e-6)")
      ->check(InLimit(limits::kCohesionRadius, "m"));
  app->add_option("--density-kg-m3", o->in.density_kg_m3, "granule density (2320)")
      ->check(InLimit(limits::kCohesionDensity, "kg/m3"));
  app->add_option("--gravity-m-s2", o->in.gravity_m_s2, "gravity (9.81)")
      ->check(InLimit(limits::kCohesionGravity, "m/s2"));
  app->add_option("--reference-gamma-J-m2", o->in.reference_gamma_sim_J_m2,
                  "a carried Gamma to compare with (the paper's 0.046)")
      ->check(InLimit(limits::kCohesionGamma, "J/m2"));
  app->add_flag("--json", o->json, "print JSON on stdout");
  return {app, [o] { return Run(*o); }};
}

}  // namespace demcal::apps
