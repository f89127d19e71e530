// Calibrations running together share one log through TaggedLog: every line arrives whole and
// tagged with its calibration, as soon as it ends; a last line without a newline is not lost.
#include "workflow/reproduce/tagged_log.h"

#include <catch2/catch.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using demcal::workflow::TaggedLog;

TEST_CASE("tagged log: whole lines, each with its tag, written as they end", "[unit]") {
  std::ostringstream shared;
  std::mutex lock;
  {
    TaggedLog bp_buf("BP", &shared, &lock);
    std::ostream bp(&bp_buf);
    bp << "candidate 1/6: mu_r " << 0.25;
    CHECK(shared.str().empty());  // the line has not ended yet
    bp << " -> 31.2 deg\n";
    CHECK(shared.str() == "[BP] candidate 1/6: mu_r 0.25 -> 31.2 deg\n");
    bp << "stopped early";
  }
  CHECK(shared.str() ==
        "[BP] candidate 1/6: mu_r 0.25 -> 31.2 deg\n[BP] stopped early\n");
}

TEST_CASE("tagged log: lines of threads writing at once never mix", "[unit]") {
  std::ostringstream shared;
  std::mutex lock;
  const std::vector<std::string> tags = {"BP", "TAED", "EP"};
  std::vector<std::thread> threads;
  for (const std::string& tag : tags)
    threads.emplace_back([&shared, &lock, tag] {
      TaggedLog buf(tag, &shared, &lock);
      std::ostream out(&buf);
      for (int i = 0; i < 200; ++i) out << "line " << i << " of " << tag << "\n";
    });
  for (std::thread& t : threads) t.join();
  std::istringstream lines(shared.str());
  std::string line;
  int count = 0;
  while (std::getline(lines, line)) {
    ++count;
    const size_t close = line.find("] ");
    REQUIRE(close != std::string::npos);
    const std::string tag = line.substr(1, close - 1);
    // The tag in front is the writer named at the end: no line carries another's text.
    CHECK(line.substr(line.size() - tag.size() - 4) == " of " + tag);
  }
  CHECK(count == 600);
}
