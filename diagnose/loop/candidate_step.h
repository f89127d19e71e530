#pragma once
// RunCandidateStep: one iteration of the loop (diagnosis.h steps 3-4) — the signatures of the
// candidates not yet added, their linearised refits, the simulated refits of the best ones and
// the ranking. Returns the step and, for the winner, the fit it leads to.
//
// Thread-safety: runs on the calling thread; the model parallelises.
#include <string>
#include <vector>

#include "diagnose/loop/base_fit.h"
#include "diagnose/loop/diagnosis.h"
#include "diagnose/loop/fit_state.h"

namespace demcal::diagnose {

struct StepOutcome {
  DiagnosisStep step;
  bool has_winner = false;
  FitState next;      // the winner's refitted fit (valid when has_winner)
  FitState tied_fit;  // the refitted fit of the entry tied with it (valid when ranking.tied >= 0)
  // The refit of the winner the control guard set aside (ranking.set_aside, not a control):
  // the loop takes it into the fit when it only re-values a modelled parameter.
  bool has_set_aside = false;
  FitState set_aside_fit;
  std::vector<PhaseTime> phases;
  // Per entry: its signature per unit of its parameter (raw units), secant-corrected by its
  // refits.
  std::vector<std::vector<double>> unit_signatures;
  // With bound parameters: the effects refitted with them held inside the range (RefitInside),
  // as entries, standardised residuals and unit signatures; not part of the ranking.
  std::vector<RankingEntry> inside_entries;
  std::vector<std::vector<double>> inside_residuals, inside_signatures;
};

// bounds: base parameters fitted onto a bound (base_fit.h); non-empty, the controls copying them
// are refitted by simulation too, and the best effects again with those parameters held inside
// (candidate_step.cc, ForceBoundControls and RefitInside).
StepOutcome RunCandidateStep(ForwardModel& model, const std::vector<Observation>& observations,
                             const std::vector<CandidateEffect>& candidates,
                             const std::vector<int>& remaining, const FitState& fit,
                             const DiagnoseOptions& options, const DiagnoseProgress& progress,
                             const std::vector<BaseBound>& bounds = {});

}  // namespace demcal::diagnose
