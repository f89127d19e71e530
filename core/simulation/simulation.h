#pragma once
// Simulation: the DEM engine facade. Lifecycle: construct from a Scene → Initialize() (validates,
// resolves materials, places the initial particles, builds the neighbour list) → Run() as often
// as needed. Each Run() returns a RunSummary; failures (NaN, energy blow-up, lost particles,
// wall-time budget) are reported there, never thrown.
//
// Threads: a Simulation runs inside its own TBB arena of `threads` workers (0 = all cores), so
// many small simulations can run side by side, each with one thread. Results are bit-identical
// for any thread count (see ContactForces).
//
// Usage:
//   Simulation sim(scene, {.threads = 1});
//   std::string err;
//   if (!sim.Initialize(&err)) ...;
//   RunSummary s = sim.Run(scene.time.duration_s);
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <tbb/task_arena.h>

#include "core/contact/contact_forces.h"
#include "core/insertion/factory.h"
#include "core/neighbours/neighbour_list.h"
#include "core/bodies/particle_system.h"
#include "core/simulation/run_summary.h"
#include "core/scene/scene.h"
#include "core/scene/scene_fingerprint.h"

namespace demcal::core {

class Simulation {
 public:
  struct Options {
    int threads = 0;                  // 0: all available cores
    int check_every_steps = 100;      // cadence of the NaN / energy / domain checks
    int reorder_every_rebuilds = 20;  // spatial re-sort of particles for cache locality (0: never)
    // Fixed spheres are kept in the slots after the moving ones, out of the pair search among
    // themselves, of the integration and of the force sweep (moving–fixed contacts unchanged).
    // false: they are swept like moving spheres with zero inverse mass (for comparisons).
    bool exclude_fixed_pairs = true;
    // Incremental neighbour rebuilds (NeighbourList::Update): at a rebuild only the particles
    // more than this fraction of the skin from their reference position are re-searched, the
    // rows of the others are kept. Range (0, 0.5]; 0: every rebuild searches all particles.
    double neighbour_refresh_fraction = 0.25;
    // Sinks (Scene::sinks) remove the particles that reached them at the first neighbour
    // rebuild at least this many steps after their previous pass (as LIGGGHTS deletes lost
    // atoms when it re-neighbours). A removal changes the slots, so that rebuild is a full
    // build instead of an incremental one: the cadence bounds that cost. A grain that crossed a
    // sink is fast, so rebuilds come every few steps: 50 steps at Δt ~ 2e-5 s is a ~1 ms lag.
    int sink_every_steps = 50;
    // A measurement of the force sweep's balance at this many threads on any machine (0: off):
    // the sweep runs in that many chunks one after another on one thread, the last first, so
    // each chunk evaluates exactly its own cross pairs, as when every chunk has its own core;
    // RunSummary::sweep_balance then gives the balance those threads would see. Results are
    // the same as with any thread count.
    int balance_probe_chunks = 0;
  };
  // Called during Run() after every step whose step count (steps(), counted from the start of
  // the simulation, so a restarted run keeps the cadence) is a multiple of `every_steps`;
  // return false to stop the run early (ok).
  struct Observer {
    int64_t every_steps = 0;
    std::function<bool(const Simulation&)> callback;
  };

  explicit Simulation(Scene scene);
  Simulation(Scene scene, Options options);
  ~Simulation();

