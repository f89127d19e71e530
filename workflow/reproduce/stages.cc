#include <cmath>

#include "workflow/reproduce/stages.h"

#include "files/json_document.h"

namespace demcal::workflow {

const std::vector<Stage>& ReproduceStages() {
  static const std::vector<Stage> stages = {
      {"species", "Species: friction against each repose angle", &RunSpeciesStage},
      {"cohesion", "Cohesion number and Γ at the simulation stiffness", &RunCohesionStage},
      {"gamma_per_coating", "Γ per coating level", &RunGammaPerCoatingStage},
      {"gamma_curve", "Γ(w) curve", &RunGammaCurveStage},
      {"dissimilar_pairs", "Dissimilar pairs", &RunDissimilarPairsStage},
      {"segregation", "Segregation of the calibrated set", &RunSegregationStage},
      {"fidelity_check", "Fidelity check", &RunFidelityCheckStage},
  };
  return stages;
}

nlohmann::json ValueJson(double mean, double sem, const std::string& note, bool synthetic) {
  return {{"mean", NumOrNull(mean)},
          {"sem", NumOrNull(sem)},
          {"note", note},
          {"synthetic", synthetic}};
}

}  // namespace demcal::workflow
