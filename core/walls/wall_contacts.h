#pragma once
// WallContacts: the particle–wall part of ContactForces. Per particle it keeps a list of
// candidate walls (compressed rows, rebuilt with the neighbour list) and, per candidate, the
// contact history: one ContactHistory for a plane, cylinder or cone (one contact point), and a
// small fixed array of {feature key, history} for a mesh, where a sphere may touch several faces,
// edges and vertices at once (each its own contact, keyed by MeshContact::Key()). A static mesh
// candidate also keeps the triangles near the particle (TriangleMesh::NearTriangles within
// radius + skin + the adhesive break gap at the rebuild): the particle moves less than a skin
// before the next rebuild (neighbour_list_update.cc), so no other triangle can touch it, and the
// force pass tests those few instead of every triangle in the mesh grid's cells (on a silo
// bottom of long fan triangles that was more than half the force pass). It also keeps what each
// candidate exerted on its wall in the last step, for WallLoads().
//
// Hot loop: Sum() is a header template inlined per particle into the force sweep; it branches
// on the shape kind (no virtual call), inlines the plane/cylinder/cone contact and allocates
// nothing (the mesh query reuses a scratch vector owned by the calling chunk).
//
// Determinism: each particle's wall contacts are summed in candidate order, and Loads() sums
// the stored per-candidate loads in particle order, so both are independent of the thread count.
// Thread-safety: Sum() for distinct particles may run concurrently; Rebuild() uses TBB
// internally; call everything else from one thread.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/contact/clump_levers.h"
#include "core/contact/contact_state.h"
#include "core/math/heap_bytes.h"
#include "core/materials/interaction_table.h"
#include "core/bodies/particles.h"
#include "core/walls/triangle_mesh.h"
#include "core/walls/walls.h"

namespace demcal::core {

class WallContacts {
 public:
  // Mesh features one candidate remembers. More simultaneous contacts with one mesh still get
  // their force, but without tangential/rolling history (none was seen in practice: a sphere in
  // a concave corner of a box touches three).
  static constexpr int kMaxMeshContacts = 6;

  // Per-step wall velocities (index = wall); call before Sum() in every force pass.
  void SetVelocities(const std::vector<Wall>& walls, double time_s);

  // The clumps' centres of mass, for the rolling levers of their members (clump_levers.h).
  void SetBodyCentres(BodyCentres centre_m) { body_centre_m_ = centre_m; }

  // Adds to fi, ti the wall forces and torques on particle i.
  template <class Model>
  void Sum(const Particles& p, uint32_t i, const std::vector<Wall>& walls,
           const InteractionTable& table, const Model& model, double dt,
           std::vector<MeshContact>& scratch, Vec3& fi, Vec3& ti);

  // Lists per particle the walls within its radius + skin (moving walls always), keeping the
  // histories of candidates that persist. `order[new_slot] = old_slot` (identity if empty).
  // `previous_reference` / `reference`: the neighbour list's reference positions before and after
  // this rebuild (NeighbourList::ReferencePositions). A particle whose reference did not move was
  // not re-searched, and its row (listed where it then was: at that reference) is kept as it is,
  // so the cost follows what moved; the particle stays within skin/2 of its reference until the
  // next rebuild, well inside the skin the row was listed with.
  // Slots from `first_fixed` on (fixed spheres) get no candidates: they are not swept.
  // adhesive_gap_m: how far beyond touching an adhesive contact lasts (mesh near triangles).
  void Rebuild(const Particles& p, const std::vector<Vec3>& previous_reference,
               const std::vector<Vec3>& reference, const std::vector<uint32_t>& order,
               const std::vector<Wall>& walls, double skin_m, size_t first_fixed = SIZE_MAX,
               double adhesive_gap_m = 0);

  // Force and torque on each wall in the last force pass (about each wall's load point).
  std::vector<WallLoad> Loads(const Particles& p, const std::vector<Wall>& walls) const;
  // Particle–wall contacts with positive overlap (or held by adhesion) in the last pass.
  size_t ActiveContacts() const;
  // Candidate rows (per particle: a few walls each) and the per-wall arrays.
  HeapBytes Heap() const {
    size_t blocks = VectorBytes(blocks_);
    for (const Block& b : blocks_) blocks += RowsBytes(b.rows) + VectorBytes(b.triangles);
    return {VectorBytes(start_, index_, history_, active_, mesh_slots_, mesh_history_,
                        mesh_near_start_, mesh_near_, load_) + blocks,
            0, VectorBytes(velocity_)};
  }

