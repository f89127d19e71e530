#pragma once
// One contact evaluation: the normal, tangential and rolling slots composed. Templated on the
// normal and rolling models so the force loop is instantiated once per combination (no
// per-contact dispatch).
#include "core/contact/contact_state.h"
#include "core/contact/mindlin_tangential.h"
#include "core/contact/normal_model.h"
#include "core/contact/rolling_model.h"

namespace demcal::core {

// A complete contact law: a normal law (an alternative of NormalModel, normal_model.h) and a
// rolling model, each a value with its options. Contact forces are instantiated once per
// ContactModel type.
template <class NormalLaw, class RollingModelT>
struct ContactModel {
  using Normal = NormalLaw;
  // Whether the rolling law reads ContactGeometry's rolling levers; only then are clump members'
  // levers computed (SetClumpLevers), so the other laws' clump scenes skip that work.
  static constexpr bool kReadsRollingLever =
      requires { requires RollingModelT::kReadsRollingLever; };
  Normal normal;
  RollingModelT rolling;

  // Whether a pair at this overlap is in contact: when pressed (δ > 0), or, for an adhesive law,
  // an existing contact stretched less than the law's break gap (Normal::Holds).
  DEMCAL_HOT_INLINE static bool InContact(double overlap, bool was_in_contact, double r_eff,
                                          const ResolvedPair& p) {
    if (overlap > 0) return true;
    if constexpr (Normal::kAdhesive) return was_in_contact && Normal::Holds(-overlap, r_eff, p);
    return false;
  }

  DEMCAL_HOT_INLINE ContactResult Evaluate(const ContactGeometry& g, const ResolvedPair& p,
                                           double dt, ContactHistory& h) const {
    const NormalForce n = normal.Force(g, p, h);
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
