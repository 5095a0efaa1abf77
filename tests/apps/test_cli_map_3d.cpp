// `cpkit map --system FILE` with a "dim": 3 system (docs/contact_3d.md, "Maps over the sphere of
// load directions"). Independent sources: `cpkit rate --system` at a cell's load direction (the
// count of that cell); the 2-D command line `cpkit map --kind param-direction` for an isotropic
// point whose Y direction is decoupled (its count array equals the 3-D one at g = 0); the
// docs' promises about files and JSON fields. Bad input: exit 2 with the problem named.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "peer_skip.hpp"

namespace fs = std::filesystem;
using namespace cpkit::test;

namespace {

fs::path write(const std::string& name, const std::string& text) {
  const fs::path p = scratch_dir() / name;
  std::ofstream(p) << text;
  return p;
}

/// The data bytes of a version-1.0 .npy file (header checked for `descr`).
std::string npy_data(const fs::path& p, const std::string& descr) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  const std::string b = s.str();
  REQUIRE(b.size() >= 10);
  REQUIRE(b.compare(0, 6, "\x93NUMPY") == 0);
  const std::size_t hlen = static_cast<unsigned char>(b[8]) + 256u * static_cast<unsigned char>(b[9]);
  const std::string header = b.substr(10, hlen);
  CHECK(header.find("'" + descr + "'") != std::string::npos);
  return b.substr(10 + hlen);
}

std::vector<double> npy_doubles(const fs::path& p) {
  const std::string d = npy_data(p, "<f8");
  std::vector<double> v(d.size() / 8);
  std::memcpy(v.data(), d.data(), v.size() * 8);
  return v;
}

const std::string kElliptic = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/elliptic_point_3d.json";
// strong tangential-normal coupling, mu = 4: a region of three solutions on the sphere
const std::string kSphere = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/sphere_point_3d.json";

}  // namespace

TEST_CASE("cpkit map --system (dim 3) --kind sphere: files, JSON, and cells as `cpkit rate`",
          "[cli][map3d]") {
  const std::string prefix = (scratch_dir() / "sphere3d" / "ell").string();
  const CliRun r = run_cpkit("map --system '" + kSphere +
                             "' --kind sphere --n 15 --n2 24 --threads 2 --out '" + prefix + "' --json");
  INFO(r.err);
  REQUIRE((r.code == 0 || r.code == 5));
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["cpkit_version"].is_string());
  CHECK(j["kind"] == "sphere");
  CHECK(j["dim"] == 3);
  CHECK(j["input"]["system"] == kSphere);
  CHECK(j["input"]["route"] == "exact");
  CHECK(j["input"]["n"] == 15);
  CHECK(j["input"]["n2"] == 24);
  CHECK(j["input"]["point"] == 1);
  CHECK(j["cells"] == 15 * 24);
  CHECK(j["run"]["options"].is_object());
  CHECK(j["type_bits"]["slip"] == 8);
  int64_t sum = 0;
  bool several = false;
  for (const auto& c : j["counts"]) {
    sum += c["cells"].get<int64_t>();
    several = several || (c["count"].is_number() && c["count"].get<int>() > 1);
  }
  CHECK(sum == 15 * 24);
  CHECK(several);
  CHECK(j["complete"] == (j["incomplete_cells"] == 0));
  CHECK((r.code == 5) == (j["incomplete_cells"].get<int>() > 0));
  for (const char* k : {"count", "types", "complete", "x", "y", "json"}) {
    CAPTURE(k);
    REQUIRE(j["files"].contains(k));
    CHECK(fs::exists(fs::path(prefix).parent_path() / j["files"][k].get<std::string>()));
  }
  // PREFIX.json is the printed summary (plus the files)
  const auto jf = nlohmann::json::parse(slurp(prefix + ".json"));
  CHECK(jf["cells"] == j["cells"]);
  const std::string count = npy_data(prefix + "_count.npy", "|i1");
  const std::string types = npy_data(prefix + "_types.npy", "|u1");
  const std::string complete = npy_data(prefix + "_complete.npy", "|u1");
  const std::vector<double> b = npy_doubles(prefix + "_x.npy"), g = npy_doubles(prefix + "_y.npy");
  REQUIRE(count.size() == 15u * 24u);
  REQUIRE(b.size() == 15u);
  REQUIRE(g.size() == 24u);
  CHECK(g.back() == Approx(M_PI));
  int incomplete = 0;
  for (char c : complete) incomplete += c == 0;
  CHECK(incomplete == j["incomplete_cells"].get<int>());
  // Some cells against `cpkit rate --system FILE --dF ...` at the cell's direction.
  int compared = 0, several_cells = 0;
  for (int i = 0; i < 15; ++i)
    for (int jj = 0; jj < 24; ++jj) {
      const std::size_t k = static_cast<std::size_t>(i) * 24 + jj;
      // every cell with several solutions, and a sample of the others
      if (!complete[k] || (count[k] <= 1 && (i % 2 != 0 || jj % 5 != 1))) continue;
      std::ostringstream dF;
      dF.precision(17);
      dF << std::sin(b[i]) * std::cos(g[jj]) << ' ' << std::sin(b[i]) * std::sin(g[jj]) << ' '
         << std::cos(b[i]);
      const CliRun one = run_cpkit("rate --system '" + kSphere + "' --dF " + dF.str() + " --json");
      CAPTURE(i, jj, dF.str(), one.err);
      REQUIRE((one.code == 0 || one.code == 1));
      const auto jr = nlohmann::json::parse(one.out);
      CHECK(jr["count"].get<int>() == static_cast<int>(count[k]));
      unsigned mask = 0;
      for (const auto& s : jr["solutions"])
        for (const auto& t : s["types"]) {
          const std::string n = t.get<std::string>();
          mask |= n == "open" ? 1u : n == "separation" ? 2u : n == "stick" ? 4u : 8u;
        }
      CHECK(mask == static_cast<unsigned char>(types[k]));
      several_cells += count[k] > 1;
      ++compared;
    }
  CHECK(compared >= 25);
  CHECK(several_cells >= 1);
}

