#include "calibrate/solver_logging.h"

#include <glog/logging.h>

namespace demcal::calibrate {

void InitSolverLogging(const char* program, bool quiet) {
  FLAGS_logtostderr = true;
  FLAGS_minloglevel = quiet ? google::GLOG_FATAL : google::GLOG_WARNING;
  if (!google::IsGoogleLoggingInitialized()) google::InitGoogleLogging(program);
}

}  // namespace demcal::calibrate
