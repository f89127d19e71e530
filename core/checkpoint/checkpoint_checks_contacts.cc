// The restored-state checks of a checkpoint, part 2: the neighbour list, the layout of fixed
// spheres, pair contact histories and wall candidates with their histories. Rows, partners,
// and wall indices are all checked against the particle and wall counts, so the
// force loop never follows a damaged index (which would read or write out of bounds).
#include <cmath>
#include <string>

#include "core/simulation/simulation.h"

namespace demcal::core {
namespace {

bool Fail(const std::string& why, std::string* error) {
  *error = why;
  return false;
}

bool Finite(const ContactHistory& h) {
  return IsFinite(h.shear_m) && IsFinite(h.rolling_torque_N_m) && std::isfinite(h.jkr_sqrt_radius);
}

// Compressed rows over `rows` rows: starts at 0, never decreases, ends at `entries`.
bool ValidRows(const std::vector<uint32_t>& start, size_t rows, size_t entries) {
  if (start.size() != rows + 1 || start.front() != 0 || start.back() != entries) return false;
  for (size_t i = 0; i < rows; ++i)
    if (start[i] > start[i + 1]) return false;
  return true;
}

}  // namespace

bool NeighbourList::CheckRestored(size_t particles, double skin_m, std::string* error) const {
  const size_t pairs = partner_.size();
  if (!ValidRows(row_start_, particles, pairs))
    return Fail("neighbour list: rows do not match the " + std::to_string(particles) + " particles",
                error);
  if (first_fixed_ > particles)
    return Fail("neighbour list: first fixed slot " + std::to_string(first_fixed_) + " beyond " +
                    std::to_string(particles) + " particles",
                error);
  for (size_t i = 0; i < particles; ++i) {
    if (i >= first_fixed_ && row_start_[i] != row_start_[i + 1])
      return Fail("neighbour list: fixed slot " + std::to_string(i) + " has partners", error);
    for (uint32_t k = row_start_[i]; k < row_start_[i + 1]; ++k)
      if (partner_[k] <= i || partner_[k] >= particles || (k > row_start_[i] && partner_[k] <= partner_[k - 1]))
        return Fail("neighbour list: row " + std::to_string(i) + " lists partner " +
                        std::to_string(partner_[k]) + " (partners must be ascending, above " +
                        std::to_string(i) + " and below " + std::to_string(particles) + ")",
                    error);
  }
  if (reference_position_.size() != particles)
    return Fail("neighbour list: reference positions do not match the particles", error);
  for (const Vec3& x : reference_position_)
    if (!IsFinite(x)) return Fail("neighbour list: a non-finite reference position", error);
  if (half_skin2_ != 0.25 * skin_m * skin_m)
    return Fail("neighbour list: built for another skin than this scene's", error);
  return true;
}

bool WallContacts::CheckRestored(size_t particles, size_t first_fixed,
                                 const std::vector<Wall>& walls, std::string* error) const {
  const size_t entries = index_.size();
  if (!ValidRows(start_, particles, entries) || history_.size() != entries ||
      active_.size() != entries || mesh_slots_.size() != entries || load_.size() != entries)
    return Fail("wall contacts: candidate rows do not match the particles", error);
  if (!ValidRows(mesh_near_start_, mesh_history_.size(), mesh_near_.size()))
    return Fail("wall contacts: near-triangle rows do not match the mesh candidates", error);
  uint32_t meshes = 0;
  for (size_t i = 0; i < particles; ++i) {
    if (i >= first_fixed && start_[i] != start_[i + 1])
      return Fail("wall contacts: fixed slot " + std::to_string(i) + " has wall candidates", error);
    for (uint32_t e = start_[i]; e < start_[i + 1]; ++e) {
      const std::string at = "wall contacts: slot " + std::to_string(i) + ": ";
      if (index_[e] >= walls.size())
        return Fail(at + "wall index " + std::to_string(index_[e]) + " (the scene has " +
                        std::to_string(walls.size()) + " walls)",
                    error);
      const bool mesh = std::holds_alternative<MeshRef>(walls[index_[e]].shape);
      // Mesh candidates take the mesh histories in order (as Rebuild assigns them).
      if (mesh ? mesh_slots_[e] != meshes++ : (mesh_slots_[e] != kNoMesh || active_[e] > 1))
        return Fail(at + "mesh history slot or contact flag does not fit wall " +
                        std::to_string(index_[e]),
                    error);
      if (!Finite(history_[e]) || !IsFinite(load_[e].force_N) || !IsFinite(load_[e].moment_N_m))
        return Fail(at + "non-finite contact history or load", error);
      if (mesh && !NearTrianglesFit(mesh_slots_[e], walls[index_[e]]))
        return Fail(at + "near triangles outside mesh wall " + std::to_string(index_[e]) +
                        " (or not ascending)",
                    error);
    }
  }
  if (mesh_history_.size() != meshes)
    return Fail("wall contacts: mesh histories do not match the mesh candidates", error);
  for (const MeshHistory& m : mesh_history_) {
    if (m.count > kMaxMeshContacts)
      return Fail("wall contacts: a mesh history holds " + std::to_string(m.count) +
                      " contacts (at most " + std::to_string(kMaxMeshContacts) + ")",
                  error);
    for (uint32_t s = 0; s < m.count; ++s)
      if (!Finite(m.slot[s].history)) return Fail("wall contacts: non-finite mesh history", error);
  }
  for (size_t e = 0; e < entries; ++e)
    if (mesh_slots_[e] != kNoMesh) {
      const std::string why = MeshHistoryProblem(mesh_history_[mesh_slots_[e]], walls[index_[e]]);
      if (!why.empty())
        return Fail("wall contacts: mesh history " + std::to_string(mesh_slots_[e]) + " (wall " +
                        std::to_string(index_[e]) + "): " + why,
                    error);
    }
  return true;
}

std::string WallContacts::MeshHistoryProblem(const MeshHistory& m, const Wall& wall) {
  // Each contact of a mesh history is keyed by the mesh feature it touches (MeshContact::Key:
  // kind << 32 | index); SumMesh looks a contact up by its key, so a key held twice would give
  // two contacts one history, and a key naming no feature of this mesh a history never found.
  const TriangleMesh& mesh = *std::get<MeshRef>(wall.shape).mesh;
  for (uint32_t s = 0; s < m.count; ++s) {
    const uint64_t key = m.slot[s].key, kind = key >> 32, index = key & 0xffffffffu;
    auto is = [kind](MeshFeatureKind k) { return kind == static_cast<uint64_t>(k); };
    const uint64_t features = is(MeshFeatureKind::kFace)     ? mesh.NumPatches()
                              : is(MeshFeatureKind::kEdge)   ? mesh.NumEdges()
                              : is(MeshFeatureKind::kVertex) ? mesh.NumVertices()
                                                             : 0;
    if (index >= features)
      return "contact " + std::to_string(s) + " has the key " + std::to_string(key) +
             ", which names no face, edge or vertex of the mesh";
    for (uint32_t t = 0; t < s; ++t)
      if (m.slot[t].key == key)
        return "contacts " + std::to_string(t) + " and " + std::to_string(s) +
               " share the key " + std::to_string(key) + " (one mesh feature, two histories)";
  }
  return "";
}

bool WallContacts::NearTrianglesFit(uint32_t slot, const Wall& wall) const {
  if (slot + 1 >= mesh_near_start_.size()) return false;
  const auto& mesh = std::get<MeshRef>(wall.shape).mesh;
  if (!mesh) return false;
  const int64_t triangles = static_cast<int64_t>(mesh->NumTriangles());
  int64_t previous = -1;
  for (uint32_t k = mesh_near_start_[slot]; k < mesh_near_start_[slot + 1]; ++k) {
    if (mesh_near_[k] <= previous || mesh_near_[k] >= triangles) return false;
    previous = mesh_near_[k];
  }
  return true;
}

bool ContactForces::CheckRestored(const NeighbourList& list, size_t particles,
                                  const std::vector<Wall>& walls, std::string* error) const {
  const size_t pairs = list.PairCount();
  if (pair_history_.size() != pairs || pair_active_.size() != pairs)
    return Fail("contact histories: " + std::to_string(pair_history_.size()) + " for " +
                    std::to_string(pairs) + " listed pairs",
                error);
  for (size_t k = 0; k < pairs; ++k)
    if (pair_active_[k] > 1 || !Finite(pair_history_[k]))
      return Fail("contact histories: entry " + std::to_string(k) +
                      " has a non-finite history or an invalid contact flag",
                  error);
  return walls_.CheckRestored(particles, list.FirstFixed(), walls, error);
}

bool Simulation::CheckRestoredState(std::string* error) const {
  const Particles& p = system_.spheres;
  if (!CheckRestoredProgress(error) || !CheckRestoredBodies(error) ||
      !CheckRestoredPhysics(error) || !list_.CheckRestored(p.Size(), list_settings_.skin_m, error))
    return false;
  // Fixed spheres after the moving ones (the integration and sweep stop at FirstFixed()).
  for (size_t i = 0; i < p.Size(); ++i)
    if (i >= list_.FirstFixed() ? !p.IsFixed(i) : (options_.exclude_fixed_pairs && p.IsFixed(i)))
      return Fail("particles: slot " + std::to_string(i) +
                      (p.IsFixed(i) ? " is fixed among the moving ones" : " moves among the fixed ones"),
                  error);
  // After every step no moving particle is more than half the skin from its reference.
  if (list_.NeedsRebuild(p.position_m))
    return Fail("neighbour list: a particle is more than half the skin from where the list was "
                "built (positions edited?)",
                error);
  return forces_.CheckRestored(list_, p.Size(), walls_, error);
}

}  // namespace demcal::core
