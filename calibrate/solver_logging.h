#pragma once
// Ceres reports through glog. Uninitialised, glog prefixes its first message with "Logging
// before InitGoogleLogging() is written to STDERR" and would, once initialised with defaults,
// write log files into /tmp. InitSolverLogging sets it up once per process: messages on stderr
// only, warnings and worse, nothing below fatal when the command runs with --quiet.
//
//   calibrate::InitSolverLogging(argv[0], quiet);
namespace demcal::calibrate {

void InitSolverLogging(const char* program, bool quiet);

}  // namespace demcal::calibrate
