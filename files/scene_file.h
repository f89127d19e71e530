#pragma once
// SceneFile: a parsed "demcal-scene/1" file — the core::Scene it describes plus the output
// settings of a run. The format is documented in docs/scene_format.md.
#include <string>
#include <vector>

#include "core/io/vtk_writer.h"
#include "core/scene/scene.h"

namespace demcal::workflow {

struct OutputSettings {
  double vtk_interval_s = 0;  // > 0: a snapshot every interval; 0: only the initial and final
  core::io::VtkOptions vtk;   // encoding of the snapshots (binary by default)
  // > 0: a row of mass_flow.csv every interval (outputs/mass_flow_log.h); 0: none.
  double mass_flow_interval_s = 0;
  // Counting planes of mass_flow.csv: the mass beyond each (where its normal points), no removal.
  std::vector<core::SinkSpec> mass_flow_planes;
};

struct SceneFile {
  std::string source;       // where it came from (file path), for messages and summaries
  std::string description;  // free text from the file, may be empty
  core::Scene scene;
  OutputSettings output;
};

inline constexpr const char* kSceneFormat = "demcal-scene/1";

}  // namespace demcal::workflow
