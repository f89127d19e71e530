#include "core/walls/wall_contacts.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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

void WallContacts::Rebuild(const Particles& p, const std::vector<Vec3>& previous_reference,
                           const std::vector<Vec3>& reference, const std::vector<uint32_t>& order,
                           const std::vector<Wall>& walls, double skin_m, size_t first_fixed,
                           double adhesive_gap_m) {
  const size_t n = p.Size();
  const size_t moving = std::min(n, first_fixed);
  const size_t old_n = start_.size() - 1;  // particles appended since keep no history
  const double half_skin2 = 0.25 * skin_m * skin_m;
  const size_t blocks = (moving + kRebuildBlock - 1) / kRebuildBlock;
  if (blocks_.size() < blocks) blocks_.resize(blocks);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, blocks), [&](const auto& range) {
    for (size_t b = range.begin(); b != range.end(); ++b) {
      Block& block = blocks_[b];
      const size_t first = b * kRebuildBlock, last = std::min(moving, first + kRebuildBlock);
      block.rows.Clear(last - first);
      for (size_t i = first; i < last; ++i) {
        const size_t o = order.empty() ? i : order[i];
        const bool known = o < old_n;
        // A particle whose neighbour-list reference stayed put was not re-searched: its row was
        // listed at that reference and still holds (the plain displacement test catches a
        // periodic wrap, which the list's minimum-image test does not see).
        if (known && o < previous_reference.size() && i < reference.size() &&
            previous_reference[o] == reference[i] &&
            Norm2(p.position_m[i] - reference[i]) <= half_skin2)
          KeepRow(o, walls, block.rows);
        else
          ListRow(p, i, known ? o : kNoOldSlot, walls, skin_m, adhesive_gap_m, block);
        block.rows.start[i - first + 1] = static_cast<uint32_t>(block.rows.index.size());
      }
    }
  });
  JoinBlocks(blocks, moving, n);
  load_.resize(index_.size());
}

void WallContacts::JoinBlocks(size_t blocks, size_t moving, size_t n) {
  // Where each block's candidates, mesh candidates and near triangles start in the arrays.
  std::vector<size_t> entry(blocks + 1, 0), mesh(blocks + 1, 0), near(blocks + 1, 0);
  for (size_t b = 0; b < blocks; ++b) {
    const Rows& r = blocks_[b].rows;
    entry[b + 1] = entry[b] + r.index.size();
    mesh[b + 1] = mesh[b] + r.mesh_history.size();
    near[b + 1] = near[b] + r.near.size();
  }
  start_.resize(n + 1);
  start_[0] = 0;
  index_.resize(entry[blocks]), history_.resize(entry[blocks]), active_.resize(entry[blocks]);
  mesh_slots_.resize(entry[blocks]);
  mesh_history_.resize(mesh[blocks]);
  mesh_near_start_.resize(mesh[blocks] + 1);
  mesh_near_start_[0] = 0;
  mesh_near_.resize(near[blocks]);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, blocks), [&](const auto& range) {
    for (size_t b = range.begin(); b != range.end(); ++b) {
      const Rows& r = blocks_[b].rows;
      const size_t first = b * kRebuildBlock, e0 = entry[b];
      for (size_t k = 1; k < r.start.size(); ++k)
        start_[first + k] = static_cast<uint32_t>(e0 + r.start[k]);
      std::copy(r.index.begin(), r.index.end(), index_.begin() + e0);
      std::copy(r.history.begin(), r.history.end(), history_.begin() + e0);
      std::copy(r.active.begin(), r.active.end(), active_.begin() + e0);
      for (size_t k = 0; k < r.mesh_slots.size(); ++k)
        mesh_slots_[e0 + k] = r.mesh_slots[k] == kNoMesh
                                  ? kNoMesh
                                  : static_cast<uint32_t>(mesh[b] + r.mesh_slots[k]);
      std::copy(r.mesh_history.begin(), r.mesh_history.end(), mesh_history_.begin() + mesh[b]);
      for (size_t k = 1; k < r.near_start.size(); ++k)
        mesh_near_start_[mesh[b] + k] = static_cast<uint32_t>(near[b] + r.near_start[k]);
      std::copy(r.near.begin(), r.near.end(), mesh_near_.begin() + near[b]);
    }
  });
  std::fill(start_.begin() + moving + 1, start_.end(), static_cast<uint32_t>(entry[blocks]));
}

void WallContacts::Rows::Clear(size_t particles) {
  start.assign(particles + 1, 0);
  index.clear(), history.clear(), active.clear(), mesh_slots.clear(), mesh_history.clear();
  near_start.assign(1, 0);
  near.clear();
}

void WallContacts::KeepRow(size_t o, const std::vector<Wall>& walls, Rows& to) const {
  for (uint32_t e = start_[o]; e < start_[o + 1]; ++e) {
    const uint32_t w = index_[e];
    if (walls[w].removed) continue;
    to.index.push_back(w);
    to.history.push_back(history_[e]);
    to.active.push_back(active_[e]);
    if (mesh_slots_[e] == kNoMesh) {
      to.mesh_slots.push_back(kNoMesh);
      continue;
    }
    const uint32_t slot = mesh_slots_[e];
    to.mesh_slots.push_back(static_cast<uint32_t>(to.mesh_history.size()));
    to.mesh_history.push_back(mesh_history_[slot]);
    to.near.insert(to.near.end(), mesh_near_.begin() + mesh_near_start_[slot],
                   mesh_near_.begin() + mesh_near_start_[slot + 1]);
    to.near_start.push_back(static_cast<uint32_t>(to.near.size()));
  }
}

void WallContacts::ListRow(const Particles& p, size_t i, size_t o, const std::vector<Wall>& walls,
                           double skin_m, double adhesive_gap_m, Block& block) const {
  Rows& to = block.rows;
  std::vector<int32_t>& triangles = block.triangles;
  for (uint32_t w = 0; w < walls.size(); ++w) {
    const Wall& wall = walls[w];
    if (wall.removed) continue;
    triangles.clear();  // a moving mesh keeps no near triangles (WithinSkin is not asked)
    if (!wall.Moves() &&
        !WithinSkin(wall, p.position_m[i], p.radius_m[i], skin_m, adhesive_gap_m, triangles))
      continue;
    const bool is_mesh = std::holds_alternative<MeshRef>(wall.shape);
    ContactHistory h{};
    MeshHistory m{};
    uint8_t on = 0;
    if (o != kNoOldSlot) {  // keep the history of a wall contact that persists
      for (uint32_t e = start_[o]; e < start_[o + 1]; ++e) {
        if (index_[e] != w) continue;
        on = active_[e];
        if (is_mesh) m = mesh_history_[mesh_slots_[e]];
        else h = history_[e];
      }
    }
    to.index.push_back(w);
    to.history.push_back(h);
    to.active.push_back(on);
    to.mesh_slots.push_back(is_mesh ? static_cast<uint32_t>(to.mesh_history.size()) : kNoMesh);
    if (is_mesh) {
      to.mesh_history.push_back(m);
      to.near.insert(to.near.end(), triangles.begin(), triangles.end());
      to.near_start.push_back(static_cast<uint32_t>(to.near.size()));
    }
  }
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
