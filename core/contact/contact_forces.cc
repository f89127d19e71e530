#include "core/contact/contact_forces.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <ctime>
#include <cmath>
#include <numeric>

#include "core/contact/contact_kernel.h"
#include "core/math/parallel_passes.h"

namespace demcal::core {
namespace {
// Measured chunk balancing (SweepChunks::Rebalance): the window of passes, and the imbalance
// worth re-planning for (a re-plan is a pass over the rows, cheaper than a sweep). Chunks are
// timed in thread CPU time, so other processes' load does not enter the window; short enough to
// follow where a pour's grains land (the balance probe at 16 chunks, a 20,000-sphere column
// pour: 0.58 / 0.67 / 0.75 / 0.80 at windows of 100 / 50 / 20 / 10 passes; the dense bed 0.84 /
// – / 0.87 / 0.88; docs/performance.md).
constexpr int kRebalancePasses = 10;
constexpr double kRebalanceTolerance = 0.03;

// The calling thread's CPU time, s. A chunk is timed in it rather than on the wall clock so that
// neither its balance figures nor Rebalance follow other processes' load.
double ThreadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
}  // namespace

DEMCAL_HOT_INLINE void StoreVec3(Vec3& to, const Vec3& v) { to.x = v.x, to.y = v.y, to.z = v.z; }

// Geometry of the contact between listed partners i < j, or false if they are not in contact.
template <class Model>
DEMCAL_HOT_INLINE bool PairGeometry(const Particles& p, size_t i, uint32_t j, bool was_in_contact,
                         const ResolvedPair& pair, const PeriodicBox* box, ContactGeometry& g) {
  const Vec3 d = box ? box->MinimumImage(p.position_m[i] - p.position_m[j])
                     : p.position_m[i] - p.position_m[j];
  const double ri = p.radius_m[i], rj = p.radius_m[j];
  const double rsum = ri + rj;
  const double dist2 = Norm2(d);
  if (dist2 >= rsum * rsum && !(Model::Normal::kAdhesive && was_in_contact)) return false;
  const double dist = std::sqrt(dist2);
  g.overlap_m = rsum - dist;
  g.effective_radius_m = ri * rj / rsum;
  if (!Model::InContact(g.overlap_m, was_in_contact, g.effective_radius_m, pair)) return false;
  // Computed in locals and stored component by component: GCC otherwise copies a Vec3 through
  // a stack temporary whose 16-byte reload straddles two 8-byte stores, and the failed store
  // forwarding stalled this loop by ~10 % (perf annotate). It also cannot prove that g does not
  // alias p, so it would reload g's fields.
  const Vec3 normal = d * (1.0 / dist);
  const double mi = p.mass_kg[i], mj = p.mass_kg[j];
  const Vec3 wi = p.angular_velocity_rad_s[i], wj = p.angular_velocity_rad_s[j];
  const Vec3 v = p.velocity_m_s[i] - p.velocity_m_s[j] - Cross(ri * wi + rj * wj, normal);
  StoreVec3(g.normal, normal);
  g.radius_i_m = ri;
  g.radius_j_m = rj;
  if constexpr (Model::kReadsRollingLever) g.rolling_lever_i_m = ri, g.rolling_lever_j_m = rj;
  g.mass_i_kg = mi;
  g.mass_j_kg = mj;
  g.effective_mass_kg = mi * mj / (mi + mj);
  StoreVec3(g.omega_i, wi);
  StoreVec3(g.omega_j, wj);
  StoreVec3(g.relative_velocity_m_s, v);
  return true;
}

template <class Model>
DEMCAL_HOT_INLINE bool ContactForces::EvaluatePair(const Particles& p, const InteractionTable& table,
                                 const Model& model, double dt, size_t i, uint32_t k, uint32_t j,
                                 ContactResult& out) {
  ContactGeometry g{};
  const ResolvedPair& pair = table.Get(p.material[i], p.material[j]);
  const bool touching =
      PairGeometry<Model>(p, i, j, pair_active_[k], pair, periodic_.Any() ? &periodic_ : nullptr, g);
  if constexpr (Model::kReadsRollingLever)
    if (touching && !body_centre_m_.empty()) SetClumpLevers(p, body_centre_m_, i, j, g);
  return ResolveContact(k, touching, g, pair, model, dt, out);
}

template <class Model>
DEMCAL_HOT_INLINE bool ContactForces::ResolveContact(uint32_t k, bool in_contact,
                                                     const ContactGeometry& g,
                                                     const ResolvedPair& pair, const Model& model,
                                                     double dt, ContactResult& out) {
  if (!in_contact) {
    EndContact(k);
    return false;
  }
  out = model.Evaluate(g, pair, dt, pair_history_[k]);
  pair_active_[k] = 1;
  return true;
}

// Chunk c's start: its particles' sums begun with gravity and then the contributions of the cross
// pairs from earlier rows (its incoming set), in entry order, as a serial sweep adds them. Each
// cross pair is evaluated here, once; its result on i is kept in the pair's slot for the sweep
// of i's chunk to read back.
template <class Model>
void ContactForces::StartChunk(Particles& p, const NeighbourList& list,
                               const InteractionTable& table, const Model& model,
                               const Vec3& gravity, double dt, size_t c) {
  for (uint32_t i = chunks_.Begin(c); i < chunks_.End(c); ++i) {
    p.force_N[i] = p.body[i] < 0 ? gravity * p.mass_kg[i] : Vec3{};  // clumps get gravity whole
    p.torque_N_m[i] = Vec3{};
  }
  for (const SweepChunks::CrossPair& x : chunks_.Incoming(c)) {
    const uint32_t j = list.Partner(x.entry);
    ContactResult r;
    if (!EvaluatePair(p, table, model, dt, x.row, x.entry, j, r)) continue;
    StoreVec3(cross_result_[x.slot].force_i, r.force_i);
    StoreVec3(cross_result_[x.slot].torque_i, r.torque_i);
    p.force_N[j] -= r.force_i;
    p.torque_N_m[j] += r.torque_j;
  }
}

// Chunk c owns particle slots [Begin(c), End(c)) and sums, per particle and in the order a
// serial sweep would, the contributions from earlier rows first (StartChunk), then its own row,
// then walls, so results are bit-identical for any number of chunks.
template <class Model>
void ContactForces::SumChunk(Particles& p, const NeighbourList& list,
                             const std::vector<Wall>& walls, const InteractionTable& table,
                             const Model& model, const Vec3& gravity, double dt, size_t c) {
  auto start = [&](size_t d) { StartChunk(p, list, table, model, gravity, dt, d); };
  const uint32_t begin = chunks_.Begin(c), end = chunks_.End(c);
  const uint32_t moving = list.FirstFixed();  // partners from here on are fixed spheres
  if (c == 0) start(0);  // no other chunk reads chunk 0's particles
  else chunks_.Ensure(c, start);
  size_t ready = c;  // chunks up to `ready` have their incoming cross pairs evaluated
  RowScratch& scratch = row_scratch_[c];
  uint32_t* const touching = scratch.touching.data();
  ContactGeometry* const geometry = scratch.geometry.data();
  uint8_t* const in_contact = scratch.in_contact.data();
  uint32_t* const cross_slot = scratch.cross_slot.data();
  uint32_t slot = chunks_.OutgoingBegin(c);  // the next cross pair's, in the order met here
  const PeriodicBox* box = periodic_.Any() ? &periodic_ : nullptr;
  for (uint32_t i = begin; i < end; ++i) {
    Vec3& fi = p.force_N[i];
    Vec3& ti = p.torque_N_m[i];
    // Pass 1, without branches on the data: the row's entries that may contribute (touching,
    // or in contact last step: a contact to end, or a JKR neck) — about half of the entries, in
    // no predictable pattern, so testing them one by one in pass 2 would mispredict often.
    const Vec3 xi = p.position_m[i];
    const double ri = p.radius_m[i];
    uint32_t n = 0;
    for (uint32_t k = list.RowBegin(i); k < list.RowEnd(i); ++k) {
      const uint32_t j = list.Partner(k);
      touching[n] = k;
      if (j >= end && j < moving) {  // a cross pair, evaluated by SweepChunks::Ensure
        while (j >= chunks_.End(ready)) chunks_.Ensure(++ready, start);
        cross_slot[n] = slot++;
        n += pair_active_[k];
        continue;
      }
      const Vec3 d = box ? box->MinimumImage(xi - p.position_m[j]) : xi - p.position_m[j];
      const double rsum = ri + p.radius_m[j];
      n += static_cast<uint32_t>(Norm2(d) < rsum * rsum) | pair_active_[k];
    }
    // Pass 2: the geometry of every own pair of the row. Pairs are independent here, so the
    // square roots and divisions of several pairs overlap in the pipeline; evaluated one after
    // another with their forces, each pair's chain of them set the pace.
    for (uint32_t m = 0; m < n; ++m) {
      const uint32_t k = touching[m];
      const uint32_t j = list.Partner(k);
      if (j >= end && j < moving) continue;
      const ResolvedPair& pair = table.Get(p.material[i], p.material[j]);
      in_contact[m] = PairGeometry<Model>(p, i, j, pair_active_[k], pair, box, geometry[m]);
      if constexpr (Model::kReadsRollingLever)
        if (in_contact[m] && !body_centre_m_.empty())
          SetClumpLevers(p, body_centre_m_, i, j, geometry[m]);
    }
    // Pass 3: the contributions in entry order (the serial sweep's summation order).
    for (uint32_t m = 0; m < n; ++m) {
      const uint32_t k = touching[m];
      const uint32_t j = list.Partner(k);
      if (j >= end && j < moving) {
        fi += cross_result_[cross_slot[m]].force_i;
        ti += cross_result_[cross_slot[m]].torque_i;
        continue;
      }
      ContactResult r{};
      const ResolvedPair& pair = table.Get(p.material[i], p.material[j]);
      if (!ResolveContact(k, in_contact[m], geometry[m], pair, model, dt, r)) continue;
      fi += r.force_i;
      ti += r.torque_i;
      if (j >= moving) continue;  // a fixed sphere needs no force (and other chunks touch it)
      p.force_N[j] -= r.force_i;
      p.torque_N_m[j] += r.torque_j;
    }
    walls_.Sum(p, i, walls, table, model, dt, mesh_scratch_[c], fi, ti);
  }
}

void ContactForces::PlanChunks(const NeighbourList& list) {
  // One chunk per worker: the fewest cross pairs. Chunks of fewer than ~256 particles would
  // cost more in cross pairs than they gain.
  const size_t workers = balance_probe_chunks_ > 0 ? balance_probe_chunks_
                                                  : tbb::this_task_arena::max_concurrency();
  const size_t chunks = std::min<size_t>(workers, list.FirstFixed() / 256 + 1);
  const bool list_changed = plan_stale_ || planned_list_ != &list;
  if (planned_list_ && chunks_.Count() == chunks) {
    chunks_.Rebalance(list, list_changed, kRebalancePasses, kRebalanceTolerance);
    if (!list_changed) return;
  } else {
    chunks_.Plan(list, chunks);
  }
  const uint32_t longest_row = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, list.FirstFixed()), uint32_t{0},
      [&](const auto& range, uint32_t longest) {
        for (size_t i = range.begin(); i != range.end(); ++i)
          longest = std::max(longest, list.RowEnd(i) - list.RowBegin(i));
        return longest;
      },
      [](uint32_t a, uint32_t b) { return std::max(a, b); });
  row_scratch_.resize(chunks);
  for (RowScratch& s : row_scratch_) {
    s.touching.resize(longest_row + 1);
    s.geometry.resize(longest_row + 1);
    s.in_contact.resize(longest_row + 1);
    s.cross_slot.resize(longest_row + 1);
  }
  plan_stale_ = false;
  planned_list_ = &list;
}

