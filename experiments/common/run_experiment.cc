#include "experiments/common/run_experiment.h"

#include <filesystem>
#include <iostream>
#include <memory>

#include "outputs/exit_codes.h"
#include "experiments/common/experiment_file.h"
#include "experiments/experiment_registry.h"
#include "files/json_document.h"
#include "outputs/earlier_outputs.h"
#include "outputs/output_lock.h"

namespace demcal::workflow {

namespace {

// A refused input: the message on the log and, if --out already holds something, the earlier
// outputs moved to previous_run/ and the refusal in rejected.json, so the folder does not look
// like a finished run of this input (earlier_outputs.h). A new --out is not created for it.
int Reject(const ExperimentOptions& options, OutputLock* lock, const std::string& message,
           std::ostream& log, bool already_logged = false) {
  if (!already_logged) log << "error: " << message << "\n";
  std::error_code ec;
  if (!std::filesystem::is_directory(options.out_dir, ec)) return kExitInvalidInput;
  std::string error;
  if (!lock->held() && !LockOutputDirectory(options.out_dir, "demcal experiment " + options.kind,
                                            lock, &error)) {
    log << "error: " << error << "\n";
    return kExitInvalidInput;
  }
  std::vector<std::string> moved;
  if (!SetAsideEarlierOutputs(options.out_dir, {options.params_path}, &moved, &error))
    log << "error: " << error << "\n";
  nlohmann::ordered_json rejected;
  rejected["format"] = "demcal-rejected/1";
  rejected["command"] = "demcal experiment " + options.kind;
  rejected["input"] = options.params_path;
  rejected["termination"] = "invalid_input";
  rejected["message"] = message;
  rejected["earlier_outputs_moved_to"] =
      moved.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(kPreviousRunDir + std::string("/"));
  rejected["earlier_outputs_moved"] = moved;
  if (!WriteJsonFile(options.out_dir + "/rejected.json", rejected, &error))
    log << "error: " << error << "\n";
  return kExitInvalidInput;
}

}  // namespace

ExperimentContext ExperimentContextFor(const ExperimentFile& file, const std::string& out_dir,
                                       bool quick) {
  ExperimentContext context;
  context.out_dir = out_dir;
  context.replicates = file.replicates;
  context.fidelity = quick ? file.quick_fidelity : file.fidelity;
  return context;
}

ExperimentResult RunExperimentFile(const ExperimentFile& file, const ExperimentContext& context,
                                   std::ostream& log) {
  ExperimentResult refused;
  refused.experiment = file.experiment;
  refused.replicates = context.replicates;
  auto refuse = [&](ExperimentStatus status, const std::string& message) {
    log << "error: " << message << "\n";
    refused.status = status;
    refused.message = message;
    return refused;
  };
  const ExperimentKind* kind = FindExperimentKind(file.experiment);
  if (!kind)
    return refuse(ExperimentStatus::kInvalidInput,
                  "unknown experiment '" + file.experiment + "' (" +
                      JoinNames(ExperimentKindNames()) + ")");
  std::string error;
  if (!context.fidelity.IsValid(&error))
    return refuse(ExperimentStatus::kInvalidInput, file.source + ": " + error);
  // One process per output directory (this also creates it).
  OutputLock lock;
  if (!LockOutputDirectory(context.out_dir, "demcal experiment " + file.experiment, &lock,
                           &error))
    return refuse(ExperimentStatus::kOutputUnavailable, "--out: " + error);
  // A fresh run: a rejection note of an earlier attempt no longer applies.
  std::error_code ignored;
  std::filesystem::remove(std::filesystem::path(context.out_dir) / "rejected.json", ignored);
  ExperimentResult result = kind->run(file, context, log);
  // The runner refused its section (e.g. aor.angle) and said why on the log.
  if (result.status == ExperimentStatus::kInvalidInput)
    result.message = file.source + ": the '" + file.experiment +
                     "' section was refused (see the error printed before this file)";
  return result;
}

int RunExperiment(const ExperimentOptions& options, std::ostream& log) {
  OutputLock lock;
  const ExperimentKind* kind = FindExperimentKind(options.kind);
  if (!kind)
    return Reject(options, &lock,
                  "unknown experiment '" + options.kind + "' (" + JoinNames(ExperimentKindNames()) + ")",
                  log);
  ExperimentFile file;
  std::string error;
  if (!LoadExperimentFile(options.params_path, &file, &error))
    return Reject(options, &lock, error, log);
  if (file.experiment != options.kind) {
    const bool vowel = std::string("aeiou").find(file.experiment[0]) != std::string::npos;
    return Reject(options, &lock,
                  options.params_path + (vowel ? " is an '" : " is a '") + file.experiment +
                      "' experiment file, not '" + options.kind +
                      "'; run it with `demcal experiment " + file.experiment + "`",
                  log);
  }
  ExperimentContext context = ExperimentContextFor(file, options.out_dir, options.quick);
  if (options.replicates > 0) context.replicates = options.replicates;
  context.threads = options.threads;
  context.quiet = options.quiet;
  const ExperimentResult result = RunExperimentFile(file, context, log);
  // A refused file or section: the refusal is on the log; rejected.json records it.
  if (result.status == ExperimentStatus::kInvalidInput)
    return Reject(options, &lock, result.message, log, /*already_logged=*/true);
  return ExitCodeOf(result.status);
}

}  // namespace demcal::workflow
