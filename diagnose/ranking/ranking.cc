#include "diagnose/ranking/ranking.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace demcal::diagnose {

bool SameMechanism(const std::string& a, const std::string& b) { return !a.empty() && a == b; }

Ranking RankCandidates(const std::vector<RankingEntry>& entries) {
  Ranking r;
  r.order.resize(entries.size());
  std::iota(r.order.begin(), r.order.end(), 0);
  std::stable_sort(r.order.begin(), r.order.end(), [&entries](int a, int b) {
    return entries[a].evidence.delta_bic < entries[b].evidence.delta_bic;
  });
  for (int i : r.order)
    if (entries[i].simulated && entries[i].evidence.significant) {
      r.winner = i;
      break;
    }
  std::ostringstream m;
  m.precision(3);
  if (r.winner >= 0) {
    int first_simulated = -1, control_level = -1;
    for (int i : r.order)
      if (entries[i].simulated && first_simulated < 0) first_simulated = i;
    for (int i : r.order)
      if (i != r.winner && entries[i].simulated && entries[i].control &&
          !ToldApart(entries[i].evidence, entries[r.winner].evidence))
        control_level = i;
    const int control = entries[r.winner].control          ? r.winner
                        : entries[first_simulated].control ? first_simulated
                                                           : control_level;
    if (control >= 0) {
      r.control_first = true;
      r.set_aside = r.winner;
      m << "the control " << entries[control].key
        << " (a copy of a fitted parameter) explains the gap as well as "
        << "any effect (delta BIC " << entries[control].evidence.delta_bic
        << "): model-form offset, no missing "
        << "effect named";
      r.winner = -1;
      r.message = m.str();
      return r;
    }
  }
  if (r.winner < 0) {
    m << "no candidate effect improves the fit significantly";
    r.message = m.str();
    return r;
  }
  m << entries[r.winner].key << " (delta BIC " << entries[r.winner].evidence.delta_bic
    << ", likelihood-ratio p " << entries[r.winner].evidence.lr_p_value << ")";
  for (int i : r.order) {
    if (i == r.winner) continue;
    if (!entries[i].simulated || ToldApart(entries[i].evidence, entries[r.winner].evidence))
      continue;
    if (SameMechanism(entries[i], entries[r.winner])) {
      if (r.same_mechanism < 0) r.same_mechanism = i;
      m << "; law not told apart from " << entries[i].key << " (same mechanism, "
        << entries[i].mechanism << "; delta BIC " << entries[i].evidence.delta_bic << ")";
      continue;
    }
    r.distinguished = false;
    if (r.tied < 0) r.tied = i;
    m << "; not told apart from " << entries[i].key << " (delta BIC "
      << entries[i].evidence.delta_bic << ")";
  }
  r.message = m.str();
  return r;
}

int DecidingEntry(const Ranking& r, const std::vector<RankingEntry>& entries) {
  if (r.winner >= 0) return r.winner;
  for (int i : r.order)
    if (entries[i].simulated) return i;
  return r.order.empty() ? -1 : r.order.front();
}

}  // namespace demcal::diagnose
