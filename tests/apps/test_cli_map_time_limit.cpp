// `cpkit map --time-limit` for the one-point grid maps (issue 37): the map (fig5b, mu x
// direction, 10^10 cells) ran past its 600 s limit with an estimate 7x too low. Now: a map the
// estimate puts beyond twice the limit is refused up front (exit 2, the estimate and the options
// that help); any other map stops at the limit with the rows done, flagged incomplete (exit 5),
// and --out keeps its finished chunks for --resume. Times are seconds, never minutes: the size of
// the stopped map is chosen from this machine's own speed (a first, small map's estimate).
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <utility>

#include "cli_runner.hpp"

namespace {

using cpkit::test::CliRun;
using cpkit::test::run_cpkit;
namespace fs = std::filesystem;

const std::string kMap = "map --preset fig5b --kind param-direction --param mu --from 0.1 --to 4 ";

double seconds_of(const std::function<CliRun()>& run, CliRun& out) {
  const auto t0 = std::chrono::steady_clock::now();
  out = run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

TEST_CASE("map: the issue's 10^10-cell map is refused up front with its estimate",
          "[cli][map][time]") {
  CliRun r;
  const double wall = seconds_of(
      [] { return run_cpkit(kMap + "--n 100000 --theta-n 100000 --time-limit 60"); }, r);
  INFO(r.err);
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find("100000 x 100000 cells (--n x --theta-n)") != std::string::npos);
  CHECK(r.err.find("far more than --time-limit 60") != std::string::npos);
  CHECK(r.err.find("use a smaller --n or --theta-n, or raise --time-limit") != std::string::npos);
  // The estimate it states is beyond twice the limit (the refusal's rule), and it came quickly.
  std::smatch m;
  const std::regex about("would need about ([0-9.e+]+) s");
  REQUIRE(std::regex_search(r.err, m, about));
  CHECK(std::stod(m[1]) > 120);
  CHECK(wall < 30);
}

TEST_CASE("map: the estimate is within 2x of the cells' measured time (4x for few directions)",
          "[cli][map][time]") {
  // The oracle is the run itself: its cell phase timed by the program's own clock (the
  // command's seconds less the estimate's sample). Two shapes: many directions per row (the
  // cells dominate: within 2x) and few (each row's set-up dominates; builds weigh the two
  // differently): within 4x, as the chunked run's record of each row is not sampled
  // (grid_estimate.cpp; measured 2.2-2.8x under a load of 10 on 2 cores).
  // Each map is sized from an estimate to take about 0.5 s, whatever the build;
  // up to three attempts per shape, in case the machine's load changes during one.
  for (const auto& [theta_n, factor] : {std::pair{20000, 2.0}, std::pair{8, 4.0}}) {
    int within = 0;
    std::string seen;  // every attempt's estimate and cell time, for the failure message
    for (int attempt = 0; attempt < 3 && within == 0; ++attempt) {
      // Sized by a map refused for its time (only its estimate is computed).
      const CliRun sizing = run_cpkit(kMap + "--n 100000 --theta-n " + std::to_string(theta_n) +
                                      " --time-limit 0.001");
      INFO(sizing.err);
      REQUIRE(sizing.code == 2);
      std::smatch m;
      REQUIRE(std::regex_search(sizing.err, m, std::regex("would need about ([0-9.e+-]+) s")));
      const double per_row = std::stod(m[1]) / 100000;
      REQUIRE(per_row > 0);
      const int n = static_cast<int>(std::min(1e6, std::ceil(0.5 / per_row)));
      const std::string args = kMap + "--n " + std::to_string(n) + " --theta-n " +
                               std::to_string(theta_n) + " --json --time-limit 60";
      const CliRun r = run_cpkit(args);
      INFO(args << "\n" << r.err);
      REQUIRE(r.code == 0);
      const auto j = nlohmann::json::parse(r.out);
      const double estimate = j.at("estimate").at("seconds").get<double>();
      const double cells =
          j.at("seconds").get<double>() - j.at("estimate").at("sample_seconds").get<double>();
      INFO("theta_n " << theta_n << ": estimate " << estimate << " s, cells " << cells << " s");
      REQUIRE(cells > 0);
      seen += " n " + std::to_string(n) + ": estimate " + std::to_string(estimate) + " s, cells " +
              std::to_string(cells) + " s;";
      if (estimate <= factor * cells && cells <= factor * estimate) ++within;
    }
    INFO("theta_n " << theta_n << ", within " << factor << "x:" << seen);
    CHECK(within == 1);
  }
}

TEST_CASE("map: a grid map stops at --time-limit, flagged incomplete, and resumes",
          "[cli][map][time]") {
  const int theta_n = 20000;
  const double limit = 1.0;
  const fs::path dir = cpkit::test::scratch_dir() / "time_limit";
  fs::create_directories(dir);
  // The estimate is a wall-clock sample of this machine as loaded now, within a factor 2; a map
  // estimated at 1.4 x the limit runs (not refused: below 2x) and cannot finish in time. Up to
  // three attempts, in case the load changes between the sizing map and the run.
  int stopped = 0;
  for (int attempt = 0; attempt < 3 && stopped == 0; ++attempt) {
    const CliRun sizing = run_cpkit(kMap + "--n 64 --theta-n " + std::to_string(theta_n) +
                                    " --json");
    INFO(sizing.err);
    REQUIRE(sizing.code == 0);
    const double per_row =
        nlohmann::json::parse(sizing.out).at("estimate").at("seconds").get<double>() / 64;
    REQUIRE(per_row > 0);
    const int n = static_cast<int>(std::min(1e5, std::ceil(1.4 * limit / per_row)));
    const std::string prefix = (dir / ("m" + std::to_string(attempt))).string();
    const std::string args = kMap + "--n " + std::to_string(n) + " --theta-n " +
                             std::to_string(theta_n) + " --time-limit 1 --json --out '" +
                             prefix + "'";
    CliRun r;
    const double wall = seconds_of([&] { return run_cpkit(args); }, r);
    INFO(args << "\n" << r.err);
    if (r.code != 5) continue;  // refused (2) or finished (0): the load changed; size again
    ++stopped;
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j.at("complete") == false);
    CHECK(j.at("time_limit_reached") == true);
    const int done = j.at("rows_done").get<int>();
    CHECK(done < n);
    // The summary counts the rows done, every one of their cells once.
    int64_t cells = 0;
    for (const auto& [count, c] : j.at("counts").items()) cells += c.get<int64_t>();
    CHECK(cells == static_cast<int64_t>(done) * theta_n);
    // Stopped by the limit: exit 5 and fewer rows than asked prove it. The wall clock is only
    // checked for a hang (timings are not asserted: a loaded or instrumented machine varies).
    CHECK(wall < 60);
    CHECK(r.err.find("time limit reached (--time-limit 1 s) after " + std::to_string(done) +
                     " of " + std::to_string(n) + " rows") != std::string::npos);
    // No map file from a part of the map; the finished chunks are kept for --resume.
    CHECK_FALSE(fs::exists(prefix + ".json"));
    CHECK_FALSE(fs::exists(prefix + "_count.npy"));
    REQUIRE(fs::is_directory(prefix + ".parts"));
    // The same command with --resume and room to finish: the whole map.
    const CliRun rest = run_cpkit(args.substr(0, args.find(" --time-limit")) + " --time-limit 60 "
                                  "--json --resume --out '" + prefix + "'");
    INFO(rest.err);
    CHECK(rest.code == 0);
    const auto k = nlohmann::json::parse(rest.out);
    CHECK_FALSE(k.contains("time_limit_reached"));
    CHECK(k.at("resumed_cells").get<int64_t>() >= static_cast<int64_t>(done) * theta_n);
    CHECK(fs::exists(prefix + "_count.npy"));
  }
  REQUIRE(stopped == 1);
}
