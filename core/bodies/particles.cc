#include "core/bodies/particles.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <functional>
#include <numbers>

namespace demcal::core {

size_t Particles::Add(int64_t particle_id, int species_index, int material_index, double radius,
                      double density, const Vec3& position, const Vec3& velocity,
                      const Vec3& omega) {
  const double mass = density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  position_m.push_back(position);
  velocity_m_s.push_back(velocity);
  angular_velocity_rad_s.push_back(omega);
  force_N.push_back({});
  torque_N_m.push_back({});
  radius_m.push_back(radius);
  mass_kg.push_back(mass);
  inv_mass.push_back(1.0 / mass);
  inv_inertia.push_back(1.0 / (0.4 * mass * radius * radius));
  species.push_back(species_index);
  material.push_back(material_index);
  body.push_back(-1);
  id.push_back(particle_id);
  return position_m.size() - 1;
}

namespace {
template <typename T>
void ApplyOrder(std::vector<T>& v, const std::vector<uint32_t>& order) {
  std::vector<T> out(order.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, order.size(), 4096), [&](const auto& range) {
    for (size_t k = range.begin(); k != range.end(); ++k) out[k] = v[order[k]];
  });
  v.swap(out);
}
}  // namespace

void Particles::Permute(const std::vector<uint32_t>& order) {
  ApplyOrder(position_m, order);
  ApplyOrder(velocity_m_s, order);
  ApplyOrder(angular_velocity_rad_s, order);
  ApplyOrder(force_N, order);
  ApplyOrder(torque_N_m, order);
  ApplyOrder(radius_m, order);
  ApplyOrder(mass_kg, order);
  ApplyOrder(inv_mass, order);
  ApplyOrder(inv_inertia, order);
  ApplyOrder(species, order);
  ApplyOrder(material, order);
  ApplyOrder(body, order);
  ApplyOrder(id, order);
}

size_t Particles::CountMoving(size_t first, size_t last) const {
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(first, std::max(first, last), 4096), size_t{0},
      [&](const auto& range, size_t moving) {
        for (size_t i = range.begin(); i != range.end(); ++i) moving += !IsFixed(i);
        return moving;
      },
      std::plus<size_t>());
}

double Particles::FreeKineticEnergy(size_t i) const {
  if (body[i] >= 0 || inv_mass[i] == 0) return 0;  // clump member, or fixed
  return 0.5 * mass_kg[i] * Norm2(velocity_m_s[i]) +
         0.5 / inv_inertia[i] * Norm2(angular_velocity_rad_s[i]);
}

double Particles::KineticEnergy() const {
  double e = 0;
  for (size_t i = 0; i < Size(); ++i) e += FreeKineticEnergy(i);
  return e;
}

void Particles::Fix(size_t i) {
  velocity_m_s[i] = {};
  angular_velocity_rad_s[i] = {};
  inv_mass[i] = 0;
  inv_inertia[i] = 0;
  force_N[i] = {};
  torque_N_m[i] = {};
}

}  // namespace demcal::core
