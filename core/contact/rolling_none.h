#pragma once
// Rolling slot "none": no rolling resistance (the pure Hertz–Mindlin sphere).
#include "core/contact/contact_state.h"

namespace demcal::core {

struct RollingNone {
  static constexpr const char* kName = "none";
  void Apply(const ContactGeometry&, const ResolvedPair&, const NormalForce&, double,
             ContactHistory&, ContactResult&) const {}
};

}  // namespace demcal::core