void ContactForces::Compute(Particles& p, const NeighbourList& list,
                            const std::vector<Wall>& walls, double time_s,
                            const InteractionTable& table, const NormalModel& normal,
                            const RollingModel& rolling, const Vec3& gravity, double dt) {
  if (pair_history_.size() != list.PairCount()) {
    pair_history_.resize(list.PairCount());
    pair_active_.resize(list.PairCount(), 0);
  }
  PlanChunks(list);
  cross_result_.resize(chunks_.CrossPairCount());
  const size_t chunks = chunks_.Count();
  if (mesh_scratch_.size() < chunks) mesh_scratch_.resize(chunks);
  walls_.SetVelocities(walls, time_s);
  auto run = [&](const auto& model) {
    if (chunks == 1) {
      SumChunk(p, list, walls, table, model, gravity, dt, 0);
      return;
    }
    chunks_.ResetClaims();
    chunk_cpu_s_.resize(chunks);
    auto sweep = [&](size_t c) {
      const double start = ThreadCpuSeconds();
      SumChunk(p, list, walls, table, model, gravity, dt, c);
      chunk_cpu_s_[c] = ThreadCpuSeconds() - start;
    };
    if (balance_probe_chunks_ > 0) {
      for (size_t c = chunks; c-- > 0;) sweep(c);
    } else {
      tbb::parallel_for(size_t{0}, chunks, sweep);
    }
    double slowest = 0;
    for (size_t c = 0; c < chunks; ++c) {
      chunks_.AddTime(c, chunk_cpu_s_[c]);
      balance_.chunk_cpu_s += chunk_cpu_s_[c];
      slowest = std::max(slowest, chunk_cpu_s_[c]);
    }
    balance_.capacity_cpu_s += static_cast<double>(chunks) * slowest;
    balance_.chunks = static_cast<int64_t>(chunks);
    balance_.cross_pairs += static_cast<double>(chunks_.CrossPairCount());
    balance_.listed_pairs += static_cast<double>(list.PairCount());
    ++balance_.passes;
  };
  // The one dispatch point of the contact laws: one instantiation of the loop per combination.
  std::visit(
      [&](const auto& normal_law, const auto& rolling_model) {
        using N = std::decay_t<decltype(normal_law)>;
        using R = std::decay_t<decltype(rolling_model)>;
        run(ContactModel<N, R>{normal_law, rolling_model});
      },
      normal, rolling);
}

