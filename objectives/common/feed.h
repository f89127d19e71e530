#pragma once
// Feed: what an experiment pours — species with mass fractions — and the factory that pours it
// at a mass rate from a region above the test (the outlet of a funnel or a feeder).
#include <string>
#include <vector>

#include "core/insertion/factory.h"
#include "core/scene/scene.h"
#include "core/simulation/simulation.h"

namespace demcal::objectives {

struct FeedComponent {
  int species = 0;           // index into the model's species
  double mass_fraction = 1;  // of the feed; the fractions of a feed sum to 1
};

struct Feed {
  std::vector<FeedComponent> components;
  double mass_kg = 0;          // total mass poured, > 0
  double mass_rate_kg_s = 0;   // > 0
  double start_s = 0;
  core::Vec3 velocity_m_s;     // initial velocity of the poured particles; zero: automatic
                               // (see MakeFeedFactory)
  double DurationS() const { return mass_kg / mass_rate_kg_s; }
  double EndS() const { return start_s + DurationS(); }  // the pour has finished by then
  // Checks fractions (sum 1 within 1e-6), species indices, mass and rate; `path` prefixes the
  // field names in the message (e.g. "aor.feed").
  bool IsValid(const core::Scene& model, const std::string& path, std::string* error) const;
};

// The factory pouring `feed` from `region`. A feed without a velocity enters downwards at the
// lowest speed (see FeedEntrySpeed) at which each batch fills at most 20% of the region, so the
// random insertion finds room: the stream leaves the feeder like a loose rain.
core::FactorySpec MakeFeedFactory(const core::Scene& model, const Feed& feed,
                                  const core::InsertionRegion& region);

// Whether the feed's factory (MakeFeedFactory, named "feed") has inserted the feed's whole mass;
// true when the scene has no such factory.
bool FeedInserted(const core::Simulation& sim, const Feed& feed);

// How long the feed took to insert its mass: its nominal mass / rate, or, when its factory could
// not insert as fast (large clumps in a small region: it inserts what fits and owes the rest),
// `inserted_at_s` − start. `inserted_at_s`: the first check of the run at which FeedInserted
// held (< 0: never); a feed inserted within `check_interval_s` of its nominal end kept up.
double FeedTookS(const Feed& feed, double inserted_at_s, double check_interval_s);

// Downward speed (m/s, >= 0) for which a batch (the region's fall-through time) of the feed
// occupies at most `solid_fraction` of the region under gravity g.
double FeedEntrySpeed(const core::Scene& model, const Feed& feed,
                      const core::InsertionRegion& region, double solid_fraction, double g_m_s2);

// Largest particle diameter among the feed's species (after fidelity scaling).
double FeedMaxDiameter(const core::Scene& model, const Feed& feed);
double FeedMinDiameter(const core::Scene& model, const Feed& feed);
// Largest enclosing diameter among the feed's grains: twice the radius of the smallest sphere
// about a grain's centre of mass that holds it (core::ClumpTemplate::BoundingRadius). For a
// sphere its diameter; for an elongated clump about its length, which sets how much room the
// grain needs where it is placed and at an orifice.
double FeedMaxEnclosingDiameter(const core::Scene& model, const Feed& feed);
// Largest mean caliper diameter among the feed's grains (core/bodies/clump_size.h): the size of
// a tumbling grain averaged over orientations; a sphere's diameter.
double FeedMaxMeanCaliperDiameter(const core::Scene& model, const Feed& feed);

}  // namespace demcal::objectives
