// A grid map whose output would not fit the free disk is refused before any cell is computed,
// naming the options that make it fit; the free disk is injected (MapEnvironment::free_disk), so
// the check runs the same on every machine (the program asks statvfs; test_cli_map.cpp runs the
// program's own refusals that do not depend on the machine). Independent source: the output's
// size by hand, 4 bytes per cell (the .npy arrays class, min_count, max_count and types, one byte
// each), against 95 % of the injected free bytes.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/requests/map_request_run.hpp"

using namespace cpkit::rate;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

/// The Fig. 5(b) preset as a param-direction grid over mu in [0.1, 4], written to `out`.
MapRequest grid_request(int n, int theta_n, const std::string& out) {
  MapRequest a;
  a.preset = "fig5b";
  a.kind = "param-direction";
  a.param = "mu";
  a.from = 0.1;
  a.to = 4;
  a.n = n;
  a.theta_n = theta_n;
  a.time_limit = 1e9;  // the time and --max-output checks would refuse the big map first
  a.max_output = "1T";
  a.threads = 1;
  a.out = out;
  return a;
}

fs::path scratch(const std::string& name) {
  const auto d = fs::temp_directory_path() /
                 ("cpkit_map_disk_refusal_" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST_CASE("a 100000 x 1000000 map (4e11 bytes) is refused with 1.5e11 bytes free",
          "[rate][maps][request][disk]") {
  const fs::path dir = scratch("huge");
  const std::string prefix = (dir / "huge").string();
  MapEnvironment env;
  std::vector<std::string> asked;
  env.free_disk = [&asked](const std::string& d) {
    asked.push_back(d);
    return 1.5e11;
  };
  const MapRequest a = grid_request(100000, 1000000, prefix);
  try {
    run_map_request(a, env);
    FAIL("not refused");
  } catch (const cpkit::InputError& e) {
    const std::string m = e.what();
    CHECK_THAT(m, Contains("100000 x 1000000 cells (--n x --theta-n)"));
    // 4 bytes per cell: 4e11 B = 372.5 GiB (the .npy headers add bytes, not GiB); 1.5e11 B =
    // 139.7 GiB free.
    CHECK_THAT(m, Contains("would take about 373 GiB but only 140 GiB is free in '" +
                           dir.string() + "'"));
    CHECK_THAT(m, Contains("use a smaller --n or --theta-n"));
  }
  REQUIRE(asked.size() == 1);
  CHECK(asked[0] == dir.string());  // the folder of --out PREFIX
  CHECK(fs::is_empty(dir));         // refused before anything is written
}

TEST_CASE("a small map: refused when its bytes exceed 95 % of the free disk, written otherwise",
          "[rate][maps][request][disk]") {
  // 7 x 24 = 168 cells: 4 bytes per cell as .npy, more than 95 % of 100 bytes; nothing close
  // to 95 % of 1e12.
  for (const double free_bytes : {100.0, 1e12, -1.0}) {
    CAPTURE(free_bytes);
    const fs::path dir = scratch("small");
    MapEnvironment env;
    env.free_disk = [free_bytes](const std::string&) { return free_bytes; };
    const MapRequest a = grid_request(7, 24, (dir / "m").string());
    if (free_bytes == 100.0) {
      CHECK_THROWS_WITH(run_map_request(a, env), Contains("but only 100 B is free in '"));
      CHECK(fs::is_empty(dir));
    } else {  // fits, or the free space unknown (-1): the map is computed and written
      const MapOutcome o = run_map_request(a, env);
      CHECK(o.exit_code == cpkit::kExitOk);
      CHECK(o.json["cells"] == 7 * 24);
      CHECK(fs::exists(dir / "m_count.npy"));
    }
  }
}
