#pragma once
// ContactForces: evaluates every particle–particle and particle–wall contact and accumulates
// force and torque per particle, keeping the per-contact histories (tangential spring, rolling
// spring) across steps and across neighbour-list rebuilds. Wall contacts of every shape (plane,
// cylinder, cone, mesh) and the loads on the walls are kept by WallContacts.
//
// Determinism: particles are split into contiguous chunks (SweepChunks); each pair is evaluated
// once, and every particle's force is summed in the order of a serial sweep (see SumChunk), so
// floating-point results do not depend on the number of threads. A serial run pays no extra
// cost: it is the plain Newton's-third-law sweep over the half list.
//
// Fixed spheres (slots from NeighbourList::FirstFixed() on) are not swept: their force, torque
// and wall contacts are not computed, and a moving–fixed pair adds to the moving sphere only.
#include <algorithm>
#include <string>
#include <vector>

#include "core/contact/clump_levers.h"
#include "core/contact/contact_state.h"
#include "core/contact/normal_model.h"
#include "core/contact/rolling_model.h"
#include "core/materials/interaction_table.h"
#include "core/neighbours/neighbour_list.h"
#include "core/bodies/particles.h"
#include "core/neighbours/sweep_balance.h"
#include "core/neighbours/sweep_chunks.h"
#include "core/walls/wall_contacts.h"
#include "core/walls/walls.h"

namespace demcal::core {

class ContactForces {
 public:
  // Sets all forces and torques of `p` (gravity included), with the normal law `normal`
  // (MakeNormalModel) and the rolling model `rolling`: the loop is instantiated per pair of them.
  // `walls` are placed where they are at time_s (the time of the positions in `p`), which also
  // selects their velocities.
  void Compute(Particles& p, const NeighbourList& list, const std::vector<Wall>& walls,
               double time_s, const InteractionTable& table, const NormalModel& normal,
               const RollingModel& rolling, const Vec3& gravity, double dt);

  // Called after every neighbour-list rebuild: carries pair histories over to the new list and
  // lists, per moving particle, the walls within its radius + skin (moving walls always), keeping
  // their histories. `order[new_slot] = old_slot` describes a particle permutation applied together
  // with the rebuild (identity if empty). adhesive_gap_m: the largest break gap of the scene's
  // normal law (an adhesive contact reaches that far beyond touching; WallContacts::Rebuild).
  void Rebuild(const Particles& p, const NeighbourList& old_list, const NeighbourList& new_list,
               const std::vector<uint32_t>& order, const std::vector<Wall>& walls,
               double skin_m, double adhesive_gap_m = 0);

  // Hertz elastic energy stored in the overlapping particle pairs, (8/15) E* sqrt(R*) δ^{5/2}
  // summed (J): the energy initial overlaps will release, for the blow-up check's budget.
  double PairElasticEnergy(const Particles& p, const NeighbourList& list,
                           const InteractionTable& table) const;

  // The clumps' centres of mass (Clumps::position_m), for the rolling levers of their members
  // (core/contact/clump_levers.h); set before each Compute, empty for a scene without clumps.
  void SetBodyCentres(BodyCentres centre_m) {
    body_centre_m_ = centre_m;
    walls_.SetBodyCentres(centre_m);
  }

  // Simulation::Options::balance_probe_chunks: `chunks` > 0 sweeps in that many chunks, one after
  // another on the calling thread, last first; 0 (default): one chunk per worker thread.
  void SetBalanceProbe(int chunks) { balance_probe_chunks_ = std::max(0, chunks), plan_stale_ = true; }

  // Periodic axes for pair separations (minimum image); default: none.
  void SetPeriodic(const PeriodicBox& box) { periodic_ = box; }

  // The pair histories and results, the wall candidates and the sweep's scratch.
  HeapBytes Heap() const;

  // How evenly the chunks of the parallel sweep shared the work, since construction.
  const SweepBalance& sweep_balance() const { return balance_; }

  // Number of particle–particle and particle–wall contacts with positive overlap last step.
  size_t ActiveContacts() const;
  // Force and torque the particles exerted on each wall in the last Compute (see WallContacts).
  std::vector<WallLoad> WallLoads(const Particles& p, const std::vector<Wall>& walls) const {
    return walls_.Loads(p, walls);
  }
  // Checkpointing: every contact history and wall candidate list.
  template <class A>
  void Serialize(A& a) {
    plan_stale_ = true;
    a.Vector(pair_history_), a.Vector(pair_active_);
    walls_.Serialize(a);
  }