TEST_CASE("cpkit map --system (dim 3) --kind param-direction at g = 0: a decoupled isotropic "
          "point gives the 2-D map's counts", "[cli][map3d]") {
  const fs::path f = write("decoupled_map3d.json", R"({"dim": 3,
    "A": [[1, 0, 0.8], [0, 2, 0], [0.8, 0, 1.5]],
    "points": [{"state": "b", "mu": 2, "C_T": 0.25}]})");
  const std::string p3 = (scratch_dir() / "pd3d").string(), p2 = (scratch_dir() / "pd2d").string();
  const CliRun r3 = run_cpkit("map --system '" + f.string() +
                              "' --kind param-direction --param mu --from 0.5 --to 3 --n 12 "
                              "--theta-n 72 --out '" + p3 + "' --json");
  const CliRun r2 = run_cpkit("map --state b --a11 1 --a12 0.8 --a22 1.5 --C_T 0.25 --kind "
                              "param-direction --param mu --from 0.5 --to 3 --n 12 --theta-n 72 "
                              "--out '" + p2 + "'");
  INFO(r3.err << r2.err);
  REQUIRE(r3.code == 0);
  REQUIRE(r2.code == 0);
  const auto j = nlohmann::json::parse(r3.out);
  CHECK(j["input"]["param"] == "mu");
  CHECK(j["input"]["gamma"] == 0.0);
  CHECK(j["axes"]["y"] == "theta");
  const std::string c3 = npy_data(p3 + "_count.npy", "|i1"), c2 = npy_data(p2 + "_count.npy", "|i1");
  REQUIRE(c3.size() == 12u * 72u);
  CHECK(c3 == c2);
  CHECK(c3.find('\x03') != std::string::npos);  // a wedge of three solutions
  CHECK(npy_doubles(p3 + "_y.npy") == npy_doubles(p2 + "_theta.npy"));
}

