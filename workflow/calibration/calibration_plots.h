#pragma once
// The pictures a calibration leaves for a person to look at (SVG, objectives/report/svg_plot.h):
//   targets.svg          per target: measured ± uncertainty and simulated ± sem at the best
//                        candidate, as standardised residuals (0 = the measurement)
//   convergence.svg      cost (Σ standardised residual²) of every candidate in the order asked,
//                        and the best so far
//   profile_<name>.svg   cost of every candidate against each parameter (the objective profile:
//                        a flat bottom is a parameter the targets do not fix)
//   parameter_plane.svg  two or more parameters: the candidates on the plane of the first two,
//                        coloured by cost quartile (a valley shows as a band of low cost)
//   calibration.svg      one parameter and one target: the observable against the parameter
//                        with the measured band
#include <string>

#include "calibrate/calibration.h"
#include "workflow/calibration/study_file.h"

namespace demcal::workflow {

bool WriteCalibrationPlots(const std::string& dir, const StudyFile& study,
                           const calibrate::CalibrationSummary& summary, std::string* error);

}  // namespace demcal::workflow
