#include "files/json_fields.h"

#include <catch2/catch.hpp>

using demcal::workflow::JsonFields;
using demcal::workflow::JsonStatus;
using demcal::workflow::kOptional;
using demcal::workflow::kRequired;
using demcal::workflow::Range;
using nlohmann::json;

TEST_CASE("an unknown key is named with its path and the closest allowed key", "[unit]") {
  JsonStatus status;
  const json object = {{"restitutoin", 0.5}};
  JsonFields f(object, "interactions.default", {"restitution", "sliding_friction"}, &status);
  REQUIRE_FALSE(status.ok());
  CHECK_THAT(status.message(), Catch::Contains("unknown key 'interactions.default.restitutoin'"));
  CHECK_THAT(status.message(), Catch::Contains("did you mean 'restitution'?"));
  CHECK_THAT(status.message(), Catch::Contains("allowed keys here: restitution, sliding_friction"));
}

TEST_CASE("missing required fields and wrong types are named with their path", "[unit]") {
  {
    JsonStatus status;
    const json object = json::object();
    JsonFields f(object, "time", {"duration_s"}, &status);
    double d = 0;
    f.Number("duration_s", &d, kRequired);
    CHECK(status.message() == "missing required field 'time.duration_s'");
  }
  {
    JsonStatus status;
    const json object = {{"duration_s", "1"}};
    JsonFields f(object, "time", {"duration_s"}, &status);
    double d = 0;
    f.Number("duration_s", &d, kRequired);
    CHECK(status.message() == "field 'time.duration_s' must be a number, got string \"1\"");
  }
  {
    JsonStatus status;
    const json array = json::array();
    JsonFields f(array, "time", {"duration_s"}, &status);
    CHECK(status.message() == "field 'time' must be an object, got array []");
  }
}

TEST_CASE("ranges are checked and described with open and closed ends", "[unit]") {
  JsonStatus status;
  const json object = {{"e", 0.0}};
  JsonFields f(object, "p", {"e"}, &status);
  double e = 0.5;
  f.Number("e", &e, kRequired, Range::LeftOpen(0, 1));
  CHECK(status.message() == "field 'p.e' = 0 is outside the allowed range (0, 1]");
  CHECK(e == 0.5);  // untouched on error
  CHECK(Range::Open(-1, 0.5).Describe() == "(-1, 0.5)");
  CHECK(Range::Closed(0, 1e3, "J/m2").Describe() == "[0, 1000] J/m2");
}

TEST_CASE("a range of the input-limits table reads as the table writes it", "[unit]") {
  namespace limits = demcal::objectives::limits;
  for (const limits::Limit& l : {limits::kSizeScale, limits::kStiffnessScale,
                                 limits::kUnitTolerance, limits::kReplicates}) {
    CHECK(Range::Of(l).Describe() == l.Text());
    CHECK(Range::Of(l).Contains(l.hi) == l.Contains(l.hi));
    CHECK(Range::Of(l).Contains(l.lo) == l.Contains(l.lo));
  }
  CHECK(Range::Of(limits::kSizeScale, "m").Describe() == "[1, 20] m");
}

TEST_CASE("integers accept integral floats (1e4) and reject fractions", "[unit]") {
  JsonStatus ok_status;
  const json good = json::parse(R"({"count": 1e4, "seed": 7})");
  JsonFields ok(good, "f", {"count", "seed"}, &ok_status);
  int64_t count = 0;
  uint64_t seed = 0;
  ok.Integer("count", &count, kRequired);
  ok.Unsigned("seed", &seed, kRequired);
  CHECK(ok_status.ok());
  CHECK(count == 10000);
  CHECK(seed == 7);

  JsonStatus bad_status;
  const json fraction = json::parse(R"({"count": 2.5})");
  JsonFields bad(fraction, "f", {"count"}, &bad_status);
  bad.Integer("count", &count, kRequired);
  CHECK_THAT(bad_status.message(), Catch::Contains("'f.count' must be an integer"));

  JsonStatus negative_status;
  const json minus = json::parse(R"({"seed": -1})");
  JsonFields negative(minus, "", {"seed"}, &negative_status);
  negative.Unsigned("seed", &seed, kRequired);
  CHECK_THAT(negative_status.message(), Catch::Contains("'seed' must be a non-negative integer"));
}

TEST_CASE("integer lists refuse values that would wrap when narrowed, naming the element", "[unit]") {
  const auto read = [](const char* text, std::vector<int64_t>* out) {
    JsonStatus status;
    const json j = json::parse(text);
    JsonFields f(j, "clump_count", {"counts"}, &status);
    f.Integers("counts", out, kRequired, Range::Closed(1, 64));
    return status.ok() ? std::string("ok") : status.message();
  };
  std::vector<int64_t> counts;
  CHECK(read(R"({"counts": [1, 2e0, 64]})", &counts) == "ok");
  CHECK(counts == std::vector<int64_t>{1, 2, 64});
  // 2^32 + 1 and -(2^32 - 1) are 1 in 32 bits: each must be refused, not read as 1.
  CHECK_THAT(read(R"({"counts": [1, 4294967297]})", &counts),
             Catch::Contains("'clump_count.counts[1]' = 4294967297 is outside the allowed range "
                             "[1, 64]"));
  CHECK_THAT(read(R"({"counts": [-4294967295]})", &counts),
             Catch::Contains("'clump_count.counts[0]' = -4294967295 is outside"));
  CHECK_THAT(read(R"({"counts": [18446744073709551615]})", &counts),
             Catch::Contains("'clump_count.counts[0]' must be an integer"));
  CHECK_THAT(read(R"({"counts": [2.5]})", &counts),
             Catch::Contains("'clump_count.counts[0]' must be an integer, got number 2.5"));
  CHECK_THAT(read(R"({"counts": 3})", &counts), Catch::Contains("must be an array of integers"));
  CHECK(counts == std::vector<int64_t>{1, 2, 64});  // untouched on error
}

TEST_CASE("vectors need exactly three numbers and strings may be restricted to choices", "[unit]") {
  JsonStatus status;
  const json short_vector = json::parse(R"({"g": [0, -9.81]})");
  JsonFields f(short_vector, "", {"g"}, &status);
  demcal::core::Vec3 g;
  f.Vector("g", &g, kOptional);
  CHECK_THAT(status.message(), Catch::Contains("'g' must be an array of 3 numbers"));

  JsonStatus choice_status;
  const json choice = json::parse(R"({"m": "epsd3"})");
  JsonFields c(choice, "contact_model", {"m"}, &choice_status);
  std::string m;
  c.String("m", &m, kRequired, {"none", "epsd2"});
  CHECK(choice_status.message() == "field 'contact_model.m' = 'epsd3' is not one of none|epsd2");
}

TEST_CASE("only the first problem is kept", "[unit]") {
  JsonStatus status;
  const json empty = json::object();
  JsonFields f(empty, "x", {"a", "b"}, &status);
  double a = 0, b = 0;
  f.Number("a", &a, kRequired);
  f.Number("b", &b, kRequired);
  CHECK(status.message() == "missing required field 'x.a'");
}
