#pragma once
// The Cohesion-number evaluation as JSON, one shape for `demcal cohesion --json` and the
// reproduce workflow's stage 2 (docs/reproduce.md): the convention, the inputs, the results.
#include <nlohmann/json.hpp>

#include "calibrate/cohesion_scaling.h"

namespace demcal::workflow {

inline constexpr const char* kCohesionConvention =
    "E* = E/(2(1-nu^2)) (two like particles); R* = the granule radius R";

// Json: nlohmann::json or nlohmann::ordered_json (the command keeps the documented key order).
template <class Json>
Json CohesionJson(const calibrate::CohesionInputs& in, const calibrate::CohesionReport& r) {
  return Json{{"convention", kCohesionConvention},
              {"inputs", {{"gamma_J_m2", in.gamma_J_m2}, {"youngs_real_Pa", in.youngs_real_Pa},
                          {"youngs_sim_Pa", in.youngs_sim_Pa}, {"poisson_ratio", in.poisson_ratio},
                          {"radius_m", in.radius_m}, {"density_kg_m3", in.density_kg_m3},
                          {"gravity_m_s2", in.gravity_m_s2},
                          {"reference_gamma_sim_J_m2", in.reference_gamma_sim_J_m2}}},
              {"effective_youngs_real_Pa", r.effective_youngs_real_Pa},
              {"effective_youngs_sim_Pa", r.effective_youngs_sim_Pa},
              {"effective_radius_m", r.effective_radius_m},
              {"cohesion_number", r.cohesion_number},
              {"cohesion_number_pair_radius", r.cohesion_number_pair_radius},
              {"gamma_sim_J_m2", r.gamma_sim_J_m2},
              {"youngs_sim_for_reference_Pa", r.youngs_sim_for_reference_Pa}};
}

}  // namespace demcal::workflow
