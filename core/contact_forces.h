#pragma once
// ContactForces: evaluates every particle–particle and particle–wall contact and accumulates
// force and torque per particle, keeping the per-contact histories (tangential spring, rolling
// spring) across steps and across neighbour-list rebuilds.
//
// Determinism: each listed pair is evaluated once into its own slot; each particle then sums
// its slots in a fixed order (its row, then its reverse entries, then walls). Floating-point
// sums therefore do not depend on the number of threads.
#include <vector>

#include "core/contact/contact_state.h"
#include "core/contact/rolling_model.h"
#include "core/interaction_table.h"
#include "core/neighbour_list.h"
#include "core/particles.h"
#include "core/walls.h"

namespace demcal::core {

class ContactForces {
 public:
  // Sets all forces and torques of `p` (gravity included).
  void Compute(Particles& p, const NeighbourList& list, const std::vector<PlaneWall>& walls,
               const InteractionTable& table, const RollingModel& rolling, const Vec3& gravity,
               double dt);

  // Carries histories over to a freshly built list. `order[new_slot] = old_slot` describes a
  // particle permutation applied together with the rebuild (identity if empty).
  void Remap(const NeighbourList& old_list, const NeighbourList& new_list,
             const std::vector<uint32_t>& order, size_t wall_count);

  // Number of particle–particle and particle–wall contacts with positive overlap last step.
  size_t ActiveContacts() const;
  const std::vector<ContactHistory>& PairHistory() const { return pair_history_; }
  std::vector<ContactHistory>& MutablePairHistory() { return pair_history_; }
  std::vector<ContactHistory>& MutableWallHistory() { return wall_history_; }

 private:
  template <class Rolling>
  void ComputePairs(const Particles& p, const NeighbourList& list, const InteractionTable& table,
                    const Rolling& rolling, double dt);
  template <class Rolling>
  void Gather(Particles& p, const NeighbourList& list, const std::vector<PlaneWall>& walls,
              const InteractionTable& table, const Rolling& rolling, const Vec3& gravity,
              double dt);

  std::vector<ContactHistory> pair_history_;  // aligned with NeighbourList entries
  std::vector<ContactResult> pair_result_;    // aligned with NeighbourList entries
  std::vector<uint8_t> pair_active_;
  std::vector<ContactHistory> wall_history_;  // particle-major: [i * walls + w]
  std::vector<uint8_t> wall_active_;
};

}  // namespace demcal::core
