#include "experiments/common/experiment_setup.h"

#include "core/io/vtk_writer.h"
#include "core/simulation/simulation.h"

namespace demcal::workflow {

objectives::RunHooks ReplicateHooks(ReplicateProgress& progress, int r, const std::string& out_dir,
                                    const std::string& vtk_stem, std::string* output_error) {
  objectives::RunHooks hooks;
  hooks.progress = [&progress, r](double t, double end) { progress.Update(r, t, end); };
  const std::string path = out_dir + "/" + vtk_stem + "_r" + std::to_string(r) + ".vtk";
  hooks.on_finish = [path, output_error](const core::Simulation& sim) {
    core::io::WriteParticlesVtk(path, sim.particles(), sim.time_s(), {}, output_error,
                                &sim.system().clumps);
  };
  return hooks;
}

std::string FirstError(const std::vector<std::string>& errors) {
  for (const std::string& e : errors)
    if (!e.empty()) return e;
  return "";
}

std::vector<std::string> SpeciesNames(const core::Scene& model) {
  std::vector<std::string> names;
  for (const core::Species& s : model.species) names.push_back(s.name);
  return names;
}

}  // namespace demcal::workflow
