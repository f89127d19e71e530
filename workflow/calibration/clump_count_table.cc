#include "workflow/calibration/clump_count_table.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "objectives/report/text_file.h"
#include "files/json_document.h"
#include "workflow/calibration/study_file.h"

namespace demcal::workflow {
namespace {

using Json = nlohmann::ordered_json;

Json Finite(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

double LargestNoise(const calibrate::TrialResult& t) {
  double largest = 0;
  for (double n : t.noise) largest = std::max(largest, n);
  return largest;
}

std::string CountList(const std::vector<int>& counts) {
  std::ostringstream out;
  for (size_t k = 0; k < counts.size(); ++k) out << (k ? ", " : "") << counts[k];
  return out.str();
}

}  // namespace

ClumpCountRow ClumpCountRowOf(int count, const calibrate::CalibrationSummary& s, double wall_per_run_s) {
  ClumpCountRow row{count, s.termination, NAN, false, false, NAN, wall_per_run_s, s.replicates_run};
  if (s.best >= 0) row.cost = s.candidates[s.best].trial.Cost(), row.within_noise = s.ok();
  for (const calibrate::Candidate& c : s.candidates) {
    if (!c.trial.WithinNoise() && !c.trial.Inconclusive()) continue;
    const double noise = LargestNoise(c.trial);
    if (!row.agrees || noise < row.agreeing_noise) row.agreeing_noise = noise;
    row.agrees = true;
  }
  return row;
}

ClumpCountVerdict JudgeClumpCounts(const std::vector<ClumpCountRow>& rows) {
  ClumpCountVerdict v;
  std::vector<int> agreeing, inconclusive_below;
  for (const ClumpCountRow& r : rows) {
    if (r.within_noise) v.matching.push_back(r.count);
    if (r.within_noise && v.chosen < 0) v.chosen = r.count;
    if (r.agrees || r.within_noise) agreeing.push_back(r.count);
  }
  for (const ClumpCountRow& r : rows)
    if (r.agrees && !r.within_noise && (v.chosen < 0 || r.count < v.chosen)) inconclusive_below.push_back(r.count);
  if (agreeing.size() > 1) v.not_told_apart = agreeing;
  std::ostringstream note;
  if (v.chosen > 0) note << "chose " << v.chosen << ", the smallest count that matches every target within noise";
  else note << "no count matched every target within noise";
  if (agreeing.size() > 1) note << "; counts " << CountList(agreeing) << " all agree with the data and are not told apart by these targets";
  else if (agreeing.size() == 1 && v.chosen > 0) note << "; every other count is excluded by the data";
  if (!inconclusive_below.empty())
    note << "; count(s) " << CountList(inconclusive_below)
         << " agree but only inconclusively (their simulations scatter more than the measurement uncertainty):"
            " more replicates or a less noisy target would decide";
  v.note = note.str();
  return v;
}

bool WriteClumpCountOutputs(const std::string& dir, const StudyFile& study, const std::vector<ClumpCountRow>& rows,
                            const ClumpCountVerdict& verdict, std::string* error) {
  Json list = Json::array();
  for (const ClumpCountRow& r : rows)
    list.push_back({{"count", r.count}, {"termination", calibrate::TerminationName(r.termination)}, {"cost", Finite(r.cost)},
                    {"within_noise", r.within_noise}, {"agrees", r.agrees},
                    {"agreeing_noise", Finite(r.agreeing_noise)}, {"replicate_runs", r.runs},
                    {"wall_per_run_s", r.wall_per_run_s}});
  const Json j{{"format", "demcal-clump-count/1"}, {"species", study.clump_count.species},
               {"semi_axes", {study.clump_count.semi_axes.x, study.clump_count.semi_axes.y,
                              study.clump_count.semi_axes.z}},
               {"chosen", verdict.chosen > 0 ? Json(verdict.chosen) : Json(nullptr)},
               {"matching", verdict.matching}, {"not_told_apart", verdict.not_told_apart},
               {"note", verdict.note}, {"counts", list}};
  if (!WriteJsonFile(dir + "/clump_count.json", j, error)) return false;
  return objectives::WriteTextFile(
      dir + "/clump_count.csv",
      [&](std::ostream& out) {
        out << "count,termination,cost,within_noise,agrees,agreeing_noise,replicate_runs,wall_per_run_s\n";
        for (const ClumpCountRow& r : rows)
          out << r.count << "," << calibrate::TerminationName(r.termination) << "," << r.cost << "," << (r.within_noise ? 1 : 0) << ","
              << (r.agrees ? 1 : 0) << "," << r.agreeing_noise << "," << r.runs << "," << r.wall_per_run_s << "\n";
      },
      error);
}

}  // namespace demcal::workflow
