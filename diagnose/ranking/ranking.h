#pragma once
// RankCandidates: orders the candidate effects by evidence (evidence.h) and names the winner.
// Control guard: a control (a copy of a fitted base parameter, such as the sliding-friction
// control when μs is fitted) never wins. When the best simulated candidate is a control, or a
// control is not told apart from the winner, there is no winner and control_first is set: an
// improvement a re-tuned fitted parameter gives equally is a model-form offset, not a missing
// effect. Otherwise a simulated runner-up not told apart from the winner is `tied`.
// A candidate can win only when its refit is significant (likelihood-ratio p below the
// significance AND ΔBIC < 0); among those the lowest ΔBIC wins. The refit of a candidate is the
// real one (simulated at the refitted point) when it was made, else the linearised one; only a
// refit that was simulated can win (a linear prediction is a shortlist, not evidence). When the
// runner-up is not told apart from the winner (ToldApart, evidence.h: within kBicIndistinct or
// within the refits' simulation noise) the two are not told apart and the ranking
// says so (`distinguished` false; only simulated refits are compared); the winner is still the
// lower ΔBIC. Laws of one mechanism: a runner-up not told apart from the winner that is another
// law of the winner's mechanism (JKR and sjkr adhesion) does not make a tie: the mechanism is
// what the diagnosis names, and both laws say it is there; it is `same_mechanism` instead, so
// the answer names the mechanism, the better-fitting law (the winner) and that the law is not
// told apart. Entries of different mechanisms (or none declared) tie as before.
//
//   Ranking r = RankCandidates(entries, 0.01);
//   if (r.winner >= 0) entries[r.winner].key ...
//
// Thread-safety: pure function.
#include <string>
#include <vector>

#include "diagnose/ranking/evidence.h"

namespace demcal::diagnose {

struct RankingEntry {
  int candidate = 0;  // index into the loop's candidates
  std::string key;
  std::string mechanism;       // the physical mechanism it is a law of; "": its own
  std::vector<double> values;  // refitted effect parameters
  double chi2_linear = 0;      // predicted by the linearised refit
  Evidence linear;
  bool simulated = false;      // the refit was simulated (DEM refit)
  double chi2 = 0;             // simulated when simulated, else chi2_linear
  Evidence evidence;           // from chi2
  double chi2_per_dof = 0;     // chi2 / (n − fitted − k)
  double signature_match = 0;  // linear_refit.h
  bool control = false;        // a copy of a fitted base parameter (CandidateEffect::control)
  std::vector<double> base_unit;  // the simulated refit's base parameters (unit cube); empty
                                  // for a linearised refit
  std::string note;            // e.g. "refit failed: ..." or "redundant with the fitted parameters"
};

struct Ranking {
  std::vector<int> order;  // entry indices, best (lowest ΔBIC) first
  int winner = -1;         // entry index, −1: none significant (or the control guard held)
  bool distinguished = true;
  int tied = -1;               // an entry not told apart from the winner (−1: none)
  int same_mechanism = -1;     // another law of the winner's mechanism, not told apart from it
  bool control_first = false;  // the control ranked first, or level with the winner: no effect
  int set_aside = -1;          // the winner the control guard set aside (−1: none)
  std::string message;
};

// Two effects are laws of one mechanism when both declare it ("" declares none: its own).
bool SameMechanism(const std::string& a, const std::string& b);
inline bool SameMechanism(const RankingEntry& a, const RankingEntry& b) {
  return SameMechanism(a.mechanism, b.mechanism);
}

Ranking RankCandidates(const std::vector<RankingEntry>& entries);

// The entry whose own test a step's answer rests on: the winner, else the best simulated entry,
// else the best linearised one (−1: no entries). The screen without a gap reports its p
// (diagnosis.h step 2).
int DecidingEntry(const Ranking& r, const std::vector<RankingEntry>& entries);

}  // namespace demcal::diagnose
