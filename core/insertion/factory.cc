#include "core/insertion/factory.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace demcal::core {

ParticleFactory::ParticleFactory(FactorySpec spec, std::vector<SpeciesDraw> mixture,
                                 double gravity_m_s2, uint64_t seed)
    : spec_(std::move(spec)), mixture_(std::move(mixture)), rng_(seed), next_batch_s_(spec_.start_s) {
  std::vector<double> mean_mass;
  for (const SpeciesDraw& d : mixture_) mean_mass.push_back(d.density_kg_m3 * d.size->MeanVolume());
  const std::vector<double> weights = NumberWeightsFromMassFractions(spec_.mass_fractions, mean_mass);
  for (size_t k = 0; k < mixture_.size(); ++k) mixture_[k].number_weight = weights[k];
  interval_ = BatchInterval(spec_, gravity_m_s2);
  report_.name = spec_.name;
}

double ParticleFactory::BatchInterval(const FactorySpec& spec, double gravity_m_s2) {
  if (spec.batch_interval_s > 0) return spec.batch_interval_s;
  // The time a particle needs to fall through the region, so each batch finds the region
  // (nearly) emptied by the previous one.
  const double h = spec.region.max_m.z - spec.region.min_m.z;
  const double v = std::abs(spec.velocity_m_s.z);
  const double g = std::abs(gravity_m_s2);
  if (g == 0) return h / std::max(v, 1e-3);
  return (-v + std::sqrt(v * v + 2 * g * h)) / g;
}

int64_t ParticleFactory::Update(double t, ParticleSystem& system) {
  int64_t added = 0;
  while (t >= next_batch_s_ && next_batch_s_ < spec_.end_s &&
         report_.inserted_mass_kg < spec_.total_mass_kg) {
    const double span = std::min(interval_, spec_.end_s - next_batch_s_);
    const double requested = std::min(spec_.mass_rate_kg_s * span,
                                      spec_.total_mass_kg - report_.requested_mass_kg);
    report_.requested_mass_kg += requested;
    report_.active_time_s += span;
    owed_kg_ += requested;
    InsertionRequest q;
    q.region = RegionAt(next_batch_s_);
    if (spec_.follow_heap_clearance_m > 0) {
      const double lift = HeapTop(system.spheres, q.region) + spec_.follow_heap_clearance_m -
                          q.region.min_m.z;
      if (lift > 0) {
        report_.region_lift_m += lift;
        q.region = RegionAt(next_batch_s_);
      }
    }
    q.mixture = mixture_;
    q.max_mass_kg = owed_kg_;
    if (HasClump(system)) {
      q.max_mass_kg = std::min(owed_kg_, 2 * spec_.mass_rate_kg_s * interval_);
      q.carried = std::move(carried_);
    }
    q.velocity_m_s = spec_.velocity_m_s;
    InsertionResult r = InsertRandomNonOverlapping(q, rng_, system);
    carried_ = std::move(r.unplaced);
    owed_kg_ -= r.mass_kg;  // may go slightly negative: the last particle overshoots
    report_.inserted_mass_kg += r.mass_kg;
    report_.particles += r.count;
    if (r.region_full) ++report_.full_batches;
    added += r.count;
    next_batch_s_ += interval_;
  }
  return added;
}

bool ParticleFactory::HasClump(const ParticleSystem& system) const {
  for (const SpeciesDraw& d : mixture_)
    if (system.IsClump(d.species)) return true;
  return false;
}

double ParticleFactory::CarriedMassKg(const ParticleSystem& system) const {
  double kg = 0;
  for (const CarriedDraw& c : carried_)
    kg += DrawMassKg(system, mixture_[c.mixture_index], c.diameter_m);
  return kg;
}

std::string ParticleFactory::RateWarning() const {
  const double nominal = spec_.mass_rate_kg_s;
  const double behind_kg = nominal * report_.active_time_s - report_.inserted_mass_kg;
  if (!(behind_kg > nominal * interval_)) return "";
  std::ostringstream os;
  os << std::setprecision(3) << "factory '" << spec_.name << "' fell behind its nominal rate: "
     << report_.inserted_mass_kg << " kg in " << report_.active_time_s << " s, "
     << report_.AchievedRate() << " kg/s against a nominal " << nominal << " kg/s; "
     << report_.full_batches
     << " batch(es) found the region full (it cannot hold a batch's particles at random "
        "positions";
  if (!carried_.empty()) os << "; " << carried_.size() << " draw(s) wait for room";
  os << "): enlarge the region, raise the entry speed (velocity_m_s) or lower the rate";
  return os.str();
}

InsertionRegion ParticleFactory::RegionAt(double time_s) const {
  const double moving_s = std::clamp(time_s, spec_.start_s, spec_.end_s) - spec_.start_s;
  const Vec3 shift = spec_.region_velocity_m_s * moving_s + Vec3{0, 0, report_.region_lift_m};
  InsertionRegion r = spec_.region;
  r.min_m = r.min_m + shift;
  r.max_m = r.max_m + shift;
  r.axis_point_m = r.axis_point_m + shift;
  return r;
}

double ParticleFactory::HeapTop(const Particles& p, const InsertionRegion& region) const {
  const double ceiling = region.min_m.z - 0.5 * spec_.follow_heap_clearance_m;
  const double v2 = spec_.settled_speed_m_s * spec_.settled_speed_m_s;
  constexpr double kLow = -std::numeric_limits<double>::infinity();
  double top[3] = {kLow, kLow, kLow};  // the three highest, descending
  for (size_t i = 0; i < p.Size(); ++i) {
    const Vec3& x = p.position_m[i];
    if (x.z >= ceiling || x.x < region.min_m.x || x.x > region.max_m.x ||
        x.y < region.min_m.y || x.y > region.max_m.y || Norm2(p.velocity_m_s[i]) >= v2)
      continue;
    double h = x.z + p.radius_m[i];
    for (double& t : top)
      if (h > t) std::swap(h, t);
  }
  return top[2];
}

}  // namespace demcal::core
