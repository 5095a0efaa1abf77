// `cpkit map` end to end: runs the built binary (CPKIT_BINARY_DIR/apps/cpkit), checks the JSON
// it prints, the files it writes, the exit codes for bad input, and the plotting script.
#include <catch2/catch.hpp>

#include "cli_runner.hpp"
#include "peer_skip.hpp"
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace fs = std::filesystem;

namespace {
const std::string kCpkit = CPKIT_BINARY_DIR "/apps/cpkit";

using Run = cpkit::test::CliRun;
using cpkit::test::slurp;

fs::path scratch_dir() {
  const fs::path d = cpkit::test::scratch_dir() / "map";
  fs::create_directories(d);
  return d;
}

Run run(const std::string& args) { return cpkit::test::run_cpkit(args); }

int count_lines(const fs::path& p) {
  std::ifstream f(p);
  std::string line;
  int n = 0;
  while (std::getline(f, line)) ++n;
  return n;
}
}  // namespace

TEST_CASE("CliDirectionMapJsonListsSectorsAndCriticalDirections", "[cli][map]") {
  const Run r = run("map --preset fig5b --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["sectors"].size() == 4);
  REQUIRE(j["critical"].size() == 4);
  // The three-solution sector lies between L+ = 0 and N = 0 (closed forms of model.md).
  const auto& s0 = j["sectors"][0];
  CHECK(s0["count"] == 3);
  CHECK(s0["theta_from"].get<double>() == Approx(std::atan(1.375 / 3.75)).margin(1e-12));
  CHECK(s0["theta_to"].get<double>() == Approx(std::atan(0.5)).margin(1e-12));
  CHECK(s0["types"] == nlohmann::json({"separation", "stick", "slip+"}));
  for (const auto& c : j["critical"]) {
    CHECK(c["theta"].get<double>() >= 0);
    CHECK(c["theta"].get<double>() < 2 * M_PI);
  }
  CHECK(j["cpkit_version"].is_string());
  CHECK(j["method"] == "enumerate");
  CHECK(j.contains("seconds"));
}

TEST_CASE("CliTextSummaryNamesTheNonUniqueSector", "[cli][map]") {
  const Run r = run("map --preset fig5b");
  REQUIRE(r.code == 0);
  // Open interval: the sector's end directions are critical and have 2 solutions each.
  CHECK(r.out.find("3 solutions for theta in (0.35, 0.46)") != std::string::npos);
}

TEST_CASE("CliGridMapWritesCsvAndJson", "[cli][map]") {
  const fs::path prefix = scratch_dir() / "mu_dir";
  fs::remove(prefix.string() + ".csv");
  const Run r = run("map --preset fig5b --kind param-direction --param mu --from 0.5 --to 3.5 "
                    "--n 31 --theta-n 90 --threads 2 --format csv --out " + prefix.string());
  REQUIRE(r.code == 0);
  REQUIRE(fs::exists(prefix.string() + ".csv"));
  REQUIRE(fs::exists(prefix.string() + ".json"));
  REQUIRE(fs::exists(prefix.string() + "_critical.csv"));
  CHECK(count_lines(prefix.string() + ".csv") == 31 * 90 + 1);
  const auto j = nlohmann::json::parse(slurp(prefix.string() + ".json"));
  CHECK(j["cells"] == 31 * 90);
  CHECK(j["kind"] == "param-direction");
  CHECK(j["files"]["csv"] == "mu_dir.csv");
  REQUIRE(j["critical_values"].size() == 1);
  CHECK(j["critical_values"][0]["x"].get<double>() == Approx(2.0).margin(1e-12));
  CHECK(j["counts"].contains("3"));
  // --json on a grid map prints the summary with cells and seconds.
  const Run rj = run("map --preset state-d --n 20 --theta-n 36 --json");
  REQUIRE(rj.code == 0);
  const auto s = nlohmann::json::parse(rj.out);
  CHECK(s["cells"] == 720);
  CHECK(s.contains("seconds"));
}

TEST_CASE("CliThreadCountDoesNotChangeTheCsv", "[cli][map]") {
  const fs::path a = scratch_dir() / "t1", b = scratch_dir() / "t3";
  const std::string common =
      "map --preset fig5b --kind param-direction --param mu --from 0.1 --to 4 --n 50 "
      "--theta-n 73 --format csv --out ";
  REQUIRE(run(common + a.string() + " --threads 1").code == 0);
  REQUIRE(run(common + b.string() + " --threads 3").code == 0);
  CHECK(slurp(a.string() + ".csv") == slurp(b.string() + ".csv"));
  CHECK(slurp(a.string() + "_critical.csv") == slurp(b.string() + "_critical.csv"));
  // The JSON differs exactly in what docs/maps.md names: seconds, threads, run (the command
  // line) and files (the names follow --out).
  auto json_of = [](const fs::path& p) {
    auto j = nlohmann::json::parse(slurp(p.string() + ".json"));
    REQUIRE(j.at("run").at("options").at("threads").is_number());
    for (const char* k : {"seconds", "threads", "run", "files", "estimate"}) j.erase(k);
    return j;
  };
  CHECK(json_of(a) == json_of(b));
}

TEST_CASE("CliAnalyticCrossCheckOnFig5HasNoDisagreement", "[cli][map]") {
  const Run r = run("map --preset fig5a --method analytic --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["disagreements"] == 0);
  CHECK(j["cross_checked"] == true);
}

TEST_CASE("CliMapRejectsBadInputWithExitCode2", "[cli][map]") {
  for (const char* args :
       {"map --kind spiral", "map --preset nosuch", "map --mu nan", "map --a12 5",
        "map --kind param-direction --param mu --from 2 --to 1",
        "map --kind param-direction --param nosuch --from 0 --to 1",
        "map --kind param-direction", "map --preset fig5b --threads -1",
        "map --preset fig5b --method lemke", "map --bogus-option",
        "map --preset fig5b --plot", "map --kind param-direction --param kappa --from 0 --to 1",
        "map --preset fig5b --theta-n 90", "map --preset state-d-mu-kappa --n 3 --n2 3 --theta-n 9",
        "map --preset fig5b --criterion 37", "map --preset fig5b --criterion coulomb38",
        "map --preset state-d --n 4 --theta-n 8 --format png --out /tmp/x",
        "map --preset fig5b --format npy --out /tmp/x",
        "map --preset state-d --n 4 --theta-n 8 --format csv"}) {
    CAPTURE(args);
    const Run r = run(args);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK(!r.err.empty());
  }
}

TEST_CASE("CliPlotWritesPngAndSvg", "[cli][map][plot]") {
  if (std::system("/usr/bin/python3 -c 'import matplotlib, numpy' >/dev/null 2>&1") != 0) {
    CPKIT_SKIP_CHECK("/usr/bin/python3 has no matplotlib (Debian: apt-get install python3-matplotlib)");
    return;
  }
  for (const char* kind : {"direction", "param-direction", "param-param"}) {
    CAPTURE(kind);
    const fs::path prefix = scratch_dir() / (std::string("plot_") + kind);
    fs::remove(prefix.string() + ".png");
    fs::remove(prefix.string() + ".svg");
    const std::string preset = std::string(kind) == "param-param" ? "state-d-mu-kappa" : "fig5b";
    // --theta-n is accepted only where directions are sampled (param-direction).
    const std::string theta_n = std::string(kind) == "param-direction" ? " --theta-n 48" : "";
    // Axis options only where the kind has axes (elsewhere they are errors).
    const std::string axes = std::string(kind) == "direction" ? ""
                             : std::string(kind) == "param-direction"
                                 ? " --param mu --from 0.5 --to 3.5 --n 24"
                                 : " --param mu --from 0.5 --to 3.5 --n 24 --n2 12";
    const Run r = run("map --preset " + preset + " --kind " + kind + axes + theta_n + " --out " +
                      prefix.string() + " --plot");
    REQUIRE(r.code == 0);
    REQUIRE(fs::exists(prefix.string() + ".png"));
    REQUIRE(fs::exists(prefix.string() + ".svg"));
    const std::string png = slurp(prefix.string() + ".png");
    CHECK(png.substr(1, 3) == "PNG");
    CHECK(slurp(prefix.string() + ".svg").find("<svg") != std::string::npos);
    const auto j = nlohmann::json::parse(slurp(prefix.string() + ".json"));
    CHECK(j["files"]["png"] == "plot_" + std::string(kind) + ".png");
  }
}

TEST_CASE("CliPlotWithoutMatplotlibStillWritesTheData", "[cli][map][plot]") {
  // A Python without matplotlib: the data is written, the message says how to get the picture,
  // and the exit code is 4 (a requested picture that is missing is a failure).
  const fs::path fake = scratch_dir() / "fake_python.sh";
  {
    std::ofstream f(fake);
    f << "#!/bin/sh\nexec /usr/bin/python3 -S -I -c 'import sys; sys.path=[p for p in sys.path "
         "if \"dist-packages\" not in p]; sys.argv=sys.argv[1:]; "
         "exec(open(sys.argv[0]).read())' \"$@\"\n";
  }
  fs::permissions(fake, fs::perms::owner_all);
  const fs::path prefix = scratch_dir() / "nompl";
  const std::string env_cmd = "CPKIT_PYTHON=" + fake.string() + " ";
  const fs::path o = scratch_dir() / "nompl_err.txt";
  fs::remove(prefix.string() + ".png");
  fs::remove(prefix.string() + ".csv");
  const int rc = std::system((env_cmd + kCpkit + " map --preset fig5a --out " + prefix.string() +
                              " --plot >/dev/null 2>" + o.string())
                                 .c_str());
  CHECK(WEXITSTATUS(rc) == 4);
  CHECK(fs::exists(prefix.string() + ".csv"));
  CHECK_FALSE(fs::exists(prefix.string() + ".png"));
  CHECK(slurp(o).find("python3-matplotlib") != std::string::npos);
}

// --criterion 38|35 as in `cpkit rate`. State-d preset (a11 = 1, a12 = 0.5, a22 = 1, C_T = 0.25,
// kappa = 0.5, s = +1), by hand from eqn (51): Lambda = 1.25 - (1 + 3/32) m, zero at m = 8/7.
// (38): m = mu, so mu = 8/7; (35): m = mu - 2 kappa = mu - 1, so mu = 15/7.
TEST_CASE("CliCriterion35MovesTheLambdaCurve", "[cli][map]") {
  const Run r38 = run("map --preset state-d --criterion 38 --n 23 --theta-n 40 --json");
  REQUIRE(r38.code == 0);
  const auto j38 = nlohmann::json::parse(r38.out);
  CHECK(j38["model"]["criterion"] == "coulomb");
  REQUIRE(j38["critical_values"].size() == 1);
  CHECK(j38["critical_values"][0]["x"].get<double>() == Approx(8.0 / 7.0).epsilon(1e-12));
  // (35) needs P_N < 3 P_s mu / k_a, i.e. mu > 0.5 here; cross-checked by the analytic route.
  const Run r35 = run("map --preset state-d --criterion 35 --from 0.6 --to 3 --n 23 "
                      "--theta-n 40 --method analytic --json");
  REQUIRE(r35.code == 0);
  const auto j35 = nlohmann::json::parse(r35.out);
  CHECK(j35["model"]["criterion"] == "softening");
  CHECK(j35["disagreements"] == 0);
  CHECK(j35["unreliable"] == 0);
  REQUIRE(j35["critical_values"].size() == 1);
  CHECK(j35["critical_values"][0]["x"].get<double>() == Approx(15.0 / 7.0).epsilon(1e-12));
  // The text output names the criterion.
  const Run rt = run("map --preset state-d --kind direction --criterion 35 --mu 3");
  REQUIRE(rt.code == 0);
  CHECK(rt.out.find("criterion (35)") != std::string::npos);
}

// Every map reports how many evaluations the enumeration could not decide (never hidden).
TEST_CASE("CliMapJsonReportsUnreliableCells", "[cli][map]") {
  for (const char* args : {"map --preset fig5b --json",
                           "map --preset state-d --n 5 --theta-n 12 --json",
                           "map --preset state-d-mu-kappa --n 4 --n2 4 --json"}) {
    CAPTURE(args);
    const Run r = run(args);
    REQUIRE(r.code == 0);
    const auto j = nlohmann::json::parse(r.out);
    REQUIRE(j.contains("unreliable"));
    // These presets sit well away from ties (every cell also agrees with the analytic route,
    // test_map_direction / test_map_grid): no sign test may be reported too close to call.
    CHECK(j["unreliable"].get<int64_t>() == 0);
  }
}

// The default grid output: .npy arrays read back by numpy itself (an independent reader) equal
// the CSV of the same map, cell by cell.
TEST_CASE("CliGridMapNpyEqualsCsvReadByNumpy", "[cli][map][npy]") {
  if (std::system("/usr/bin/python3 -c 'import numpy' >/dev/null 2>&1") != 0) {
    CPKIT_SKIP_CHECK("/usr/bin/python3 has no numpy (Debian: apt-get install python3-numpy)");
    return;
  }
  for (const std::string kind : {"param-direction", "param-param"}) {
    CAPTURE(kind);
    const fs::path a = scratch_dir() / ("npy_" + kind), b = scratch_dir() / ("csv_" + kind);
    const std::string common =
        kind == "param-direction"
            ? "map --preset state-d --n 23 --theta-n 41 --method analytic --out "
            : "map --preset state-d-mu-kappa --n 9 --n2 7 --out ";
    const Run ra = run(common + a.string());
    REQUIRE(ra.code == 0);
    REQUIRE(run(common + b.string() + " --format csv").code == 0);
    const auto j = nlohmann::json::parse(slurp(a.string() + ".json"));
    CHECK(j["format"] == "npy");
    CHECK(!j["files"].contains("csv"));
    const fs::path script = scratch_dir() / "compare_npy.py";
    {
      std::ofstream f(script);
      f << R"(import csv, json, sys, numpy as np
pre_npy, pre_csv, kind = sys.argv[1], sys.argv[2], sys.argv[3]
s = json.load(open(pre_npy + ".json"))
rows = list(csv.reader(open(pre_csv + ".csv")))[1:]
d = pre_npy.rsplit("/", 1)[0] + "/"
load = lambda key: np.load(d + s["files"][key])
bits = sorted(s["type_bits"].items(), key=lambda kv: kv[1])
name = lambda m: "|".join(n for n, b in bits if int(m) & b) or "none"
cnt = lambda c: "inf" if c < 0 else str(c)
if kind == "param-direction":
    c, t, x, th = load("count"), load("types"), load("x"), load("theta")
    assert c.dtype == np.int8 and c.shape == (s["axis"]["n"], s["theta_n"]), c.shape
    dis = load("disagree")
    assert dis.shape == c.shape and int(dis.sum()) == s["disagreements"]
    for k, r in enumerate(rows):
        i, jj = divmod(k, c.shape[1])
        assert abs(float(r[0]) - x[i]) <= 1e-11 * max(1, abs(x[i])), (r, x[i])
        assert abs(float(r[1]) - th[jj]) <= 1e-11 * max(1, th[jj]), (r, th[jj])
        assert r[2] == cnt(c[i, jj]) and r[3] == name(t[i, jj]) and r[4] == str(dis[i, jj]), r
else:
    cl, lo, hi, t = load("class"), load("min_count"), load("max_count"), load("types")
    codes = {v: k for k, v in s["class_codes"].items()}
    assert cl.shape == (s["axis"]["n"], s["axis2"]["n"])
    for k, r in enumerate(rows):
        i, jj = divmod(k, cl.shape[1])
        assert r[2] == codes[int(cl[i, jj])] and r[3] == cnt(lo[i, jj]), r
        assert r[4] == cnt(hi[i, jj]) and r[5] == name(t[i, jj]), r
assert len(rows) == s["cells"]
)";
    }
    const int rc = std::system(("/usr/bin/python3 " + script.string() + " " + a.string() + " " +
                                b.string() + " " + kind)
                                   .c_str());
    CHECK(rc == 0);
  }
}

// A grid that cannot be computed in --time-limit is refused before any cell is computed: 1e11
// cells cannot be done in 60 s at any speed the estimate could measure (that would be 1.7e9
// cells/s), a refusal that does not depend on how loaded the machine is. (A grid whose output
// would not fit the free disk: rate_problem.test_map_disk_refusal, with the free disk injected.)
TEST_CASE("CliGridMapOverTheTimeLimitIsRefused", "[cli][map]") {
  const fs::path prefix = scratch_dir() / "huge";
  const Run t = run("map --preset fig5b --kind param-direction --param mu --from 0.1 --to 4 "
                    "--n 100000 --theta-n 1000000 --time-limit 60 --out " + prefix.string());
  CHECK(t.code == 2);
  CHECK(t.err.find("--time-limit") != std::string::npos);
  CHECK(t.err.find("100000 x 1000000 cells") != std::string::npos);
  CHECK(t.out.empty());
  CHECK_FALSE(fs::exists(prefix.string() + "_count.npy"));
  CHECK_FALSE(fs::exists(prefix.string() + ".json"));
}

// A grid with an invalid row (A not positive definite from a12 = 1.0102 on) is refused, the
// message names the first invalid grid value, and no partial output is left behind.
TEST_CASE("CliGridMapWithAnInvalidRowLeavesNoFiles", "[cli][map]") {
  const fs::path prefix = scratch_dir() / "invalid_row";
  const Run r = run("map --preset fig5b --kind param-direction --param a12 --from 0.5 --to 1.5 "
                    "--n 50 --theta-n 10 --out " + prefix.string());
  CHECK(r.code == 2);
  // Grid values 0.5 + i / 49: the first with a12 >= 1 (det A <= 0) is i = 25, 1.0102...
  CHECK(r.err.find("a12 = 1.010204") != std::string::npos);
  for (const char* f : {"_count.npy", "_types.npy", "_x.npy", "_theta.npy", ".json"})
    CHECK_FALSE(fs::exists(prefix.string() + f));
}

TEST_CASE("CliMapRefusesUnknownAndInapplicableParametersNamingThem", "[cli][map][params]") {
  // One table of map parameters (map_parameter_table.hpp) for every kind of map: exit 2 and a
  // message naming the parameter, whichever kind meets it.
  const std::string sys2 = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/coupled_grazing_points.json";
  const std::string sys3 = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/elliptic_point_3d.json";
  struct Case {
    std::string args, named, why;
  };
  const Case cases[] = {
      {"--preset fig5b --kind param-direction --param nonsense --from 0 --to 1", "'nonsense'",
       "unknown"},
      {"--preset fig5b --kind param-direction --param coupling --from 0 --to 1", "'coupling'",
       "does not apply to one-point maps"},
      {"--preset fig5b --kind param-direction --param mu@1 --from 0 --to 1", "'mu@1'",
       "no point number"},
      {"--system '" + sys2 + "' --kind param-direction --param kappa --from 0 --to 1", "'kappa'",
       "does not apply to N-point maps"},
      {"--system '" + sys2 + "' --kind param-direction --param P_s@3 --from 1 --to 2", "'P_s@3'",
       "1..2"},
      {"--system '" + sys3 + "' --kind param-direction --param coupling --from 0 --to 1",
       "'coupling'", "does not apply to 3-D maps"},
  };
  for (const auto& c : cases) {
    CAPTURE(c.args);
    const Run r = run("map " + c.args);
    CHECK(r.code == 2);
    CHECK(r.err.find(c.named) != std::string::npos);
    CHECK(r.err.find(c.why) != std::string::npos);
  }
  // P_s of an N-point map is accepted: every value is the file's system with P_s set (k_a = 0
  // there, so the hardness changes nothing: every row equals the file's direction map).
  const Run ps = run("map --system '" + sys2 + "' --kind param-direction --param P_s@2 --from 0.5 "
                     "--to 2 --n 3 --theta-n 360 --json");
  REQUIRE(ps.code == 0);
  const Run dir = run("map --system '" + sys2 + "' --json");
  REQUIRE(dir.code == 0);
  const auto jp = nlohmann::json::parse(ps.out), jd = nlohmann::json::parse(dir.out);
  int64_t three = 0;
  for (const auto& c : jp.at("counts"))
    if (c.at("count") == 3) three += c.at("cells").get<int64_t>();
  // The exact sectors of the file's direction map: cell centres (j + 1/2) 2 pi / 360 inside a
  // sector of 3 solutions.
  const double kTwoPi = 6.283185307179586;
  int64_t expected = 0;
  for (int j = 0; j < 360; ++j) {
    const double t = (j + 0.5) * kTwoPi / 360;
    for (const auto& sec : jd.at("sectors"))
      if (sec.at("count") == 3 && t > sec.at("theta_from").get<double>() &&
          t < sec.at("theta_to").get<double>())
        ++expected;
  }
  CHECK(expected > 0);
  CHECK(three == 3 * expected);  // the same directions in each of the 3 rows
}
