#include "diagnose/dem/shared_run_groups.h"

#include <cstdint>

#include "core/math/fnv1a.h"
#include "core/scene/scene_fingerprint.h"

namespace demcal::diagnose {
namespace {

// The digest of the scene group `g` runs at the unit point `unit`, with everything the run
// depends on beside the seed: the fingerprint's parts (with the resolved time step and skin)
// and the time settings the fingerprint leaves out (a restart may extend them, a run may not).
// 0 when the parameters do not apply (such a group is never merged).
uint64_t PreparedSceneDigest(const calibrate::RunGroup& g, const calibrate::ParameterSpace& space,
                             const std::vector<double>& unit) {
  core::Scene model = g.model;
  std::string why;
  if (!g.space.Apply(space.FromUnit(unit), g.condition, &model, &why)) return 0;
  if (g.prepare) g.prepare(&model);
  const double dt = core::TimeStep(model);
  core::Fnv1a64 h;
  for (const core::FingerprintPart& p :
       core::SceneFingerprint(model, dt, core::NeighbourSkin(model)))
    h.Text(p.name), h.Field(p.digest);
  h.Field(model.time.duration_s), h.Field(model.time.force_timestep),
      h.Field(model.max_wall_time_s);
  return h.digest() == 0 ? 1 : h.digest();
}

}  // namespace

MergedRunGroups MergeSharedRunGroups(const std::vector<calibrate::RunGroup>& groups,
                                     const std::vector<calibrate::TargetBinding>& bindings,
                                     const calibrate::ParameterSpace& space) {
  MergedRunGroups out;
  const size_t p = space.Size();
  const std::vector<std::vector<double>> points = {std::vector<double>(p, 0.3),
                                                   std::vector<double>(p, 0.7)};
  std::vector<std::vector<uint64_t>> digests;  // per kept group
  std::vector<int> kept_as(groups.size(), -1);
  for (size_t k = 0; k < groups.size(); ++k) {
    std::vector<uint64_t> d;
    for (const std::vector<double>& u : points)
      d.push_back(PreparedSceneDigest(groups[k], space, u));
    const bool mergeable = d[0] != 0 && d[1] != 0;
    for (size_t j = 0; mergeable && j < out.groups.size(); ++j)
      if (out.groups[j].probe == groups[k].probe && digests[j] == d) {
        kept_as[k] = static_cast<int>(j);
        ++out.merged;
        break;
      }
    if (kept_as[k] >= 0) continue;
    kept_as[k] = static_cast<int>(out.groups.size());
    out.groups.push_back(groups[k]);
    digests.push_back(mergeable ? d : std::vector<uint64_t>{0, 0});
  }
  for (const calibrate::TargetBinding& b : bindings)
    out.bindings.push_back(
        {b.group >= 0 && b.group < static_cast<int>(kept_as.size()) ? kept_as[b.group] : b.group,
         b.observable});
  return out;
}

std::vector<int> BindingSources(const std::vector<calibrate::TargetBinding>& bindings) {
  std::vector<int> source;
  for (size_t k = 0; k < bindings.size(); ++k) {
    size_t first = 0;
    while (bindings[first].group != bindings[k].group ||
           bindings[first].observable != bindings[k].observable)
      ++first;  // ends at k at the latest
    source.push_back(static_cast<int>(first));
  }
  return source;
}

}  // namespace demcal::diagnose
