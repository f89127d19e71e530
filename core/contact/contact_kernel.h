#pragma once
// One contact evaluation: the normal, tangential and rolling slots composed. Templated on the
// rolling model so the force loop is instantiated once per model (no per-contact dispatch).
#include "core/contact/contact_state.h"
#include "core/contact/hertz_mindlin.h"
#include "core/contact/mindlin_tangential.h"

namespace demcal::core {

template <class Rolling>
inline ContactResult EvaluateContact(const ContactGeometry& g, const ResolvedPair& p, double dt,
                                     const Rolling& rolling, ContactHistory& h) {
  const NormalForce n = HertzMindlinNormal::Compute(g, p);
  const Vec3 f_t = MindlinTangential::Compute(g, p, n, dt, h);
  ContactResult r;
  r.force_i = n.total_N * g.normal + f_t;
  // Contact point at −R_i n from i and +R_j n from j: τ = r × F gives −R (n × F_t) for both.
  const Vec3 n_cross_ft = Cross(g.normal, f_t);
  r.torque_i = -g.radius_i_m * n_cross_ft;
  r.torque_j = -g.radius_j_m * n_cross_ft;
  rolling.Apply(g, p, n, dt, h, r);
  return r;
}

}  // namespace demcal::core
