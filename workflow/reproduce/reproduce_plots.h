#pragma once
// The pictures of the reproduce report, in the paper's figure styles, as SVG documents
// (objectives/report/svg_plot.h and svg_canvas.h): every one built from stage results, every one
// titled "SYNTHETIC" when it rests on synthetic data.
//   GammaCurveSvg       Fig. 6: Γ per coating level ± σ with the fitted curve and its 1σ band
//   AngleVsCoatingSvg   Fig. 7: repose angle vs coating level, measured ± u and simulated ± sem
//   SegregationBarsSvg  Figs. 10, 12, 13: CoV and S_n of the coated species per scenario ± sem
// Each returns "" when its stage has nothing to plot.
#include <nlohmann/json.hpp>
#include <string>

namespace demcal::workflow {

std::string GammaCurveSvg(const nlohmann::json& results);
std::string AngleVsCoatingSvg(const nlohmann::json& results, const std::string& material);
std::string SegregationBarsSvg(const nlohmann::json& results, const std::string& material);

}  // namespace demcal::workflow