  template <class A>
  void Serialize(A& a) {
    a.Vector(start_), a.Vector(index_), a.Vector(history_), a.Vector(active_);
    a.Vector(mesh_slots_), a.Vector(mesh_history_), a.Vector(load_);
    a.Vector(mesh_near_start_), a.Vector(mesh_near_);
  }

  // After a checkpoint load: rows, wall indices and histories fit the particles and walls.
  bool CheckRestored(size_t particles, size_t first_fixed, const std::vector<Wall>& walls,
                     std::string* error) const;

 private:
  struct MeshSlot {
    uint64_t key = 0;
    ContactHistory history{};
  };
  struct MeshHistory {
    std::array<MeshSlot, kMaxMeshContacts> slot{};
    uint32_t count = 0;
    // What would be padding, named and zeroed: checkpoints store this struct's bytes raw, and
    // indeterminate padding would make two checkpoints of one state differ byte for byte.
    uint32_t padding = 0;
  };
  // What candidate e exerted on its wall: the force, and the moment about the particle centre.
  struct Load {
    Vec3 force_N;
    Vec3 moment_N_m;
  };
  static constexpr uint32_t kNoMesh = ~uint32_t{0};
  // Mesh candidate `slot`'s near triangles exist in `wall`'s mesh, ascending (CheckRestored).
  bool NearTrianglesFit(uint32_t slot, const Wall& wall) const;
  // "" if mesh history `m` of a candidate of mesh wall `wall` keys each contact by a distinct
  // feature of the mesh; else the problem (CheckRestored).
  static std::string MeshHistoryProblem(const MeshHistory& m, const Wall& wall);

  template <class Model>
  void SumOne(const Particles& p, uint32_t i, uint32_t e, const Vec3& wall_velocity,
              const Vec3& normal, double overlap, const ResolvedPair& pair, const Model& model,
              double dt, Vec3& fi, Vec3& ti);
  // `moving`: the mesh moves, so its contacts come from its grid, not the near triangles.
  template <class Model>
  void SumMesh(const Particles& p, uint32_t i, uint32_t e, const MeshRef& mesh, bool moving,
               const Vec3& wall_velocity, const ResolvedPair& pair, const Model& model, double dt,
               std::vector<MeshContact>& scratch, Vec3& fi, Vec3& ti);

  // The candidate arrays below, for a block of particles as Rebuild lists them.
  struct Rows {
    std::vector<uint32_t> start, index, mesh_slots, near_start;
    std::vector<ContactHistory> history;
    std::vector<uint8_t> active;
    std::vector<MeshHistory> mesh_history;
    std::vector<int32_t> near;
    void Clear(size_t particles);
  };
  static constexpr size_t kNoOldSlot = SIZE_MAX;
  static size_t RowsBytes(const Rows& r) {
    return VectorBytes(r.start, r.index, r.mesh_slots, r.near_start, r.history, r.active,
                       r.mesh_history, r.near);
  }
  // Rebuild lists the rows of each block of kRebuildBlock particles into the block's own Rows,
  // blocks in parallel, reading the old arrays; then it joins the blocks into the arrays in
  // block order. A block's bounds do not depend on the thread count, so neither do the arrays:
  // they are the serial listing's. The blocks are kept as the next rebuild's destination (a
  // pour rebuilds every ~7–12 steps; no allocation each time). On a 200,000-sphere pour the
  // serial listing was 3 % of the one-thread time (perf, 2026-12-06): at 16 threads a cap of
  // 11× on the whole run by itself.
  static constexpr size_t kRebuildBlock = 2048;
  struct Block {
    Rows rows;
    std::vector<int32_t> triangles;  // ListRow's scratch: a mesh's near triangles
  };
  // Old row o copied to `to` as it is (walls removed since dropped).
  void KeepRow(size_t o, const std::vector<Wall>& walls, Rows& to) const;
  // Particle i's walls listed anew at its position; histories from old slot o (or kNoOldSlot).
  void ListRow(const Particles& p, size_t i, size_t o, const std::vector<Wall>& walls,
               double skin_m, double adhesive_gap_m, Block& to) const;
  // The first `blocks` blocks, in order, become the candidate arrays of n particles; they list
  // the first `moving`, the rows after are empty.
  void JoinBlocks(size_t blocks, size_t moving, size_t n);
  std::vector<Block> blocks_;

