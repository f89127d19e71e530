#include "core/wall_contacts.h"

#include <algorithm>
#include <numeric>

namespace demcal::core {
namespace {

// Whether a static wall can touch the sphere before the next rebuild (gap below the skin). For a
// mesh, `triangles` receives the near ones, within the skin plus the adhesive break gap.
bool WithinSkin(const Wall& wall, const Vec3& x, double radius, double skin_m,
                double adhesive_gap_m, std::vector<int32_t>& triangles) {
  if (const auto* plane = std::get_if<PlaneSurface>(&wall.shape))
    return Dot(x - plane->point_m, plane->normal) - radius <= skin_m;
  if (const auto* cylinder = std::get_if<CylinderSurface>(&wall.shape)) {
    double gap;
    if (CylinderSideDistance(*cylinder, wall.shell, x, gap)) return gap - radius <= skin_m;
    return ShellSide(wall, ClosestOnCylinder(*cylinder, x)).distance_m - radius <= skin_m;
  }
  if (const auto* cone = std::get_if<ConeFrustumSurface>(&wall.shape))
    return ShellSide(wall, ClosestOnConeFrustum(*cone, x)).distance_m - radius <= skin_m;
  const MeshRef& mesh = std::get<MeshRef>(wall.shape);
  mesh.mesh->NearTriangles(x - mesh.offset_m, radius + skin_m + adhesive_gap_m, triangles);
  return !triangles.empty();
}

}  // namespace

void WallContacts::SetVelocities(const std::vector<Wall>& walls, double time_s) {
  velocity_.resize(walls.size());
  for (size_t w = 0; w < walls.size(); ++w) velocity_[w] = walls[w].VelocityAt(time_s);
}

void WallContacts::Rebuild(const Particles& p, const std::vector<uint32_t>& order,
                           const std::vector<Wall>& walls, double skin_m, size_t first_fixed,
                           double adhesive_gap_m) {
  const size_t n = p.Size();
  const size_t moving = std::min(n, first_fixed);
  auto old_slot = [&](size_t s) { return order.empty() ? s : order[s]; };
  const size_t old_n = start_.size() - 1;  // particles appended since keep no history
  std::vector<uint32_t> start(n + 1, 0), index, mesh_slots, near_start{0};
  std::vector<int32_t> near;
  std::vector<ContactHistory> history;
  std::vector<uint8_t> active;
  std::vector<MeshHistory> mesh_history;
  std::vector<int32_t> triangles;
  for (size_t i = 0; i < n; ++i) {
    for (uint32_t w = 0; i < moving && w < walls.size(); ++w) {
      const Wall& wall = walls[w];
      if (wall.removed) continue;
      triangles.clear();  // a moving mesh keeps no near triangles (WithinSkin is not asked)
      if (!wall.Moves() &&
          !WithinSkin(wall, p.position_m[i], p.radius_m[i], skin_m, adhesive_gap_m, triangles))
        continue;
      const bool is_mesh = std::holds_alternative<MeshRef>(wall.shape);
      ContactHistory h;
      MeshHistory m;
      uint8_t on = 0;
      const size_t o = old_slot(i);
      if (o < old_n) {  // keep the history of a wall contact that persists
        for (uint32_t e = start_[o]; e < start_[o + 1]; ++e) {
          if (index_[e] != w) continue;
          on = active_[e];
          if (is_mesh) m = mesh_history_[mesh_slots_[e]];
          else h = history_[e];
        }
      }
      index.push_back(w);
      history.push_back(h);
      active.push_back(on);
      mesh_slots.push_back(is_mesh ? static_cast<uint32_t>(mesh_history.size()) : kNoMesh);
      if (is_mesh) {
        mesh_history.push_back(m);
        near.insert(near.end(), triangles.begin(), triangles.end());
        near_start.push_back(static_cast<uint32_t>(near.size()));
      }
    }
    start[i + 1] = static_cast<uint32_t>(index.size());
  }
  start_.swap(start);
  index_.swap(index);
  history_.swap(history);
  active_.swap(active);
  mesh_slots_.swap(mesh_slots);
  mesh_history_.swap(mesh_history);
  mesh_near_start_.swap(near_start);
  mesh_near_.swap(near);
  load_.resize(index_.size());
}

std::vector<WallLoad> WallContacts::Loads(const Particles& p,
                                          const std::vector<Wall>& walls) const {
  std::vector<WallLoad> loads(walls.size());
  for (size_t w = 0; w < walls.size(); ++w) loads[w].point_m = walls[w].load_point_m;
  const size_t n = std::min(p.Size(), start_.size() - 1);
  for (size_t i = 0; i < n; ++i) {
    for (uint32_t e = start_[i]; e < start_[i + 1]; ++e) {
      if (!active_[e]) continue;
      WallLoad& load = loads[index_[e]];
      load.force_N += load_[e].force_N;
      load.torque_N_m += Cross(p.position_m[i] - load.point_m, load_[e].force_N) +
                         load_[e].moment_N_m;
    }
  }
  return loads;
}

size_t WallContacts::ActiveContacts() const {
  return std::accumulate(active_.begin(), active_.end(), size_t{0});
}

}  // namespace demcal::core