  // After a checkpoint load: histories aligned with `list`, wall candidates fit the walls.
  bool CheckRestored(const NeighbourList& list, size_t particles, const std::vector<Wall>& walls,
                     std::string* error) const;

 private:
  template <class Model>
  bool EvaluatePair(const Particles& p, const InteractionTable& table, const Model& model,
                    double dt, size_t i, uint32_t k, uint32_t j, ContactResult& out);
  // A listed pair out of contact: its history is cleared (a new contact starts from zero).
  void EndContact(uint32_t k) {
    if (pair_active_[k]) pair_history_[k] = ContactHistory{}, pair_active_[k] = 0;
  }
  // Ends contact k when out of contact, else evaluates it into `out` and marks it active.
  template <class Model>
  bool ResolveContact(uint32_t k, bool in_contact, const ContactGeometry& g,
                      const ResolvedPair& pair, const Model& model, double dt, ContactResult& out);
  template <class Model>
  void StartChunk(Particles& p, const NeighbourList& list, const InteractionTable& table,
                  const Model& model, const Vec3& gravity, double dt, size_t chunk);
  template <class Model>
  void SumChunk(Particles& p, const NeighbourList& list, const std::vector<Wall>& walls,
                const InteractionTable& table, const Model& model, const Vec3& gravity,
                double dt, size_t chunk);
  void PlanChunks(const NeighbourList& list);

  void RemapPairs(const NeighbourList& old_list, const NeighbourList& new_list,
                  const std::vector<uint32_t>& order);
  // New row i's histories from the old list: by a binary search per entry (any permutation),
  // or by one merge with old row order[i] (an order-keeping permutation).
  void SearchRow(const NeighbourList& old_list, const NeighbourList& new_list,
                 const std::vector<uint32_t>& order, size_t i,
                 std::vector<ContactHistory>& history, std::vector<uint8_t>& active) const;
  void MergeRow(const NeighbourList& old_list, const NeighbourList& new_list,
                const std::vector<uint32_t>& order, size_t i,
                std::vector<ContactHistory>& history, std::vector<uint8_t>& active) const;
  // Entry k takes old entry e's history (none if e < 0 or inactive), mirrored if `swapped`.
  void CarryPair(int64_t e, bool swapped, uint32_t k, std::vector<ContactHistory>& history,
                 std::vector<uint8_t>& active) const;

  std::vector<ContactHistory> pair_history_;  // aligned with NeighbourList entries
  struct CrossResult {  // a cross pair's contribution to its row's particle i
    Vec3 force_i;
    Vec3 torque_i;
  };
  std::vector<CrossResult> cross_result_;     // by SweepChunks slot
  std::vector<uint8_t> pair_active_;
  // The previous list's arrays, kept as RemapPairs' destination: a pour rebuilds every ~12 steps,
  // and fresh pair-sized arrays each time cost an allocation and a clearing pass.
  std::vector<ContactHistory> spare_history_;
  std::vector<uint8_t> spare_active_;
  PeriodicBox periodic_;
  BodyCentres body_centre_m_;
  SweepChunks chunks_;
  std::vector<double> chunk_cpu_s_;           // per chunk, this pass (thread CPU time)
  SweepBalance balance_;
  int balance_probe_chunks_ = 0;
  bool plan_stale_ = true;                    // chunks_ predates the list or the thread count
  const NeighbourList* planned_list_ = nullptr;
  WallContacts walls_;
  std::vector<std::vector<MeshContact>> mesh_scratch_;  // one per chunk, reused
  struct RowScratch {  // per chunk, reused row after row
    std::vector<uint32_t> touching;        // the row's entries that may contribute
    std::vector<ContactGeometry> geometry; // their geometry (own pairs)
    std::vector<uint8_t> in_contact;       // whether each is in contact
    std::vector<uint32_t> cross_slot;      // each cross pair's SweepChunks slot
  };
  std::vector<RowScratch> row_scratch_;
};

}  // namespace demcal::core
