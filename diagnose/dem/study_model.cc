#include "diagnose/dem/study_model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <sstream>

#include "calibrate/calibration.h"
#include "calibrate/response_surface.h"
#include "core/math/fnv1a.h"
#include "diagnose/dem/shared_run_groups.h"
#include "objectives/farm/farm.h"

namespace demcal::diagnose {
namespace {

std::string Hex(const std::string& text) {
  std::ostringstream hex;
  hex << std::hex << std::setw(16) << std::setfill('0') << std::hash<std::string>{}(text);
  return hex.str();
}

// The effects written into one group's model (after the parameters, before the fidelity).
struct EffectWriter {
  std::vector<std::pair<const Effect*, std::vector<double>>> effects;
  calibrate::Condition condition;
  EffectContext context;
  bool Apply(core::Scene* model, std::string* why) const {
    for (const auto& [effect, values] : effects)
      if (!effect->Apply(values, condition, context, model, why)) return false;
    return true;
  }
};

}  // namespace

StudyModel::StudyModel(const workflow::StudyFile& study, const std::vector<const Effect*>& effects,
                       const EffectContext& context, const StudyModelOptions& options)
    : study_(study), effects_(effects), context_(context), options_(options) {}

std::unique_ptr<StudyModel> StudyModel::Create(const workflow::StudyFile& study,
                                               const std::vector<const Effect*>& effects,
                                               const EffectContext& context,
                                               const StudyModelOptions& options,
                                               std::string* error) {
  std::unique_ptr<StudyModel> m(new StudyModel(study, effects, context, options));
  if (!workflow::BuildStudyRuns(study, options.quick, 0, &m->runs_, error)) return nullptr;
  m->replicates_ = study.replicates > 0 ? study.replicates : study.experiment().replicates;
  m->seed_ = study.has_seed ? study.seed : study.experiment().seed;
  m->pool_ = ReplicatePool(study.targets.size());
  std::error_code ec;
  if (objectives::farm::IsManager())
    std::filesystem::create_directories(options.out_dir + "/journal", ec);
  if (ec)
    return *error = "--out: cannot create '" + options.out_dir + "/journal': " + ec.message(),
           nullptr;
  return m;
}

std::vector<Observation> StudyModel::Observations() const {
  std::vector<Observation> out;
  for (const workflow::StudyTarget& t : study_.targets) {
    out.push_back(
        {t.target.name, t.target.observable, t.condition, t.target.value, t.target.uncertainty});
    out.back().repeats = t.repeats;
    if (t.experiment >= 0 && t.experiment < static_cast<int>(study_.experiments.size()))
      out.back().experiment =
          std::filesystem::path(study_.experiments[t.experiment].path).filename().string();
  }
  return out;
}

std::string StudyModel::DescribeEffects(const std::vector<ActiveEffect>& effects) const {
  std::ostringstream s;
  s.precision(17);
  for (const ActiveEffect& a : effects) {
    const std::vector<EffectParameter> p = effects_[a.candidate]->Parameters(context_);
    s << (s.tellp() > 0 ? " + " : "") << effects_[a.candidate]->Key() << "(";
    for (size_t k = 0; k < a.values.size() && k < p.size(); ++k)
      s << (k ? ", " : "") << p[k].name << "=" << a.values[k];
    s << ")";
  }
  return s.str();
}

StudyModel::Setting* StudyModel::SettingFor(const std::vector<ActiveEffect>& effects,
                                            std::string* error) {
  const std::string key = DescribeEffects(effects);
  auto found = settings_.find(key);
  if (found != settings_.end()) return &found->second;
  Setting& s = settings_[key];
  std::vector<calibrate::RunGroup> groups = runs_.groups;
  for (calibrate::RunGroup& g : groups) {
    EffectWriter writer{{}, g.condition, context_};
    for (const ActiveEffect& a : effects)
      writer.effects.push_back({effects_[a.candidate], a.values});
    core::Scene probe = g.model;  // the effects must apply to every group's model
    if (!writer.Apply(&probe, &s.invalid)) break;
    auto fidelity = g.prepare;
    g.prepare = [writer, fidelity](core::Scene* m) {
      std::string ignored;  // checked above on the same model
      writer.Apply(m, &ignored);
      if (fidelity) fidelity(m);
    };
  }
  s.bindings = runs_.bindings;
  if (s.invalid.empty()) {
    MergedRunGroups merged = MergeSharedRunGroups(groups, runs_.bindings, study_.space);
    groups = std::move(merged.groups);
    s.bindings = std::move(merged.bindings);
    s.merged_groups = merged.merged;
    if (options_.log && merged.merged > 0)
      *options_.log << "diagnose:   " << (key.empty() ? "base" : key) << ": " << merged.merged
                    << " of " << runs_.groups.size() << " run groups share another's scene"
                    << " (a condition not in this model): run once\n"
                    << std::flush;
  }
  const std::string path =
      options_.out_dir + (key.empty() ? "/journal/base.jsonl" : "/journal/" + Hex(key) + ".jsonl");
  s.journal = std::make_unique<calibrate::EvaluationJournal>();
  s.journal->ExpectSeeds(seed_);
  // The other ranks of an MPI farm read the journal; rank 0 appends once all have read it.
  if (!s.journal->Open(path, runs_.fingerprint + "|effects:" + key, error, study_.space.Size(),
                       !objectives::farm::IsManager())) {
    if (s.journal->io_error() && journal_error_.empty()) journal_error_ = *error;
    settings_.erase(key);
    return nullptr;
  }
  core::Fnv1a64 loaded;
  loaded.Text(path), loaded.Field(s.journal->LoadedRecords());
  objectives::farm::Rendezvous(loaded.digest());
  s.evaluator = std::make_unique<calibrate::TargetEvaluator>(
      study_.space, std::move(groups), s.bindings,
      calibrate::TargetEvaluatorOptions{
          .replicates = replicates_, .seed = seed_, .workers = options_.threads},
      s.journal.get());
  return &s;
}

void StudyModel::Pool(Setting* s) {
  const auto& history = s->evaluator->history();
  const size_t n = std::min(s->bindings.size(), study_.targets.size());
  for (; s->pooled < history.size(); ++s->pooled) {
    std::vector<std::vector<double>> values(n);
    std::vector<int> group(n, -1);
    for (size_t k = 0; k < n; ++k) {
      const calibrate::TargetBinding& b = s->bindings[k];
      group[k] = b.group;
      for (const calibrate::ReplicateRecord& r : history[s->pooled].runs[b.group]) {
        const auto it = r.values.find(b.observable);
        values[k].push_back(r.ok() && it != r.values.end() ? it->second : NAN);
      }
    }
    pool_.Add(values, group);
  }
}

Prediction StudyModel::Predict(const Setting& s, const calibrate::CandidateResult& result) const {
  Prediction p;
  p.ok = result.ok();
  p.status = result.status;
  const size_t n = std::min(result.targets.size(), study_.targets.size());
  for (size_t k = 0; k < n; ++k) {
    const calibrate::TargetValue& t = result.targets[k];
    const double pooled = pool_.Spread(k);
    const double spread = pooled >= 0 ? pooled : t.sem * std::sqrt(t.replicates);
    p.mean.push_back(t.mean);
    p.spread.push_back(spread);
    p.sem.push_back(t.replicates > 0 ? spread / std::sqrt(t.replicates) : t.sem);
  }
  p.source = BindingSources(s.bindings);
  p.source.resize(p.mean.size(), -1);  // a target without a binding: its own
  // Rows of one source read one value (1); rows of one run, different observables, its pooled
  // within-run correlation; rows of different runs none.
  p.correlation.assign(n, std::vector<double>(n, 0.0));
  for (size_t k = 0; k < n; ++k)
    for (size_t l = 0; l < n; ++l) {
      const bool same_group = k < s.bindings.size() && l < s.bindings.size() &&
                              s.bindings[k].group == s.bindings[l].group;
      p.correlation[k][l] = k == l || (p.source[k] >= 0 && p.source[k] == p.source[l]) ? 1.0
                            : same_group ? pool_.Correlation(k, l)
                                         : 0.0;
    }
  return p;
}

std::vector<Prediction> StudyModel::Evaluate(const std::vector<ModelPoint>& points) {
  std::vector<Prediction> out;
  for (const ModelPoint& point : points) {
    std::string error;
    Prediction p;
    if (!journal_error_.empty()) {  // nothing runs once the journal cannot be written
      p.status = "journal: " + journal_error_;
      out.push_back(p);
      continue;
    }
    Setting* s = SettingFor(point.effects, &error);
    if (!s) p.status = "journal: " + error;
    else if (!s->invalid.empty()) p.status = "effect not applicable: " + s->invalid;
    if (!s || !s->invalid.empty()) {
      out.push_back(p);
      continue;
    }
    const std::vector<calibrate::CandidateResult> r =
        s->evaluator->EvaluateBatch({study_.space.FromUnit(point.base_unit)});
    run_ += r[0].replicates_run;
    reused_ += r[0].replicates_reused;
    if (journal_error_.empty()) journal_error_ = r[0].journal_error;
    Pool(s);
    out.push_back(Predict(*s, r[0]));
    if (options_.log)
      *options_.log << "diagnose:   "
                    << (point.effects.empty() ? "base" : DescribeEffects(point.effects)) << ": "
                    << (out.back().ok ? "ok" : out.back().status) << " (" << r[0].replicates_run
                    << " runs, " << r[0].replicates_reused << " from journal)\n"
                    << std::flush;
  }
  return out;
}

}  // namespace demcal::diagnose