void ContactForces::Rebuild(const Particles& p, const NeighbourList& old_list,
                            const NeighbourList& new_list, const std::vector<uint32_t>& order,
                            const std::vector<Wall>& walls, double skin_m, double adhesive_gap_m) {
  RemapPairs(old_list, new_list, order);
  plan_stale_ = true;
  walls_.Rebuild(p, old_list.ReferencePositions(), new_list.ReferencePositions(), order, walls,
                 skin_m, new_list.FirstFixed(), adhesive_gap_m);
}

void ContactForces::RemapPairs(const NeighbourList& old_list, const NeighbourList& new_list,
                               const std::vector<uint32_t>& order) {
  const size_t n = new_list.RowsCount();
  std::vector<ContactHistory>& history = spare_history_;
  std::vector<uint8_t>& active = spare_active_;
  history.resize(new_list.PairCount());  // every entry is written below
  active.resize(new_list.PairCount());
  // Without a permutation, or with an order-keeping one (a sink's removal compacts the slots),
  // old row order[i] holds i's old partners in the same ascending order as the new row: one
  // merge pass per row instead of a binary search per entry.
  const bool keeps_order = IsAscending(order);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      if (keeps_order) MergeRow(old_list, new_list, order, i, history, active);
      else SearchRow(old_list, new_list, order, i, history, active);
    }
  });
  pair_history_.swap(history);
  pair_active_.swap(active);
}