TEST_CASE("cpkit map --system (dim 3) --kind param-param over alpha_X x alpha_Y, and N points",
          "[cli][map3d]") {
  const std::string p = (scratch_dir() / "pp3d").string();
  const CliRun r = run_cpkit("map --system '" + kElliptic +
                             "' --kind param-param --param alpha_X --from 0.4 --to 1.2 --n 5 "
                             "--param2 alpha_Y --from2 0.4 --to2 1.2 --n2 5 --out '" + p + "' --json");
  INFO(r.err);
  REQUIRE((r.code == 0 || r.code == 5));
  const auto j = nlohmann::json::parse(r.out);
  CHECK((r.code == 5) == (j["incomplete_cells"].get<int>() > 0));
  CHECK(j["kind"] == "param-param");
  CHECK(j["input"]["param"] == "alpha_X");
  CHECK(j["input"]["param2"] == "alpha_Y");
  CHECK(j["input"]["dF"] == std::vector<double>{1.0, 0.5, 0.9});
  CHECK(j["cells"] == 25);
  // the cell (0.6, 1.0) is the file's point at its dF: `cpkit rate` says 3 solutions
  const std::string count = npy_data(p + "_count.npy", "|i1");
  CHECK(count[1 * 5 + 3] == 3);  // alpha_X = 0.6 (row 1), alpha_Y = 1.0 (column 3)
  CHECK(npy_data(p + "_complete.npy", "|u1")[1 * 5 + 3] == 1);

  // Two points: --facets required; the sphere of point 2 with point 1's load from the file.
  const std::string two = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/two_point_system_3d.json";
  const CliRun n2 = run_cpkit("map --system '" + two + "' --kind sphere --n 4 --n2 8 --facets 8 "
                              "--point 2 --others file --json");
  INFO(n2.err);
  REQUIRE((n2.code == 0 || n2.code == 5));
  const auto jn = nlohmann::json::parse(n2.out);
  CHECK(jn["input"]["route"] == "faceted");
  CHECK(jn["input"]["facets"] == 8);
  CHECK(jn["input"]["point"] == 2);
  CHECK(jn["input"]["others"] == "file");
  CHECK(jn["cells"] == 32);
  // without --others: the file's dF for the other point (the file has one), the same map
  const CliRun d = run_cpkit("map --system '" + two + "' --kind sphere --n 4 --n2 8 --facets 8 "
                             "--point 2 --json");
  REQUIRE(d.code == n2.code);
  const auto jd = nlohmann::json::parse(d.out);
  CHECK(jd["input"]["others"] == "file");
  CHECK(jd["counts"] == jn["counts"]);
  CHECK(jd["types"] == jn["types"]);
}

TEST_CASE("cpkit map --system (dim 3) --plot draws the picture", "[cli][map3d]") {
  if (std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") != 0) {
    CPKIT_SKIP_CHECK("picture not checked: /usr/bin/python3 has no matplotlib");
    return;
  }
  for (const std::string kind : {"sphere", "param-direction"}) {
    const std::string p = (scratch_dir() / ("plot3d_" + kind)).string();
    const std::string extra = kind == "sphere" ? " --n 10 --n2 16"
                                               : " --param alpha_X --from 0.3 --to 1 --n 4 --theta-n 24";
    const CliRun r = run_cpkit("map --system '" + kElliptic + "' --kind " + kind + extra +
                               " --out '" + p + "' --plot");
    INFO(r.err);
    CHECK((r.code == 0 || r.code == 5));
    CHECK(fs::exists(p + ".png"));
    CHECK(fs::exists(p + ".svg"));
    const auto j = nlohmann::json::parse(slurp(p + ".json"));
    CHECK(j["files"]["png"] == fs::path(p).filename().string() + ".png");
  }
}

