#pragma once
// Rolling slot "epsd" / "epsd2": elastic–plastic spring–dashpot rolling resistance (Ai et al.
// 2011 type C; EDEM "Type C"; LIGGGHTS rolling_model_epsd(2).h; docs/physics.md §2.2).
//   ω_t = (ω_i − ω_j) without its normal component;  M_k += k_r ω_t dt (kept in the tangent
//   plane);  |M_k| ≤ μ_r R* F_n (full mobilisation: capped, no damping);
//   otherwise M = M_k + C_r ω_t.   Torque: τ_i −= M, τ_j += M.
// Variants (choose with the factory functions):
//   Epsd():  k_r = 2.25 k_n μ_r² R*² (k_n Hertz secant), C_r = η_r 2 sqrt(I_r k_r), η_r = 0.3;
//   Epsd2(): k_r = S_t R*² (Iwashita & Oda 1998), no viscous term (Wensrich & Katterfeld 2012).
// A sphere on an incline therefore rests iff tan θ ≤ μ_r.
#include <cmath>

#include "core/contact/contact_state.h"

namespace demcal::core {

struct RollingEpsd {
  const char* name = "epsd";
  bool tangential_stiffness_rule = false;  // true: epsd2 (k_r = S_t R*²)
  double damping_ratio = 0.3;              // η_r; 0 disables the dashpot

  static RollingEpsd Epsd(double damping_ratio = 0.3) { return {"epsd", false, damping_ratio}; }
  static RollingEpsd Epsd2() { return {"epsd2", true, 0.0}; }

  DEMCAL_HOT_INLINE void Apply(const ContactGeometry& g, const ResolvedPair& p, const NormalForce& n, double dt,
             ContactHistory& h, ContactResult& r) const {
    const double mu_r = p.rolling_friction;
    if (mu_r <= 0) return;
    const double r_eff = g.effective_radius_m;
    Vec3 w = g.omega_i - g.omega_j;
    w -= Dot(w, g.normal) * g.normal;
    const double k_r = tangential_stiffness_rule
                           ? 8.0 * p.effective_shear_Pa * n.contact_radius_m * r_eff * r_eff
                           : 2.25 * n.secant_kn * mu_r * mu_r * r_eff * r_eff;
    Vec3& m_k = h.rolling_torque_N_m;
    m_k -= Dot(m_k, g.normal) * g.normal;
    m_k += w * (k_r * dt);
    const double m_max = mu_r * r_eff * n.rolling_load_N;
    Vec3 torque = m_k;
    const double m2 = Norm2(m_k);
    if (m2 > m_max * m_max) {
      m_k *= m_max / std::sqrt(m2);
      torque = m_k;
    } else if (damping_ratio > 0) {
      torque += w * (damping_ratio * 2.0 * std::sqrt(RollingInertia(g) * k_r));
    }
    r.torque_i -= torque;
    r.torque_j += torque;
  }

 private:
  // LIGGGHTS' I_r: 1.4 (m_i R_i²)(m_j R_j²)/(m_i R_i² + m_j R_j²); wall: 1.4 m_i R_i².
  static double RollingInertia(const ContactGeometry& g) {
    const double a = g.mass_i_kg * g.radius_i_m * g.radius_i_m;
    if (g.mass_j_kg <= 0) return 1.4 * a;
    const double b = g.mass_j_kg * g.radius_j_m * g.radius_j_m;
    return 1.4 * a * b / (a + b);
  }
};

}  // namespace demcal::core
