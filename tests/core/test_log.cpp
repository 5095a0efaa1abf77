// LogSink / log(): library code logs only through a sink, filtered by verbosity.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "cpkit/core/log.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/lemke.hpp"

namespace {
struct Collect final : cpkit::LogSink {
  std::vector<std::string> lines;
  void write(cpkit::LogLevel level, std::string_view m) override {
    lines.push_back(std::string(cpkit::to_string(level)) + ":" + std::string(m));
  }
};
}  // namespace

TEST_CASE("log() filters by verbosity and tolerates a null sink", "[log]") {
  Collect c;
  cpkit::log(&c, 0, cpkit::LogLevel::kError, "e");
  cpkit::log(&c, 0, cpkit::LogLevel::kWarning, "w0");
  cpkit::log(&c, 1, cpkit::LogLevel::kWarning, "w1");
  cpkit::log(&c, 2, cpkit::LogLevel::kDebug, "d2");
  cpkit::log(&c, 3, cpkit::LogLevel::kDebug, "d3");
  cpkit::log(nullptr, 3, cpkit::LogLevel::kError, "nowhere");
  CHECK(c.lines == std::vector<std::string>{"error:e", "warning:w1", "debug:d3"});
}

TEST_CASE("StreamLogSink writes '[level] message' lines", "[log]") {
  std::ostringstream s;
  cpkit::StreamLogSink sink(s);
  cpkit::log(&sink, 2, cpkit::LogLevel::kInfo, "hello");
  CHECK(s.str() == "[info] hello\n");
}

TEST_CASE("Solvers log through the sink of CommonOptions, not to the terminal", "[log]") {
  Collect c;
  cpkit::lcp::LemkeOptions o;
  o.common.log = &c;
  o.common.verbosity = 2;
  cpkit::lcp::solve_lemke(cpkit::LcpProblem(cpkit::Mat{{2}}, cpkit::Vec{{-1}}), o);
  REQUIRE(c.lines.size() == 1);
  CHECK(c.lines[0].find("info:lemke: solved after 2 pivots") == 0);
}

TEST_CASE("Stopwatch: infinite limits are never exceeded", "[timer]") {
  cpkit::Stopwatch w;
  CHECK_FALSE(w.exceeded(std::numeric_limits<double>::infinity()));
  CHECK(w.seconds() >= 0);
  CHECK(w.exceeded(-1.0));
}