TEST_CASE("cpkit map --system (dim 3): bad input exits 2 naming the problem", "[cli][map3d]") {
  const std::string f = "'" + kElliptic + "'";
  const fs::path nodF = write("nodF3d.json", R"({"dim": 3, "A": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
    "points": [{"state": "b", "mu": 1}]})");
  const std::string two = "'" + std::string(CPKIT_SOURCE_DIR) + "/docs/examples/two_point_system_3d.json'";
  struct Case {
    std::string args, message;
  };
  const std::vector<Case> cases = {
      {"--system " + f, "dim 3"},
      {"--system " + f + " --kind direction", "sphere, param-direction or param-param"},
      {"--system " + f + " --kind globe", "globe"},
      {"--system " + f + " --kind sphere --a11 1", "--a11 has no effect"},
      {"--system " + f + " --kind sphere --theta-n 10", "--theta-n has no effect"},
      {"--system " + f + " --kind sphere --param mu", "--param has no effect"},
      {"--system " + f + " --kind sphere --resume --out x", "--resume has no effect"},
      {"--system " + f + " --kind sphere --method analytic", "--method has no effect"},
      {"--system " + f + " --kind sphere --gamma 1", "--gamma has no effect"},
      {"--system " + f + " --kind sphere --n 0", "--n must be"},
      {"--system " + f + " --kind sphere --n 100000 --n2 100000", "cells"},
      {"--system " + f + " --kind sphere --n 3000 --n2 3000 --time-limit 0.01", "--time-limit"},
      {"--system " + f + " --kind sphere --from nan --to 1", "--from"},
      {"--system " + f + " --kind sphere --from 0 --to 4", "[0, pi]"},
      {"--system " + f + " --kind sphere --from 1", "--from and --to"},
      {"--system " + f + " --kind sphere --facets 2", "--facets must be"},
      {"--system " + f + " --kind sphere --point 2", "--point must be"},
      {"--system " + f + " --kind sphere --others file", "--others has no effect"},
      {"--system " + f + " --kind sphere --format csv --out x", "npy"},
      {"--system " + f + " --kind sphere --plot", "--plot needs --out"},
      {"--system " + f + " --kind param-direction --param alpha_X --from 0.5", "needs --to"},
      {"--system " + f + " --kind param-direction --param alpha --from 0.5 --to 1", "alpha_X, alpha_Y"},
      {"--system " + f + " --kind param-direction --param alpha_X --from -1 --to 1 --n 3", "alpha_X = -1"},
      {"--system " + f + " --kind param-direction --param mu --from 1 --to 2 --theta-from 0 --theta-to 7", "2 pi"},
      {"--system " + f + " --kind param-param --param mu --from 1 --to 2 --param2 mu@1 --from2 1 --to2 2", "same quantity"},
      {"--system '" + nodF.string() + "' --kind param-param --param mu --from 1 --to 2 --param2 C_T --from2 0 --to2 1", "dF"},
      {"--system " + two + " --kind sphere", "--facets"},
      {"--system " + two + " --kind sphere --facets 8 --others all", "--others must be zero or file"},
      {"--preset fig5b --facets 8", "3-D systems"},
  };
  for (const auto& c : cases) {
    const CliRun r = run_cpkit("map " + c.args);
    CAPTURE(c.args, r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK(r.out.empty());
  }
}

TEST_CASE("cpkit map (dim 3): --time-limit is one deadline for the whole map (issue 24, "
          "items 11 and 12)", "[cli][map][map3d]") {
  const std::string sys =
      std::string(CPKIT_SOURCE_DIR) + "/tests/data/systems/eight_grazing_points_3d.json";
  // The issue's reproducer: one cell of eight grazing points, 4 facets, --time-limit 1 ran
  // 600 s. Now about 1 s, the cell flagged: complete false, exit 5.
  auto t0 = std::chrono::steady_clock::now();
  CliRun r = run_cpkit("map --system '" + sys +
                       "' --kind sphere --facets 4 --n 1 --n2 1 --time-limit 1 --json");
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  INFO(r.err);
  CHECK(r.code == 5);
  auto j = nlohmann::json::parse(r.out);
  CHECK(j["complete"] == false);
  CHECK(j["time_limit_reached"] == true);
  CHECK(j["timed_out_cells"] == 1);
  CHECK(j["incomplete_cells"] == 1);
  CHECK(r.err.find("time limit reached") != std::string::npos);
  CHECK(seconds < 15);  // the bound allows a slow (sanitizer) build
  // A larger map whose timed sample cannot finish within the limit is refused up front.
  t0 = std::chrono::steady_clock::now();
  r = run_cpkit("map --system '" + sys + "' --kind sphere --facets 4 --n 5 --n2 9 --time-limit 1");
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK(r.code == 2);
  CHECK(r.err.find("the time limit was reached") != std::string::npos);
  CHECK(r.out.empty());
  CHECK(seconds < 15);
  // Limits that depend on N and the states are checked right after the file is read: 11
  // grazing points (at most 10), and 8 grazing points x 9 facets = 72 > 64.
  std::ostringstream big;
  big << "{\"dim\": 3, \"A\": [";
  for (int i = 0; i < 33; ++i) {
    big << (i ? ", " : "") << "[";
    for (int k = 0; k < 33; ++k) big << (k ? ", " : "") << (i == k ? 1 : 0);
    big << "]";
  }
  big << "], \"points\": [";
  for (int i = 0; i < 11; ++i) big << (i ? ", " : "") << "{\"state\": \"b\", \"mu\": 1}";
  big << "]}";
  const fs::path eleven = write("eleven_grazing.json", big.str());
  r = run_cpkit("map --system '" + eleven.string() + "' --kind sphere --facets 4 --n 2 --n2 2");
  CHECK(r.code == 2);
  CHECK(r.err.find("11 grazing points") != std::string::npos);
  r = run_cpkit("map --system '" + sys + "' --kind sphere --facets 9 --n 2 --n2 2");
  CHECK(r.code == 2);
  CHECK(r.err.find("n_d + K n_b = 72") != std::string::npos);
}