  // Candidates in compressed rows: particle i's are [start_[i], start_[i + 1]).
  std::vector<uint32_t> start_{0};
  std::vector<uint32_t> index_;          // wall index
  std::vector<ContactHistory> history_;  // plane, cylinder, cone candidates
  std::vector<uint8_t> active_;          // contacts active last pass (mesh: how many)
  std::vector<uint32_t> mesh_slots_;     // mesh candidates: index into mesh_history_
  std::vector<MeshHistory> mesh_history_;
  // Near triangles of mesh candidate s (index into mesh_history_): mesh_near_[mesh_near_start_[s]
  // .. mesh_near_start_[s + 1]), ascending; empty for a moving mesh.
  std::vector<uint32_t> mesh_near_start_{0};
  std::vector<int32_t> mesh_near_;
  std::vector<Load> load_;  // valid where active_
  std::vector<Vec3> velocity_;  // per wall, this pass
  BodyCentres body_centre_m_;   // the clumps' centres (SetBodyCentres)
};

// The geometry of a sphere–wall contact: the wall is infinitely heavy, has no radius and moves
// with wall_velocity; normal points from the wall to the sphere centre.
inline ContactGeometry WallGeometry(const Particles& p, size_t i, const Vec3& normal,
                                    const Vec3& wall_velocity, double overlap) {
  ContactGeometry g{};
  const double ri = p.radius_m[i];
  g.normal = normal;
  g.overlap_m = overlap;
  g.radius_i_m = ri;
  g.radius_j_m = 0;
  g.rolling_lever_i_m = ri;
  g.effective_radius_m = ri;
  g.mass_i_kg = g.effective_mass_kg = p.mass_kg[i];
  g.mass_j_kg = 0;
  g.omega_i = p.angular_velocity_rad_s[i];
  g.relative_velocity_m_s = p.velocity_m_s[i] - wall_velocity - Cross(ri * g.omega_i, normal);
  return g;
}

// A thin shell (Wall::shell) repels a sphere on either side: the distance becomes unsigned and
// the normal points to the side the centre is on.
inline WallProximity ShellSide(const Wall& wall, WallProximity near) {
  if (wall.shell && near.distance_m < 0) {
    near.distance_m = -near.distance_m;
    near.normal = -near.normal;
  }
  return near;
}

template <class Model>
DEMCAL_HOT_INLINE void WallContacts::SumOne(const Particles& p, uint32_t i, uint32_t e, const Vec3& wall_velocity,
                          const Vec3& normal, double overlap, const ResolvedPair& pair,
                          const Model& model, double dt, Vec3& fi, Vec3& ti) {
  if (!Model::InContact(overlap, active_[e], p.radius_m[i], pair)) {
    if (active_[e]) history_[e] = ContactHistory{}, active_[e] = 0;
    return;
  }
  ContactGeometry g = WallGeometry(p, i, normal, wall_velocity, overlap);
  if constexpr (Model::kReadsRollingLever)
    if (!body_centre_m_.empty()) SetClumpLevers(p, body_centre_m_, i, -1, g);
  const ContactResult r = model.Evaluate(g, pair, dt, history_[e]);
  active_[e] = 1;
  fi += r.force_i;
  ti += r.torque_i;
  // On the wall: −F at the sphere's contact point x_i − R n, plus the couple on the wall side.
  load_[e] = {-r.force_i, Cross(p.radius_m[i] * normal, r.force_i) + r.torque_j};
}

template <class Model>
void WallContacts::SumMesh(const Particles& p, uint32_t i, uint32_t e, const MeshRef& mesh,
                           bool moving, const Vec3& wall_velocity, const ResolvedPair& pair,
                           const Model& model, double dt, std::vector<MeshContact>& scratch,
                           Vec3& fi, Vec3& ti) {
  const double radius = p.radius_m[i];
  // An adhesive contact survives stretching up to the break gap: query that much further.
  const double reach = Model::Normal::BreakGap(radius, pair);
  const uint32_t slot = mesh_slots_[e];
  if (moving) {
    mesh.mesh->SphereContacts(p.position_m[i] - mesh.offset_m, radius + reach, scratch);
  } else {
    const std::span<const int32_t> near(mesh_near_.data() + mesh_near_start_[slot],
                                        mesh_near_start_[slot + 1] - mesh_near_start_[slot]);
    mesh.mesh->SphereContacts(p.position_m[i] - mesh.offset_m, radius + reach, near, scratch);
  }
  MeshHistory& old = mesh_history_[slot];
  MeshHistory now{};
  Load load{};
  uint32_t evaluated = 0;
  for (const MeshContact& c : scratch) {
    const uint64_t key = c.Key();
    const double overlap = c.overlap_m - reach;
    int found = -1;
    for (uint32_t s = 0; s < old.count; ++s)
      if (old.slot[s].key == key) found = static_cast<int>(s);
    if (!Model::InContact(overlap, found >= 0, radius, pair)) continue;
    ContactHistory h = found >= 0 ? old.slot[found].history : ContactHistory{};
    ContactGeometry g = WallGeometry(p, i, c.normal, wall_velocity, overlap);
    if constexpr (Model::kReadsRollingLever)
      if (!body_centre_m_.empty()) SetClumpLevers(p, body_centre_m_, i, -1, g);
    const ContactResult r = model.Evaluate(g, pair, dt, h);
    if (now.count < kMaxMeshContacts) now.slot[now.count++] = {key, h};
    ++evaluated;
    fi += r.force_i;
    ti += r.torque_i;
    load.force_N -= r.force_i;
    load.moment_N_m += Cross(radius * c.normal, r.force_i) + r.torque_j;
  }
  old = now;
  active_[e] = static_cast<uint8_t>(std::min<uint32_t>(evaluated, 255));
  load_[e] = load;
}

template <class Model>
DEMCAL_HOT_INLINE void WallContacts::Sum(const Particles& p, uint32_t i, const std::vector<Wall>& walls,
                       const InteractionTable& table, const Model& model, double dt,
                       std::vector<MeshContact>& scratch, Vec3& fi, Vec3& ti) {
  for (uint32_t e = start_[i]; e < start_[i + 1]; ++e) {
    const uint32_t w = index_[e];
    const Wall& wall = walls[w];
    const ResolvedPair& pair = table.Get(p.material[i], wall.material);
    if (const auto* plane = std::get_if<PlaneSurface>(&wall.shape)) {
      const double overlap = p.radius_m[i] - Dot(p.position_m[i] - plane->point_m, plane->normal);
      SumOne(p, i, e, velocity_[w], plane->normal, overlap, pair, model, dt, fi, ti);
    } else if (const auto* cylinder = std::get_if<CylinderSurface>(&wall.shape)) {
      double gap;
      if (!active_[e] && CylinderSideDistance(*cylinder, wall.shell, p.position_m[i], gap) &&
          !(p.radius_m[i] - gap > 0))
        continue;  // not touching: what SumOne would conclude, at a fraction of the cost
      const WallProximity near = ShellSide(wall, ClosestOnCylinder(*cylinder, p.position_m[i]));
      SumOne(p, i, e, velocity_[w], near.normal, p.radius_m[i] - near.distance_m, pair, model, dt,
             fi, ti);
    } else if (const auto* cone = std::get_if<ConeFrustumSurface>(&wall.shape)) {
      const WallProximity near = ShellSide(wall, ClosestOnConeFrustum(*cone, p.position_m[i]));
      SumOne(p, i, e, velocity_[w], near.normal, p.radius_m[i] - near.distance_m, pair, model, dt,
             fi, ti);
    } else {
      SumMesh(p, i, e, std::get<MeshRef>(wall.shape), wall.Moves(), velocity_[w], pair, model, dt,
              scratch, fi, ti);
    }
  }
}

}  // namespace demcal::core
