#pragma once
// CLI11 validators whose messages read like the rest of demcal's ("must be > 0 s") instead of
// CLI11's, which print the largest double as a 300-digit number; and the input limits as CLI11
// ranges.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <string>

#include "objectives/common/input_limits.h"

namespace demcal::apps {

// A limit of the input-limits table (objectives/common/input_limits.h) as CLI11's closed range,
// in the option's type T (its help then reads "INT in [1 - 100000]"). Open ends are left to the
// IsValid behind the option.
template <class T>
CLI::Range CliRange(const objectives::limits::Limit& limit) {
  return CLI::Range(static_cast<T>(limit.lo), static_cast<T>(limit.hi));
}

// The whole of `text` as a number; NaN when it is not one (any part left over, or no number).
inline double WholeNumber(const std::string& text) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    return NAN;
  }
  return used == text.size() ? v : NAN;
}

// A finite number of seconds, > 0 (or >= 0 with allow_zero), at most `max_s`.
inline CLI::Validator Seconds(bool allow_zero, double max_s) {
  return CLI::Validator(
      [allow_zero, max_s](std::string& text) -> std::string {
        const double v = WholeNumber(text);
        char max_text[32];
        std::snprintf(max_text, sizeof max_text, "%g", max_s);
        const std::string range = std::string(allow_zero ? "[0, " : "(0, ") + max_text + "] s";
        if (!std::isfinite(v) || v < 0 || (!allow_zero && v == 0) ||
            v > max_s)
          return "'" + text + "' is not a number of seconds in " + range;
        return {};
      },
      allow_zero ? "SECONDS>=0" : "SECONDS>0");
}

// A number within a limit of the input-limits table: the check and the help print the same
// range (Limit::Text), and NaN, which CLI::Range lets through, is refused here with the option's
// name (CLI11 puts it before the message).
inline CLI::Validator InLimit(const objectives::limits::Limit& limit, const char* unit = "") {
  const std::string range = limit.Text() + (*unit ? std::string(" ") + unit : std::string());
  return CLI::Validator(
      [limit, range](std::string& text) -> std::string {
        const double v = WholeNumber(text);
        if (!limit.Contains(v))
          return "'" + text + "' is not a number in " + range;
        return {};
      },
      "in " + range);
}

// A name or path: an empty string would otherwise read as "not given" and the default (or the
// current directory) would be used in its place without a word.
inline CLI::Validator NonEmpty() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return text.empty() ? "an empty string is not allowed; leave an optional option out "
                              "for its default"
                            : std::string();
      },
      "");
}

}  // namespace demcal::apps
