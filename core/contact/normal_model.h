#pragma once
// Registry of normal contact laws: the normal slot, which also carries a law's adhesion (JKR's
// attraction is a term of its one force law F(a), so it cannot sit in a slot of its own).
// Adding a law = one header with the members HertzMindlinNormal (hertz_mindlin.h) lists and
// documents, and one alternative in NormalModel below; everything else asks this registry.
//
// The law is chosen once per run from the pair table (SelectNormalModel: the last law in
// registry order that some pair calls for, else the first; JKR when any pair has Γ > 0, sjkr
// when any pair has k > 0, with the other pairs reducing exactly to Hertz–Mindlin inside it),
// made with its options from the
// scene's contact_model section (MakeNormalModel), and dispatched once per force pass by
// std::visit around the contact loop (ContactForces::Compute), never per contact. One law runs a
// scene, so a pair table that calls for two adhesive laws (JKR's Γ on one pair, sjkr's k on
// another) is refused by the scene's validation (NormalLawsCalledFor), not run with one of them
// silently dropped: each law's loop is instantiated without the other's term, which keeps the
// loop of the scenes without adhesion exactly what it was.
#include <cstddef>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/contact/hertz_mindlin.h"
#include "core/contact/jkr.h"
#include "core/contact/rolling_model.h"
#include "core/contact/sjkr.h"
#include "core/materials/interaction_table.h"

namespace demcal::core {

using NormalModel = std::variant<HertzMindlinNormal, JkrNormal, SjkrNormal>;

namespace normal_model_detail {
template <class F>
void ForEachLaw(F&& f) {
  [&]<size_t... k>(std::index_sequence<k...>) {
    (f(std::integral_constant<size_t, k>{}), ...);
  }(std::make_index_sequence<std::variant_size_v<NormalModel>>{});
}
template <size_t k>
using Law = std::variant_alternative_t<k, NormalModel>;
}  // namespace normal_model_detail

// The laws' names, in registry order.
inline const std::vector<std::string>& NormalModelNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    normal_model_detail::ForEachLaw(
        [&](auto k) { n.emplace_back(normal_model_detail::Law<k()>::kName); });
    return n;
  }();
  return names;
}

// For each law of the registry that some pair calls for, the index of the first such pair in
// `pairs` (in registry order); more than one entry means the table mixes laws, which no scene may.
inline std::vector<std::pair<std::string, size_t>> NormalLawsCalledFor(
    const std::vector<PairParameters>& pairs) {
  std::vector<std::pair<std::string, size_t>> called;
  normal_model_detail::ForEachLaw([&](auto k) {
    using Law = normal_model_detail::Law<k()>;
    for (size_t i = 0; i < pairs.size(); ++i)
      if (Law::CalledFor(pairs[i])) {
        called.emplace_back(Law::kName, i);
        return;
      }
  });
  return called;
}

// The law the pair table calls for, with its options at their defaults.
inline NormalModel SelectNormalModel(const std::vector<PairParameters>& pairs) {
  NormalModel chosen;
  normal_model_detail::ForEachLaw([&](auto k) {
    using Law = normal_model_detail::Law<k()>;
    for (const PairParameters& p : pairs)
      if (Law::CalledFor(p)) {
        chosen.template emplace<k()>();
        return;
      }
  });
  return chosen;
}

// The law the pair table calls for, made with its options from the scene's contact_model
// section. False (and `model` untouched) if an option is not one the law knows.
inline bool MakeNormalModel(const std::vector<PairParameters>& pairs,
                            const RollingModelSpec& contact_model, NormalModel* model) {
  return std::visit(
      [&](auto selected) {
        if (!decltype(selected)::Make(contact_model, &selected)) return false;
        *model = selected;
        return true;
      },
      SelectNormalModel(pairs));
}

inline std::string NormalModelName(const NormalModel& model) {
  return std::visit([](const auto& law) { return std::string(law.kName); }, model);
}

// Every law's constants derived from a pair (Resolve), filled in once at setup.
inline void ResolveNormalModelConstants(ResolvedPair& pair) {
  normal_model_detail::ForEachLaw([&](auto k) { normal_model_detail::Law<k()>::Resolve(pair); });
}

}  // namespace demcal::core
