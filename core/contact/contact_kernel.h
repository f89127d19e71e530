#pragma once
#include <algorithm>

// One contact evaluation: the normal, tangential and rolling slots composed. Templated on the
// normal and rolling models so the force loop is instantiated once per combination (no
// per-contact dispatch).
#include "core/contact/contact_state.h"
#include "core/contact/hertz_mindlin.h"
#include "core/contact/jkr.h"
#include "core/contact/mindlin_tangential.h"
#include "core/contact/rolling_model.h"

namespace demcal::core {

// A complete contact law: a normal model type (HertzMindlinNormal or JkrNormal) and a rolling
// model value. Contact forces are instantiated once per ContactModel type.
template <class NormalModel, class RollingModelT>
struct ContactModel {
  using Normal = NormalModel;
  RollingModelT rolling;
  JkrRollingLoad jkr_rolling_load = JkrRollingLoad::kNet;  // used with an adhesive normal model

  // Whether a pair at this overlap is in contact. Without adhesion: when pressed (δ > 0). With
  // JKR: a new contact forms at δ > 0 and an existing one survives until δ <= −BreakGap.
  DEMCAL_HOT_INLINE static bool InContact(double overlap, bool was_in_contact, double r_eff, const ResolvedPair& p) {
    if (overlap > 0) return true;
    if constexpr (Normal::kAdhesive) {
      return was_in_contact && p.interfacial_energy_J_m2 > 0 &&
             Normal::Holds(-overlap, r_eff, p.effective_youngs_Pa, p.interfacial_energy_J_m2);
    }
    return false;
  }

  DEMCAL_HOT_INLINE ContactResult Evaluate(const ContactGeometry& g, const ResolvedPair& p, double dt,
                         ContactHistory& h) const {
    NormalForce n = Normal::Compute(g, p, h);
    if constexpr (Normal::kAdhesive) {
      // Γ = 0 pairs: Hertz's elastic force, which is the rolling load already (δ > 0).
      if (jkr_rolling_load == JkrRollingLoad::kNet) n.rolling_load_N = std::max(0.0, n.elastic_N);
    }
    const Vec3 f_t = MindlinTangential::Compute(g, p, n, dt, h);
    ContactResult r{};
    r.force_i = n.total_N * g.normal + f_t;
    // Contact point at −R_i n from i and +R_j n from j: τ = r × F gives −R (n × F_t) for both.
    const Vec3 n_cross_ft = Cross(g.normal, f_t);
    r.torque_i = -g.radius_i_m * n_cross_ft;
    r.torque_j = -g.radius_j_m * n_cross_ft;
    rolling.Apply(g, p, n, dt, h, r);
    return r;
  }
};

}  // namespace demcal::core
