#pragma once
// The pictures of a diagnosis (SVG, objectives/report/svg_plot.h):
//   gap.svg         standardised residual per observation (numbered as in residuals.csv),
//                   before and after, with the ±1 band and the Bonferroni outlier lines
//   signatures.svg  per candidate of the first step: the simulated change of each observation
//                   at the probe value, in units of the observation's sigma
//   ranking.svg     ΔBIC per candidate of the first step (simulated refits as filled dots)
#include <string>

#include "diagnose/report/diagnosis_outputs.h"
#include "objectives/report/svg_plot.h"

namespace demcal::diagnose {

objectives::SvgPlot GapPlot(const Diagnosis& d);
objectives::SvgPlot SignaturePlot(const DiagnosisRunInfo& info, const Diagnosis& d);
objectives::SvgPlot RankingPlot(const Diagnosis& d);

}  // namespace demcal::diagnose
