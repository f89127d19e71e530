// Scene JSON section: sinks (see scene_json.h and core/insertion/sink.h), where particles are removed and
// counted: {"name", "shape": "plane", "point_m", "normal"} (normal points where particles go
// out) or {"name", "shape": "box", "min_m", "max_m"}.
#include <cmath>

#include "files/scene_json_sections.h"
#include "core/insertion/sink.h"

namespace demcal::workflow::internal {

using nlohmann::json;

void ParseSinks(JsonFields& top, core::Scene* scene, JsonStatus* status) {
  const json* list = top.Array("sinks", kOptional);
  if (!list) return;
  for (size_t i = 0; i < list->size() && status->ok(); ++i) {
    const std::string path = IndexPath("sinks", i);
    std::string shape = "plane";
    {
      JsonFields probe((*list)[i], path, {"name", "shape", "point_m", "normal", "min_m", "max_m"},
                       status);
      probe.String("shape", &shape, kRequired, {"plane", "box"});
    }
    if (!status->ok()) return;
    core::SinkSpec sink;
    if (shape == "plane") {
      JsonFields f((*list)[i], path, {"name", "shape", "point_m", "normal"}, status);
      f.String("name", &sink.name, kRequired);
      f.Vector("point_m", &sink.point_m, kRequired);
      f.Vector("normal", &sink.normal, kRequired);
      const double length = core::Norm(sink.normal);
      if (f.ok() && !(length > 1e-12))
        f.Fail("normal", "must be a non-zero vector (pointing where particles go out)");
      if (f.ok()) sink.normal = sink.normal / length;
    } else {
      JsonFields f((*list)[i], path, {"name", "shape", "min_m", "max_m"}, status);
      f.String("name", &sink.name, kRequired);
      f.Vector("min_m", &sink.min_m, kRequired);
      f.Vector("max_m", &sink.max_m, kRequired);
      sink.shape = core::SinkSpec::Shape::kBox;
    }
    for (const core::SinkSpec& earlier : scene->sinks)
      if (status->ok() && earlier.name == sink.name)
        status->Fail("field '" + path + ".name' = '" + sink.name + "' is used by another sink");
    if (status->ok()) scene->sinks.push_back(sink);
  }
}

}  // namespace demcal::workflow::internal
