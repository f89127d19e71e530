// CalibrationSummary's reports (text for a terminal or a log).
#include <cmath>
#include <sstream>

#include "calibrate/calibration.h"

namespace demcal::calibrate {

std::string CalibrationSummary::BriefReport(const ParameterSpace& space) const {
  std::ostringstream out;
  out.precision(4);
  out << "calibration: " << TerminationName(termination) << " (" << message << "), " << candidates.size()
      << " candidates in " << batches << " batches, " << replicates_run << " replicate runs (+"
      << replicates_reused << " from the journal)\n";
  if (local_crossing.fitted)
    out << "local crossing: " << space.parameters[0].name << " = " << local_crossing_value
        << " +- " << local_crossing_sigma << ", " << local_crossing.message << "\n";
  if (best < 0) return out.str();
  out << "best: " << space.Describe(candidates[best].parameters) << "\n";
  for (const TargetResidual& t : residuals)
    out << "target " << t.name << ": " << t.observable << " = " << t.simulated << " +- " << t.sem
        << " (measured " << t.measured << " +- " << t.uncertainty << "), residual " << t.residual
        << (t.within_noise ? " (within noise)" : "") << "\n";
  for (const ParameterEstimate& e : estimates) {
    out << "parameter " << e.name << " = " << e.value << " +- ";
    if (std::isfinite(e.sigma))
      out << e.sigma;
    else
      out << "inf";
    out << (e.identifiable ? "" : " (not identifiable)") << "\n";
  }
  if (estimates.size() > 1 && correlation.rows() == static_cast<Eigen::Index>(estimates.size())) {
    out << "correlation:";
    for (Eigen::Index a = 0; a < correlation.rows(); ++a)
      for (Eigen::Index b = a + 1; b < correlation.cols(); ++b) {
        out << " " << estimates[a].name << "~" << estimates[b].name << " ";
        if (std::isfinite(correlation(a, b)))
          out << correlation(a, b);
        else
          out << "undefined";
      }
    out << "\n";
  }
  out << "uncertainty: " << covariance_note << "\n" << identifiability.summary;
  return out.str();
}

}  // namespace demcal::calibrate
