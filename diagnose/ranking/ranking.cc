#include "diagnose/ranking/ranking.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace demcal::diagnose {

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
  if (r.winner < 0) {
    m << "no candidate effect improves the fit significantly";
    r.message = m.str();
    return r;
  }
  m << entries[r.winner].key << " (delta BIC " << entries[r.winner].evidence.delta_bic << ", likelihood-ratio p "
    << entries[r.winner].evidence.lr_p_value << ")";
  for (int i : r.order) {
    if (i == r.winner) continue;
    if (entries[i].simulated &&
        std::fabs(entries[i].evidence.delta_bic - entries[r.winner].evidence.delta_bic) < kBicIndistinct) {
      r.distinguished = false;
      m << "; not told apart from " << entries[i].key << " (delta BIC " << entries[i].evidence.delta_bic << ")";
    }
  }
  r.message = m.str();
  return r;
}

}  // namespace demcal::diagnose
