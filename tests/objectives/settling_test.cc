#include "objectives/settling.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace demcal::objectives;

TEST_CASE("settling: mass-weighted specific kinetic energy against the threshold", "[unit]") {
  Snapshot snap;
  // 1 kg at rest and 3 kg at 0.02 m/s: ½·3·0.0004 / 4 = 1.5e-4 J/kg.
  snap.grains = {{.velocity_m_s = {0, 0, 0}, .mass_kg = 1},
                 {.velocity_m_s = {0, 0.02, 0}, .mass_kg = 3}};
  CHECK(MeanSpecificKineticEnergy(snap) == Approx(1.5e-4).epsilon(1e-12));
  CHECK(IsSettled(snap, 2e-4));
  CHECK_FALSE(IsSettled(snap, 1e-4));
  snap.grains[0].velocity_m_s.x = std::nan("");
  CHECK_FALSE(IsSettled(snap, 1.0));        // a blown-up state never counts as settled
  CHECK_FALSE(IsSettled(Snapshot{}, 1.0));  // no heap yet
  CHECK(MeanSpecificKineticEnergy(Snapshot{}) == 0);
}
