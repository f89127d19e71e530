#pragma once
// Internal to the scene JSON parser: one function per section of a "demcal-scene/1" document.
// Each reads its key from the top-level object `top` into `scene`, recording the first problem
// in `status` (see json_fields.h). Split by theme to keep files small:
//   scene_json_materials.cc  materials, species, interactions, contact_model
//   scene_json_bodies.cc     walls, particles, fills
//   scene_json_factories.cc  factories (and the insertion regions fills share)
//   scene_json_sinks.cc      sinks
#include <string>
#include <vector>

#include "files/json_fields.h"
#include "core/scene/scene.h"

namespace demcal::workflow::internal {

void ParseMaterials(JsonFields& top, core::Scene* scene, JsonStatus* status);
void ParseSpecies(JsonFields& top, core::Scene* scene, JsonStatus* status);
void ParseInteractions(JsonFields& top, core::Scene* scene, JsonStatus* status);
void ParseContactModel(JsonFields& top, core::Scene* scene, JsonStatus* status);
// Mesh wall files are resolved relative to `base_dir` (the scene file's directory).
void ParseWalls(JsonFields& top, const std::string& base_dir, core::Scene* scene,
                JsonStatus* status);
void ParseParticles(JsonFields& top, core::Scene* scene, JsonStatus* status);
void ParseFills(JsonFields& top, core::Scene* scene, JsonStatus* status);
void ParseFactories(JsonFields& top, core::Scene* scene, JsonStatus* status);
void ParseSinks(JsonFields& top, core::Scene* scene, JsonStatus* status);

// The required key "region" of `f`: {"shape": "box", "min_m", "max_m"} (shape may be omitted)
// or {"shape": "cylinder", "axis_point_m", "radius_m", "z_range_m"} (a vertical cylinder).
void ParseInsertionRegion(JsonFields& f, core::InsertionRegion* region, JsonStatus* status);

// The names of the scene's materials / species, in index order.
std::vector<std::string> MaterialNames(const core::Scene& scene);
std::vector<std::string> SpeciesNames(const core::Scene& scene);

// Resolves `value` (at JSON path `path`) as the name of one of `names` (what = "material",
// "species") and returns its index, or -1 after recording a type error or
// "names no <what> (defined: ...)".
int ResolveName(const nlohmann::json& value, const std::string& path, const std::string& what,
                const std::vector<std::string>& names, JsonStatus* status);

// Reads the required `key` of `fields` and resolves it with ResolveName.
int ReadNameReference(JsonFields& fields, const std::string& key, const std::string& what,
                      const std::vector<std::string>& names, JsonStatus* status);

}  // namespace demcal::workflow::internal
