#pragma once
// What the rooms' registry entries (experiments/*/*_kind.cc) share: the registry's runner built
// from the room's typed runner, a section checker and a probe maker built from the room's section
// parser, scene builder and probe class.
#include <memory>
#include <ostream>
#include <string>

#include "experiments/experiment_registry.h"

namespace demcal::workflow {

// The registry's runner over a room's typed runner: the common fields (status, replicates_ok,
// Values()) copied out, the typed result kept as the detail.
template <class Result, Result (*Run)(const ExperimentFile&, const ExperimentContext&,
                                      std::ostream&)>
ExperimentResult RunTyped(const ExperimentFile& file, const ExperimentContext& context,
                          std::ostream& log) {
  Result typed = Run(file, context, log);
  ExperimentResult result;
  result.status = typed.status;
  result.experiment = file.experiment;
  result.replicates = context.replicates;
  result.replicates_ok = typed.replicates_ok;
  result.values = typed.Values();
  result.detail = std::move(typed);
  return result;
}

// Parse(section, source, model, &settings, &error) -> bool: the room's section reader.
template <class Settings, auto Parse>
bool CheckSection(const ExperimentFile& file, std::string* error) {
  Settings settings;
  return Parse(file.section, file.source, file.model, &settings, error);
}

// Parses the section into Settings against `model`, validates the scene `build` makes for the
// file's seed, and wraps the settings in the Probe.
template <class Probe, class Settings, class Parse, class Build>
std::unique_ptr<calibrate::ExperimentProbe> MakeProbe(const ExperimentFile& file,
                                                      const core::Scene& model, Parse parse,
                                                      Build build, std::string* error) {
  Settings settings;
  if (!parse(file.section, file.source, model, &settings, error)) return nullptr;
  std::string why;
  if (!build(model, settings, file.seed).IsValid(&why)) {
    *error = file.source + ": the " + file.experiment + " scene is invalid: " + why;
    return nullptr;
  }
  return std::make_unique<Probe>(std::move(settings));
}

}  // namespace demcal::workflow
