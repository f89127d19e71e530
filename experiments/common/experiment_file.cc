#include "experiments/common/experiment_file.h"

#include "experiments/experiment_registry.h"
#include "files/json_document.h"
#include "files/scene_json_sections.h"
#include "objectives/common/input_limits.h"

namespace demcal::workflow {

namespace limits = objectives::limits;

namespace {

using nlohmann::json;

void ParseOutput(JsonFields& top, OutputSettings* output, JsonStatus* status) {
  const json* section = top.Object("output", kOptional);
  if (!section) return;
  JsonFields f(*section, "output", {"vtk_interval_s"}, status);
  f.Number("vtk_interval_s", &output->vtk_interval_s, kOptional, Range::LeftOpen(0, 1e6, "s"));
}

}  // namespace

void ParseFidelity(const json& value, const std::string& path, objectives::Fidelity* fidelity,
                   JsonStatus* status) {
  JsonFields f(value, path, {"name", "size_scale", "stiffness_scale", "rayleigh_fraction"},
               status);
  f.String("name", &fidelity->name, kOptional);
  f.Number("size_scale", &fidelity->size_scale, kOptional, Range::Of(limits::kSizeScale));
  f.Number("stiffness_scale", &fidelity->stiffness_scale, kOptional,
           Range::Of(limits::kStiffnessScale));
  f.Number("rayleigh_fraction", &fidelity->rayleigh_fraction, kOptional,
           Range::Of(limits::kRayleighFraction));
}

bool ParseExperimentJson(const json& document, const std::string& source, ExperimentFile* out,
                         std::string* error) {
  JsonStatus status;
  ExperimentFile file;
  file.source = source;
  std::vector<std::string> keys = {"format",        "experiment", "description", "seed",
                                   "replicates",    "materials",  "species",     "interactions",
                                   "contact_model", "fidelity",   "quick_fidelity", "output"};
  for (const std::string& e : ExperimentKindNames()) keys.push_back(e);
  JsonFields top(document, "", keys, &status);
  std::string format;
  top.String("format", &format, kRequired);
  if (status.ok() && format != kExperimentFormat)
    top.Fail("format", "= '" + format + "' is not supported; this demcal reads '" +
                           std::string(kExperimentFormat) + "'");
  top.String("experiment", &file.experiment, kRequired,
             ExperimentKindNames());
  top.String("description", &file.description, kOptional);
  top.Unsigned("seed", &file.seed, kOptional);
  int64_t replicates = file.replicates;
  top.Integer("replicates", &replicates, kOptional, Range::Of(limits::kReplicates));
  file.replicates = static_cast<int>(replicates);
  internal::ParseMaterials(top, &file.model, &status);
  internal::ParseSpecies(top, &file.model, &status);
  internal::ParseInteractions(top, &file.model, &status);
  internal::ParseContactModel(top, &file.model, &status);
  if (const json* f = top.Object("fidelity", kOptional)) ParseFidelity(*f, "fidelity", &file.fidelity, &status);
  if (const json* f = top.Object("quick_fidelity", kOptional))
    ParseFidelity(*f, "quick_fidelity", &file.quick_fidelity, &status);
  if (status.ok() && !file.experiment.empty()) {
    if (const json* section = top.Object(file.experiment, kRequired)) file.section = *section;
  }
  ParseOutput(top, &file.output, &status);
  file.document = document;
  if (!status.ok()) {
    if (error) *error = source + ": " + status.message();
    return false;
  }
  *out = std::move(file);
  return true;
}

bool LoadExperimentFile(const std::string& path, ExperimentFile* out, std::string* error) {
  json document;
  return ReadJsonFile(path, "experiment file", &document, error) &&
         ParseExperimentJson(document, path, out, error);
}

}  // namespace demcal::workflow