  bool Initialize(std::string* error);
  // Checkpoint: the complete dynamic state (particles, clumps, contact histories, neighbour
  // list, factories' random streams, time). Restore into a Simulation initialised from the same
  // scene; the continued run is bit-identical to an uninterrupted one. Saving is atomic
  // (temporary, fsync, rename). Loading verifies the file (core/checkpoint/checkpoint_file.h: length,
  // checksum), the scene fingerprint and time step (core/scene/scene_fingerprint.h), and every count
  // and index of the state before use; false with "PATH: checkpoint: <failed check>". A file
  // refused before its payload leaves the simulation untouched; one refused later leaves it
  // uninitialised (Run() refuses to run it). `may_differ`: fingerprint parts allowed to differ
  // from this scene's (a hand-over to a changed scene, e.g. {"wall motion"} for a gate opened
  // later); never the time step.
  bool SaveCheckpoint(const std::string& path, std::string* error) const;
  bool LoadCheckpoint(const std::string& path, std::string* error,
                      const std::vector<std::string>& may_differ = {});
  // The same from the bytes of a whole checkpoint file; `name` stands for the file in messages.
  bool LoadCheckpointBytes(const std::string& file_bytes, const std::string& name,
                           std::string* error, const std::vector<std::string>& may_differ = {});

  // Changes the body-force field for subsequent steps (load-controlled tests, tilting).
  void SetGravity(const Vec3& gravity_m_s2) { scene_.gravity_m_s2 = gravity_m_s2; }
  // Changes the worker count for subsequent Run() calls (0: all cores).
  void SetThreads(int threads);
  // Options::balance_probe_chunks from now on (0: off).
  void SetBalanceProbe(int chunks);
  RunSummary Run(double duration_s);
  RunSummary Run(double duration_s, const Observer& observer);

  const Scene& scene() const { return scene_; }
  // All spheres (free ones and clump members); clumps themselves are in system().clumps.
  const Particles& particles() const { return system_.spheres; }
  Particles& mutable_particles() { return system_.spheres; }
  const ParticleSystem& system() const { return system_; }
  double time_s() const { return time_s_; }
  int64_t steps() const { return steps_; }
  double timestep_s() const { return dt_; }
  double KineticEnergy() const { return system_.KineticEnergy(); }
  size_t ActiveContacts() const { return forces_.ActiveContacts(); }
  // The walls where they are now (moving walls translated; scene().walls holds them at t = 0).
  const std::vector<Wall>& walls() const { return walls_; }
  // Per wall (scene order): the force and torque the particles exerted on it in the last force
  // pass (the last step, or Initialize). Summed in particle order: identical for any thread count.
  std::vector<WallLoad> WallLoads() const { return forces_.WallLoads(system_.spheres, walls_); }
  const NeighbourList& neighbours() const { return list_; }
  // Heap bytes of the state and scratch arrays (particles, clumps, the three neighbour lists,
  // contact histories, wall candidates), by what they grow with.
  HeapBytes Heap() const;
  // Wall time per phase of the step since Initialize (RunSummary::phases has one Run's).
  const PhaseTimes& phases() const { return phases_; }
  std::vector<FactoryReport> FactoryReports() const;
  const std::vector<ParticleFactory>& factories() const { return factories_; }
  // The report of the factory named `name` (the first, if several share it); nullptr if none.
  const FactoryReport* FindFactoryReport(const std::string& name) const;
  // ParticleFactory::RateWarning of every factory that fell behind its nominal rate.
  std::vector<std::string> FactoryRateWarnings() const;
  // Per sink (scene order), then the implicit "domain" sink when the scene has sinks: what
  // each has removed so far, per species.
  const std::vector<SinkReport>& SinkReports() const { return sink_reports_; }

