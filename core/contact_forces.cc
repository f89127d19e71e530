#include "core/contact_forces.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>

#include "core/contact/contact_kernel.h"

namespace demcal::core {

template <class Rolling>
void ContactForces::ComputePairs(const Particles& p, const NeighbourList& list,
                                 const InteractionTable& table, const Rolling& rolling,
                                 double dt) {
  const size_t n = p.Size();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      const Vec3 xi = p.position_m[i];
      const double ri = p.radius_m[i];
      for (uint32_t k = list.RowBegin(i); k < list.RowEnd(i); ++k) {
        const uint32_t j = list.Partner(k);
        const Vec3 d = xi - p.position_m[j];
        const double rsum = ri + p.radius_m[j];
        const double dist2 = Norm2(d);
        if (dist2 >= rsum * rsum) {
          if (pair_active_[k]) pair_history_[k] = ContactHistory{}, pair_active_[k] = 0;
          continue;
        }
        const double dist = std::sqrt(dist2);
        ContactGeometry g;
        g.normal = d * (1.0 / dist);
        g.overlap_m = rsum - dist;
        g.radius_i_m = ri;
        g.radius_j_m = p.radius_m[j];
        g.effective_radius_m = ri * g.radius_j_m / rsum;
        g.mass_i_kg = p.mass_kg[i];
        g.mass_j_kg = p.mass_kg[j];
        g.effective_mass_kg = g.mass_i_kg * g.mass_j_kg / (g.mass_i_kg + g.mass_j_kg);
        g.omega_i = p.angular_velocity_rad_s[i];
        g.omega_j = p.angular_velocity_rad_s[j];
        g.relative_velocity_m_s = p.velocity_m_s[i] - p.velocity_m_s[j] -
                                  Cross(ri * g.omega_i + g.radius_j_m * g.omega_j, g.normal);
        const ResolvedPair& pair = table.Get(p.material[i], p.material[j]);
        pair_result_[k] = EvaluateContact(g, pair, dt, rolling, pair_history_[k]);
        pair_active_[k] = 1;
      }
    }
  });
}

template <class Rolling>
void ContactForces::Gather(Particles& p, const NeighbourList& list,
                           const std::vector<PlaneWall>& walls, const InteractionTable& table,
                           const Rolling& rolling, const Vec3& gravity, double dt) {
  const size_t n = p.Size();
  const size_t nw = walls.size();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      Vec3 f = gravity * p.mass_kg[i];
      Vec3 t;
      for (uint32_t k = list.RowBegin(i); k < list.RowEnd(i); ++k) {
        if (!pair_active_[k]) continue;
        f += pair_result_[k].force_i;
        t += pair_result_[k].torque_i;
      }
      for (uint32_t r = list.ReverseBegin(i); r < list.ReverseEnd(i); ++r) {
        const uint32_t k = list.ReverseEntry(r);
        if (!pair_active_[k]) continue;
        f -= pair_result_[k].force_i;
        t += pair_result_[k].torque_j;
      }
      for (size_t w = 0; w < nw; ++w) {
        const PlaneWall& wall = walls[w];
        const size_t slot = i * nw + w;
        const double ri = p.radius_m[i];
        const double overlap = ri - Dot(p.position_m[i] - wall.point_m, wall.normal);
        if (overlap <= 0) {
          if (wall_active_[slot]) wall_history_[slot] = ContactHistory{}, wall_active_[slot] = 0;
          continue;
        }
        ContactGeometry g;
        g.normal = wall.normal;
        g.overlap_m = overlap;
        g.radius_i_m = ri;
        g.radius_j_m = 0;
        g.effective_radius_m = ri;
        g.mass_i_kg = g.effective_mass_kg = p.mass_kg[i];
        g.mass_j_kg = 0;
        g.omega_i = p.angular_velocity_rad_s[i];
        g.relative_velocity_m_s =
            p.velocity_m_s[i] - wall.velocity_m_s - Cross(ri * g.omega_i, g.normal);
        const ContactResult c = EvaluateContact(g, table.Get(p.material[i], wall.material), dt,
                                                rolling, wall_history_[slot]);
        wall_active_[slot] = 1;
        f += c.force_i;
        t += c.torque_i;
      }
      p.force_N[i] = f;
      p.torque_N_m[i] = t;
    }
  });
}

void ContactForces::Compute(Particles& p, const NeighbourList& list,
                            const std::vector<PlaneWall>& walls, const InteractionTable& table,
                            const RollingModel& rolling, const Vec3& gravity, double dt) {
  if (pair_history_.size() != list.PairCount()) {
    pair_history_.resize(list.PairCount());
    pair_active_.resize(list.PairCount(), 0);
  }
  pair_result_.resize(list.PairCount());
  if (wall_history_.size() != p.Size() * walls.size()) {
    wall_history_.resize(p.Size() * walls.size());
    wall_active_.resize(p.Size() * walls.size(), 0);
  }
  std::visit(
      [&](const auto& model) {
        ComputePairs(p, list, table, model, dt);
        Gather(p, list, walls, table, model, gravity, dt);
      },
      rolling);
}

void ContactForces::Remap(const NeighbourList& old_list, const NeighbourList& new_list,
                          const std::vector<uint32_t>& order, size_t wall_count) {
  const size_t n = new_list.RowsCount();
  auto old_slot = [&](uint32_t s) { return order.empty() ? s : order[s]; };
  std::vector<ContactHistory> history(new_list.PairCount());
  std::vector<uint8_t> active(new_list.PairCount(), 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      for (uint32_t k = new_list.RowBegin(i); k < new_list.RowEnd(i); ++k) {
        const uint32_t a = old_slot(i), b = old_slot(new_list.Partner(k));
        const int64_t e = old_list.Find(std::min(a, b), std::max(a, b));
        if (e < 0 || !pair_active_[e]) continue;
        history[k] = pair_history_[e];
        active[k] = 1;
        if (a > b) {  // i and j swapped roles: the relative displacement changes sign
          history[k].shear_m = -history[k].shear_m;
          history[k].rolling_torque_N_m = -history[k].rolling_torque_N_m;
        }
      }
    }
  });
  pair_history_.swap(history);
  pair_active_.swap(active);
  if (!order.empty() && wall_count > 0 && wall_history_.size() == order.size() * wall_count) {
    std::vector<ContactHistory> walls(order.size() * wall_count);
    std::vector<uint8_t> wall_on(order.size() * wall_count, 0);
    for (size_t s = 0; s < order.size(); ++s) {
      for (size_t w = 0; w < wall_count; ++w) {
        walls[s * wall_count + w] = wall_history_[order[s] * wall_count + w];
        wall_on[s * wall_count + w] = wall_active_[order[s] * wall_count + w];
      }
    }
    wall_history_.swap(walls);
    wall_active_.swap(wall_on);
  }
}

size_t ContactForces::ActiveContacts() const {
  return std::accumulate(pair_active_.begin(), pair_active_.end(), size_t{0}) +
         std::accumulate(wall_active_.begin(), wall_active_.end(), size_t{0});
}

}  // namespace demcal::core
