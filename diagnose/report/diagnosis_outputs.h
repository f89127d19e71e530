#pragma once
// The files `demcal diagnose` writes into DIR (docs/diagnose.md lists every one), each
// atomically (objectives/report/text_file.h):
//   diagnosis.json        "demcal-diagnosis/1": verdict, gap before/after, candidates with
//                         parameters, ΔBIC, likelihood-ratio p, signature match, χ²/dof after,
//                         residual tables, trends, observables that carried the decision,
//                         simulations and time per phase, provenance
//   residuals.csv         per observation: measured, u, simulated and standardised residual
//                         before and after
//   ranking.csv           per loop step and candidate: refit values and evidence
//   signatures.csv        per loop step, candidate and observation: the simulated change at the
//                         probe value
//   diagnosed_params.json "demcal-params/1": the base parameters and the named effects with
//                         their refitted values (the augmented calibrated model)
//   gap.svg, signatures.svg, ranking.svg (diagnosis_plots.h)
//   report.html           all of it as one self-contained page (diagnosis_html.h)
//
//   if (!WriteDiagnosisOutputs(dir, info, diagnosis, &error)) ...
#include <string>
#include <vector>

#include "diagnose/effects/effect.h"
#include "diagnose/loop/diagnosis.h"

namespace demcal::diagnose {

struct DiagnosisRunInfo {
  std::string study;  // path as given
  std::string description;
  bool synthetic =
      false;  // some measurement row was made by a model (synthetic, simulated:<engine>)
  std::vector<std::string> data_provenance;  // the distinct provenances of the rows, in order
  std::string fidelity;                      // name of the fidelity the runs used
  uint64_t seed = 0;
  int replicates = 0;
  DiagnoseOptions options;
  EffectContext context;
  std::vector<CandidateEffect> candidates;
  std::vector<std::string> base_names;  // study parameters
  std::vector<double> base_before_si, base_after_si;
  std::vector<double> bound_effect_base_si;  // the base at the bound judgement's effect refit
  std::string journal_error;
};

bool WriteDiagnosisOutputs(const std::string& dir, const DiagnosisRunInfo& info, const Diagnosis& d,
                           std::string* error);

}  // namespace demcal::diagnose
