#pragma once
// Process exit codes of the demcal CLI (documented in docs/cli.md). Scripts and the calibration
// driver branch on them, so they are stable.
namespace demcal::workflow {

inline constexpr int kExitOk = 0;             // the command did what was asked
inline constexpr int kExitInternalError = 1;  // an unexpected error (a bug): please report it
inline constexpr int kExitInvalidInput = 2;   // bad command line or input file; nothing ran
inline constexpr int kExitRunFailed = 3;      // the simulation ended with a failure termination
inline constexpr int kExitOutputError = 4;    // an output file could not be written

}  // namespace demcal::workflow
