#pragma once
// FieldChecker: collects the first violation of a scene's checks as "field 'PATH' = VALUE is
// outside the allowed range [LO, HI] UNIT" (Scene::IsValid, core/scene/scene_validation.cc, and
// its derived motion checks, core/scene/scene_motion.cc). Not thread-safe (one per check).
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "core/math/vec3.h"
#include "core/limits/physical_limits.h"

namespace demcal::core {

struct Scene;

// The path of element i of a list field: "walls[2]".
inline std::string IndexedField(const std::string& name, size_t i) {
  return name + "[" + std::to_string(i) + "]";
}

// Collects the first violation as "field = value is outside allowed range".
class FieldChecker {
 public:
  explicit FieldChecker(std::string* error) : error_(error) {}
  bool ok() const { return ok_; }
  void Fail(const std::string& message) {
    if (ok_ && error_) *error_ = message;
    ok_ = false;
  }
  // open/closed bounds: lo_open ⇒ value > lo, else value >= lo (same for hi)
  void Range(const std::string& field, double v, double lo, double hi, bool lo_open,
             bool hi_open, const std::string& unit = "") {
    const bool good =
        std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
    if (good) return;
    // Readable bounds: "(0, 1e+06] s", "> 0 Pa"; never "inf" or a 300-digit number.
    std::ostringstream os;
    os << "field '" << field << "' = " << v << (unit.empty() ? "" : " " + unit)
       << " is outside the allowed range ";
    if (std::isinf(hi))
      os << (lo_open ? "> " : ">= ") << lo;
    else
      os << (lo_open ? "(" : "[") << lo << ", " << hi << (hi_open ? ")" : "]");
    if (!unit.empty()) os << " " << unit;
    Fail(os.str());
  }
  void Positive(const std::string& field, double v, const std::string& unit) {
    Range(field, v, 0, kInf, true, true, unit);
  }
  // A limit of the table (core/limits/physical_limits.h).
  void Within(const std::string& field, double v, const limits::Limit& l,
              const std::string& unit = "") {
    Range(field, v, l.lo, l.hi, l.lo_open, l.hi_open, unit);
  }
  // A vector's magnitude within a limit of the table; each component finite first.
  void Magnitude(const std::string& field, const Vec3& v, const limits::Limit& l,
                 const std::string& unit) {
    if (!IsFinite(v)) return Fail("field '" + field + "' must be finite");
    // hypot: |(0, 0, 1e308)| is 1e308, where Norm's sum of squares overflows to inf.
    const double norm = std::hypot(v.x, v.y, v.z);
    if (l.Contains(norm)) return;
    std::ostringstream os;
    os << "field '" << field << "' has magnitude " << norm << " " << unit
       << ", outside the allowed range " << l.Text() << " " << unit;
    Fail(os.str());
  }
  // Every component of a point within the coordinate limit.
  void Point(const std::string& field, const Vec3& x) {
    for (int a = 0; a < 3; ++a) Within(field + "[" + std::to_string(a) + "]", x[a],
                                       limits::kCoordinate, "m");
  }
  static constexpr double kInf = std::numeric_limits<double>::infinity();

 private:
  std::string* error_ = nullptr;
  bool ok_ = true;
};

// The derived motion checks (core/scene/scene_motion.cc): what one time step allows a particle
// or a wall to travel, and factory regions that stay inside the domain while they move.
void CheckSceneMotion(const Scene& scene, FieldChecker& c);

}  // namespace demcal::core