 private:
  void PlaceInitialParticles(std::string* error);
  void CreateFactories();
  // Runs the factories due now; true if particles were added.
  bool InsertFromFactories();
  // One step. `defer_kick`: leave the free spheres' second half kick to the next step's first
  // pass (ParticleSystem::ReduceAndKick); only when that step follows with nothing in between
  // that reads velocities (no check, observer or end of Run).
  void Step(bool defer_kick);
  // Translates the moving walls to where they are at time t.
  void PlaceWalls(double time_s);
  // Adds the work the moving walls did on the particles this step to the energy budget.
  void AddWallWork(double time_s);
  void ComputeForces(double time_s);
  // Removes the particles that reached a sink; true if any were, with removal_order_ holding
  // the old slot of each remaining one.
  bool RemoveSunkParticles();
  // Marks the walls removed by time t (Wall::remove_at_s); true if that changed any.
  bool WallRemovedDuringStep(double time_s);
  template <class A>
  void SerializeState(A& a, const std::vector<std::string>& may_differ);
  std::vector<FingerprintPart> Fingerprint() const;
  bool LoadCheckpointPayload(const std::string& payload, const std::string& name,
                             std::string* error, const std::vector<std::string>& may_differ);
  // Every count, index and value of a just-restored state (core/checkpoint_checks_*.cc).
  bool CheckRestoredState(std::string* error) const;
  bool CheckRestoredBodies(std::string* error) const;
  bool CheckRestoredProgress(std::string* error) const;
  // Physical consistency of a restored state with what can be derived from the scene
  // (core/checkpoint/checkpoint_checks_physics.cc): masses and inertias from radius and density,
  // clump centres from their members, the energy budget and scale, sink and factory counters.
  bool CheckRestoredPhysics(std::string* error) const;
  bool CheckRestoredEnergy(std::string* error) const;
  bool CheckRestoredCounters(std::string* error) const;
  // The least and most mass one body of species k can have (its size distribution and the
  // scene's explicit diameters).
  void BodyMassRange(int k, double* lo_kg, double* hi_kg) const;
  // The most one inserted body can add to the energy scale: its kinetic energy at the fastest
  // factory velocity, a fall through the whole domain and the adhesion bound of its spheres.
  double InsertedEnergyBound(double adhesion_per_sphere_J) const;
  // `removed` (may be empty): the old slot of each remaining slot after a removal this step.
  void RebuildNeighbours(bool allow_reorder, const std::vector<uint32_t>& removed = {});
  // Returns kOk, or the failure found by the periodic checks (and fills message).
  Termination Check(std::string* message) const;

  Scene scene_;
  Options options_;
  std::unique_ptr<tbb::task_arena> arena_;
  InteractionTable table_;
  NormalModel normal_;  // the normal law the pair table calls for (MakeNormalModel)
  RollingModel rolling_;
  ParticleSystem system_;
  NeighbourList list_;
  NeighbourList spare_list_;  // the previous list, kept for history transfer and its buffers
  NeighbourList compacted_list_;  // spare_list_ less the slots a sink took (Update's input)
  NeighbourList::Settings list_settings_;
  ContactForces forces_;
  std::vector<Wall> walls_;  // current placement of scene_.walls
  bool walls_move_ = false;
  std::vector<ParticleFactory> factories_;
  std::vector<SinkReport> sink_reports_;
  std::vector<uint8_t> sphere_gone_, clump_gone_;  // removal scratch
  std::vector<uint32_t> removal_order_;
  size_t slots_before_removal_ = 0;  // sphere slots before this step's removal (0: none)
  int64_t last_sink_pass_step_ = 0;  // step of the last sink pass (checkpointed)
  double dt_ = 0;
  double time_s_ = 0;
  int64_t steps_ = 0;
  bool kick_pending_ = false;  // the last Step deferred its spheres' second half kick
  uint64_t rebuilds_since_reorder_ = 0;
  RebuildSearch rebuild_search_;  // summed over the steps' rebuilds (RunSummary)
  PhaseTimes phases_;
  double energy_budget_J_ = 0;   // initial KE + PE (+ inserted energy)
  double energy_scale_J_ = 0;    // energy that gravity and the initial state can release
  Vec3 lowest_point_;            // of the domain along gravity
  // What a restored state is checked against, recorded by Initialize: the bodies the scene
  // places at the start, the energy scale of that state, and InsertedEnergyBound.
  size_t initial_bodies_ = 0;
  double initial_energy_scale_J_ = 0;
  double inserted_energy_bound_J_ = 0;
  double adhesive_gap_m_ = 0;  // the normal law's largest break gap (MaxAdhesiveBreakGap)
  bool initialized_ = false;
};

}  // namespace demcal::core