void ContactForces::CarryPair(int64_t e, bool swapped, uint32_t k,
                              std::vector<ContactHistory>& history,
                              std::vector<uint8_t>& active) const {
  if (e < 0 || !pair_active_[e]) {
    history[k] = ContactHistory{};
    active[k] = 0;
    return;
  }
  history[k] = pair_history_[e];
  active[k] = 1;
  if (swapped) {  // i and j swapped roles: the relative displacement changes sign
    history[k].shear_m = -history[k].shear_m;
    history[k].rolling_torque_N_m = -history[k].rolling_torque_N_m;
  }
}

void ContactForces::SearchRow(const NeighbourList& old_list, const NeighbourList& new_list,
                              const std::vector<uint32_t>& order, size_t i,
                              std::vector<ContactHistory>& history,
                              std::vector<uint8_t>& active) const {
  auto old_slot = [&](uint32_t s) { return order.empty() ? s : order[s]; };
  for (uint32_t k = new_list.RowBegin(i); k < new_list.RowEnd(i); ++k) {
    const uint32_t a = old_slot(static_cast<uint32_t>(i)), b = old_slot(new_list.Partner(k));
    CarryPair(old_list.Find(std::min(a, b), std::max(a, b)), a > b, k, history, active);
  }
}

void ContactForces::MergeRow(const NeighbourList& old_list, const NeighbourList& new_list,
                             const std::vector<uint32_t>& order, size_t i,
                             std::vector<ContactHistory>& history,
                             std::vector<uint8_t>& active) const {
  auto old_slot = [&](uint32_t s) { return order.empty() ? s : order[s]; };
  const uint32_t a = old_slot(static_cast<uint32_t>(i));
  const bool old_row = a < old_list.RowsCount();  // newcomers had none
  uint32_t e = old_row ? old_list.RowBegin(a) : 0;
  const uint32_t e_end = old_row ? old_list.RowEnd(a) : 0;
  for (uint32_t k = new_list.RowBegin(i); k < new_list.RowEnd(i); ++k) {
    const uint32_t b = old_slot(new_list.Partner(k));
    while (e < e_end && old_list.Partner(e) < b) ++e;
    CarryPair(e < e_end && old_list.Partner(e) == b ? int64_t{e} : -1, false, k, history, active);
  }
}

