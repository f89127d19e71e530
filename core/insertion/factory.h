#pragma once
// ParticleFactory: inserts particles of one species, or of a mixture with given mass
// fractions, into a region at a target mass rate (kg/s), in batches, at random non-overlapping
// positions with a given initial velocity. Deterministic from its seed. The shortfall of a
// batch (region momentarily full) is carried to the next one, and the factory reports the
// requested and the achieved rate. A clump feed carries the draws themselves: those a full batch
// could not place join the next batch (InsertRandomNonOverlapping places them with its new
// draws, largest first), so the placed stream is the drawn one less the carry, whose mass is at
// most the mass owed plus one body, and at most two batches (a clump batch asks for at most
// two batches' mass: the one due and one of backlog; more would only be carried again). Dropped
// instead, they would be a full batch's smallest (placed last) and the stream would come out
// coarse. A factory more than one batch behind its nominal rate (RateWarning) has a region that
// cannot hold what a batch asks for: each batch interval the region empties (the grains fall
// through it), so a full region caps the rate whatever is owed.
//
// Moving regions, so that a staged pour is one scene: the region translates with
// region_velocity_m_s while start_s <= t < end_s, and/or follows the heap it feeds: with
// follow_heap_clearance_m > 0, before each batch the region is raised (never lowered) so that
// its bottom stays that far above the heap top under it. The heap top is the third-highest top
// (z + r) of the spheres under the region's footprint (x, y of its bounding box) that move slower
// than settled_speed_m_s and lie more than half the clearance below the region (the falling
// stream is faster, a grain at the apex of a bounce is one of few: the third-highest ignores
// two). The region is not kept inside the domain: its grains then leave it (a sink removes them,
// else the run ends with "particles_lost").
//
// Thread-safety: called from the simulation's step, one factory at a time.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/insertion/insertion.h"
#include "core/materials/material.h"
#include "core/bodies/particle_system.h"
#include "core/math/random.h"

namespace demcal::core {

struct FactorySpec {
  std::string name;
  InsertionRegion region;
  std::vector<int> species;            // indices into Scene::species
  std::vector<double> mass_fractions;  // same length, sum to 1
  double mass_rate_kg_s = 0;
  double start_s = 0;
  double end_s = std::numeric_limits<double>::infinity();
  double total_mass_kg = std::numeric_limits<double>::infinity();  // stop after this mass
  Vec3 velocity_m_s;
  double batch_interval_s = 0;  // 0: the time a particle takes to cross the region
  Vec3 region_velocity_m_s;      // translation of the region while active (see above)
  double follow_heap_clearance_m = 0;  // > 0: the region's bottom stays this far above the heap
  double settled_speed_m_s = 0.05;     // a grain slower than this may be the heap top
};

struct FactoryReport {
  std::string name;
  int64_t particles = 0;
  double inserted_mass_kg = 0;
  double requested_mass_kg = 0;   // rate × active time so far (capped by total_mass_kg)
  double active_time_s = 0;
  int64_t full_batches = 0;       // batches cut short because the region was full
  double region_lift_m = 0;       // how far the region rose following the heap
  double RequestedRate() const { return active_time_s > 0 ? requested_mass_kg / active_time_s : 0; }
  double AchievedRate() const { return active_time_s > 0 ? inserted_mass_kg / active_time_s : 0; }
};

class ParticleFactory {
 public:
  // `mixture` holds one SpeciesDraw per spec species (sizes, materials, densities resolved).
  ParticleFactory(FactorySpec spec, std::vector<SpeciesDraw> mixture, double gravity_m_s2,
                  uint64_t seed);

  // Inserts the batches due at time t (s); returns the number of particles added.
  int64_t Update(double t, ParticleSystem& system);

  // The batch interval used for `spec` under gravity of magnitude g (m/s²).
  static double BatchInterval(const FactorySpec& spec, double gravity_m_s2);

  // Checkpointing: the random stream and the progress (spec and mixture come from the scene).
  template <class A>
  void Serialize(A& a) {
    rng_.Serialize(a);
    a.Value(next_batch_s_), a.Value(owed_kg_), a.Value(report_.particles);
    a.Value(report_.inserted_mass_kg), a.Value(report_.requested_mass_kg);
    a.Value(report_.active_time_s), a.Value(report_.full_batches);
    a.Value(report_.region_lift_m);
    a.Vector(carried_);
  }
  // Where the region is for a batch at time t (after the heap lift of the last batch).
  InsertionRegion RegionAt(double time_s) const;
  // The heap top under `region` (see the file comment); −infinity if no grain qualifies.
  double HeapTop(const Particles& spheres, const InsertionRegion& region) const;

  // After a checkpoint load at time_s: progress finite, the next batch due in range, and the
  // carried draws of the mixture's species and sizes, weighing at most what is owed plus a body.
  bool CheckRestored(double time_s, const ParticleSystem& system, std::string* error) const;

  const FactoryReport& report() const { return report_; }
  // Empty while the factory is at most one batch (nominal rate × batch interval) behind its
  // nominal mass rate over its active time — the most a factory that keeps up owes (the mass of
  // the batch in progress, or the remainder of a capped total); otherwise a warning naming the
  // factory with its achieved and nominal rates and the cause. A factory that fell behind and
  // finished its total_mass_kg late stays behind: its active time ran on until it finished.
  std::string RateWarning() const;
  const FactorySpec& spec() const { return spec_; }
  double batch_interval_s() const { return interval_; }
  // Clump draws that found no room, waiting for the next batch (see the file comment).
  const std::vector<CarriedDraw>& carried() const { return carried_; }
  double CarriedMassKg(const ParticleSystem& system) const;

 private:
  bool HasClump(const ParticleSystem& system) const;  // a clump species in the mixture

  FactorySpec spec_;
  std::vector<SpeciesDraw> mixture_;
  Rng rng_;
  double interval_ = 0;
  double next_batch_s_ = 0;
  double owed_kg_ = 0;  // requested but not yet inserted
  std::vector<CarriedDraw> carried_;
  FactoryReport report_;
};

}  // namespace demcal::core
