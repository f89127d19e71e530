#include "files/duplicate_rows.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

namespace demcal::workflow {
namespace {

// A row split for sorting: everything compared exactly (observable, material, the condition
// columns, the word cells) in one string, the numeric cells in column order.
struct Keyed {
  std::string exact;
  std::vector<double> numbers;
};

Keyed KeyOf(const MeasurementRow& row) {
  Keyed k;
  // '\x1f' (unit separator) cannot occur in a CSV cell demcal reads as one line.
  k.exact = row.observable + '\x1f' + row.material;
  for (const auto& [column, cell] : row.conditions) {
    double x = 0;
    if (calibrate::ConditionNumber(row.conditions, column, &x)) {
      k.exact += '\x1f' + column + "\x1fn";
      k.numbers.push_back(x);
    } else {
      k.exact += '\x1f' + column + "\x1fw" + cell;
    }
  }
  return k;
}

// Two sorted neighbours a <= b may belong to one cluster of equal cells. SameConditionCell
// accepts |x - y| <= 1e-12 (1 + |x|); every gap between neighbours inside such a pair is at
// most |x - y|, and 1 + |x| <= (1 + max(|a|, |b|)) / (1 - 1e-12), so the factor 1 + 1e-9 keeps
// every equal pair in one cluster (it only adds candidates, which SameRowKey then rejects).
bool MayBeEqual(double a, double b) {
  return b - a <= 1e-12 * (1 + std::max(std::abs(a), std::abs(b))) * (1 + 1e-9);
}

using Best = std::optional<std::pair<size_t, size_t>>;

void Consider(size_t earlier, size_t later, Best* best) {
  if (!*best || later < (*best)->second || (later == (*best)->second && earlier < (*best)->first))
    *best = std::make_pair(earlier, later);
}

// Members agree in every exact part and lie within one cluster in each numeric column: compare
// in file order and keep the earliest later row that repeats an earlier one. Clusters are a
// handful of rows unless the table repeats itself, and then the first comparisons hit.
void CheckCluster(const std::vector<MeasurementRow>& rows, std::vector<size_t> members,
                  Best* best) {
  std::sort(members.begin(), members.end());
  for (size_t j = 1; j < members.size(); ++j)
    for (size_t i = 0; i < j; ++i)
      if (SameRowKey(rows[members[i]], rows[members[j]]))
        return Consider(members[i], members[j], best);
}

// Splits `members` into clusters along numeric column `column`, then the next, and so on.
void Split(const std::vector<MeasurementRow>& rows, const std::vector<Keyed>& keys,
           std::vector<size_t> members, size_t column, Best* best) {
  if (members.size() < 2) return;
  if (column == keys[members[0]].numbers.size())
    return CheckCluster(rows, std::move(members), best);
  auto value = [&](size_t m) { return keys[m].numbers[column]; };
  std::sort(members.begin(), members.end(),
            [&](size_t a, size_t b) { return value(a) < value(b); });
  size_t start = 0;
  for (size_t k = 1; k <= members.size(); ++k) {
    if (k < members.size() && MayBeEqual(value(members[k - 1]), value(members[k]))) continue;
    if (k - start > 1)
      Split(rows, keys, std::vector<size_t>(members.begin() + start, members.begin() + k),
            column + 1, best);
    start = k;
  }
}

}  // namespace

bool SameRowKey(const MeasurementRow& earlier, const MeasurementRow& later) {
  if (earlier.observable != later.observable || earlier.material != later.material ||
      earlier.conditions.size() != later.conditions.size())
    return false;
  for (const auto& [column, cell] : earlier.conditions) {
    auto it = later.conditions.find(column);
    if (it == later.conditions.end() || !calibrate::SameConditionCell(cell, it->second))
      return false;
  }
  return true;
}

std::optional<std::pair<size_t, size_t>> FirstDuplicateRow(
    const std::vector<MeasurementRow>& rows) {
  std::vector<Keyed> keys;
  keys.reserve(rows.size());
  std::unordered_map<std::string, std::vector<size_t>> groups;
  for (size_t k = 0; k < rows.size(); ++k) {
    keys.push_back(KeyOf(rows[k]));
    groups[keys.back().exact].push_back(k);
  }
  Best best;
  for (auto& [exact, members] : groups) Split(rows, keys, std::move(members), 0, &best);
  return best;
}

}  // namespace demcal::workflow