double ContactForces::PairElasticEnergy(const Particles& p, const NeighbourList& list,
                                        const InteractionTable& table) const {
  double energy = 0;
  for (size_t i = 0; i < list.RowsCount(); ++i)
    for (uint32_t k = list.RowBegin(i); k < list.RowEnd(i); ++k) {
      const uint32_t j = list.Partner(k);
      const double rsum = p.radius_m[i] + p.radius_m[j];
      const double overlap = rsum - Norm(periodic_.MinimumImage(p.position_m[i] - p.position_m[j]));
      if (overlap <= 0) continue;
      const double r_eff = p.radius_m[i] * p.radius_m[j] / rsum;
      energy += 8.0 / 15.0 * table.Get(p.material[i], p.material[j]).effective_youngs_Pa *
                std::sqrt(r_eff) * std::pow(overlap, 2.5);
    }
  return energy;
}

HeapBytes ContactForces::Heap() const {
  HeapBytes b = walls_.Heap();
  b.per_pair += VectorBytes(pair_history_, pair_active_, spare_history_, spare_active_);
  for (const RowScratch& s : row_scratch_)
    b.other += VectorBytes(s.touching, s.geometry, s.in_contact, s.cross_slot);
  b.other += VectorBytes(cross_result_);
  b.other += chunks_.HeapBytes();
  return b;
}

size_t ContactForces::ActiveContacts() const {
  return std::accumulate(pair_active_.begin(), pair_active_.end(), size_t{0}) +
         walls_.ActiveContacts();
}

}  // namespace demcal::core
