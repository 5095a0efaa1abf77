// Options that never lie (a newcomer's first hour): bad input is exit 2 with a message in the
// user's words, options without effect are errors, integral numbers are integers, outputs create
// their folders and say what they wrote, a failed plot is a failure. Independent source: the
// rules of docs/conventions.md ("Command line") and hand-checked values.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <map>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "peer_skip.hpp"

namespace {

namespace fs = std::filesystem;
using cpkit::test::CliRun;
using cpkit::test::run_cpkit;
using cpkit::test::scratch_dir;
using cpkit::test::slurp;

const std::string kLcp = std::string(CPKIT_TEST_DATA_DIR) + "/lcp/battle_of_the_sexes.json";
const std::string kStep =
    "step --a11 1 --a12 0 --a22 1 --mu 0.5 --P_T0 0 --P_N0 1 --g0 0 --DF 0.1 0 ";

/// Exit 2, nothing on stdout, and stderr contains every one of `words`.
void bad(const std::string& args, std::initializer_list<std::string> words,
         std::initializer_list<std::string> not_words = {}) {
  const CliRun r = run_cpkit(args);
  CAPTURE(args, r.err, r.out);
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  for (const auto& w : words) CHECK(r.err.find(w) != std::string::npos);
  for (const auto& w : not_words) CHECK(r.err.find(w) == std::string::npos);
}

bool have_matplotlib() {
  return std::system("/usr/bin/python3 -c 'import matplotlib' > /dev/null 2>&1") == 0;
}

}  // namespace

TEST_CASE("unknown subcommands and options are named, before any 'required' complaint",
          "[cli][options]") {
  bad("foo", {"unknown subcommand 'foo'", "lcp", "simulate"});
  bad("", {"'cpkit' needs a subcommand: lcp, map, rate, step, simulate"});
  bad("lcp", {"'cpkit lcp' needs a subcommand: solve, enumerate, verify"});
  CHECK(run_cpkit("--help").code == 0);
  CHECK(run_cpkit("lcp --help").code == 0);
  CHECK(run_cpkit("--version").out.find("cpkit ") == 0);
  bad("lcp foo", {"unknown subcommand 'foo' for 'cpkit lcp'", "solve, enumerate, verify"});
  bad("step --bogus", {"unknown option --bogus", "cpkit step"}, {"--a11"});
  bad("lcp solve '" + kLcp + "' --bogus=3", {"unknown option --bogus"});
  // A negative number is a value, not an option.
  const CliRun r = run_cpkit(kStep.substr(0, kStep.find("--DF")) + "--DF -0.1 0");
  CHECK(r.code == 0);
}

TEST_CASE("library limits are reported with the option's name", "[cli][options]") {
  bad("lcp enumerate '" + kLcp + "' --max-size 65",
      {"--max-size must lie in [1, 64], got 65"}, {"EnumerationOptions", "::"});
  bad("lcp solve '" + kLcp + "' --time-limit 0", {"--time-limit"}, {"time_limit_s"});
  bad("lcp solve '" + kLcp + "' --max-iter -1", {"--max-iter"}, {"max_iterations"});
  bad("map --preset fig5b --kind param-direction --param mu --from 2 --to 1 --n 5",
      {"--from < --to"});
  bad("map --preset state-d-mu-kappa --n2 0", {"--n2 must be >= 1"});
}

TEST_CASE("an integral number written as 1e1 or 10.0 is an integer", "[cli][options]") {
  // --max-size 5e0 = 5 < n = 6 (not a game): the general engine declines and names the limit 5,
  // which proves the value was read as 5.
  const CliRun small = run_cpkit("lcp enumerate '" + std::string(CPKIT_TEST_DATA_DIR) +
                                 "/lcp/murty_exp_6.json' --max-size 5e0");
  CHECK(small.code == 5);
  CHECK(small.out.find("limit 5 (max_size, the CLI's --max-size") != std::string::npos);
  CHECK(run_cpkit("lcp enumerate '" + kLcp + "' --max-size 4.0").code == 0);
  for (const char* n : {"1e1", "10.0", "10", "1.0e+1"}) {
    CAPTURE(n);
    const CliRun r = run_cpkit("map --preset fig5b --kind param-direction --param a11 --from 0.5 "
                               "--to 2 --theta-n 8 --json --n " + std::string(n));
    REQUIRE(r.code == 0);
    CHECK(nlohmann::json::parse(r.out)["axis"]["n"] == 10);
  }
  bad("map --preset fig5b --kind param-direction --param a11 --from 0.5 --to 2 --n 10.5",
      {"--n", "not an integer"});
  bad("map --preset fig5b --kind param-direction --param a11 --from 0.5 --to 2 --n 1e10",
      {"--n", "out of range"});
}

TEST_CASE("a JSON LCP with a number beyond double is bad input", "[cli][options]") {
  const fs::path f = scratch_dir() / "big.json";
  std::ofstream(f) << R"({"M": [[1e400, 2], [3, 4]], "q": [1, 2]})";
  for (const char* cmd : {"lcp solve", "lcp enumerate", "lcp verify"})
    bad(std::string(cmd) + " '" + f.string() + "'", {"1e400"}, {"internal", "json.exception"});
}

TEST_CASE("a simulate config with a number beyond double or bad JSON: the user's words",
          "[cli][options]") {
  const fs::path f = scratch_dir() / "big_cfg.json";
  std::ofstream(f) << R"({"parameters": {"a11": 1e400, "a12": 0, "a22": 1, "mu": 0.5}})";
  bad("simulate --config '" + f.string() + "'", {"1e400", "outside the range of double"},
      {"json.exception"});
  const fs::path g = scratch_dir() / "broken_cfg.json";
  std::ofstream(g) << R"({"parameters": )";
  bad("simulate --config '" + g.string() + "'", {"not valid JSON"}, {"json.exception"});
}

TEST_CASE("options without effect in their context are errors", "[cli][options]") {
  bad("lcp solve '" + kLcp + "' --all-solvers --solver ipopt", {"--all-solvers", "--solver"});
  bad("lcp verify '" + kLcp + "' --skip foo", {"--skip", "foo"});
  bad(kStep + "--chain bogus", {"--chain", "bogus"});
  bad(kStep + "--all --chain lemke", {"--chain", "--all"});
  bad(kStep + "--k_M 0.1", {"--k_M", "--wear-law mroz"});
  bad(kStep + "--wear-law mroz", {"--wear-law mroz", "--k_M"});
  bad(kStep + "--wear-law mroz --k_M 0.1 --k_a 0.1", {"--k_a"});
  CHECK(run_cpkit(kStep + "--wear-law mroz --k_M 0.1").code == 0);
  const std::string sim = "simulate --a11 1 --a12 0 --a22 1 --mu 0.5 --load ramp --F_N1 1 --steps 4 ";
  bad(sim + "--k_M 0.1", {"k_M", "mroz"});
  bad(sim + "--wear-law mroz", {"mroz", "k_M"});
  // map: no hidden default model; axes only where the kind has them; state-dependent options.
  bad("map", {"needs a model", "--preset", "--a11"});
  bad("map --a11 1 --a12 0.5 --a22 1", {"missing: --mu"});
  bad("map --preset fig5b --kind direction --param mu --from 0 --to 1", {"--param", "direction"});
  bad("map --preset fig5b --kind param-direction --param mu --from 0 --to 1 --param2 a11 "
      "--from2 1 --to2 2",
      {"--param2"});
  bad("map --preset fig5b --P_N 1", {"--P_N", "state b"});
  bad("map --preset fig5b --sgnPT -1", {"--sgnPT", "state d"});
  bad("map --preset fig5b --kind param-direction --param mu --from 0.5 --to 2 --mu 3",
      {"--mu", "axis"});
  bad("map --preset fig5b --out ''", {"--out"});
  bad("map --preset fig5b --threads 4", {"--threads", "direction"});
  const std::string rate = "rate --a11 1 --a12 0.5 --a22 1 --mu 3 --dF 1 1 ";
  bad(rate + "--state b --sgnPT -1", {"--sgnPT", "state b"});
  // --k_a in state b: accepted with a note (issue 27; test_cli_names_defaults.cpp).
  CHECK(run_cpkit(rate + "--state b --k_a 1").code == 0);
  CHECK(run_cpkit(rate + "--state d --P_N 1 --sgnPT -1 --k_a 0.1").code == 0);
  bad("lcp solve '" + kLcp + "' --all-solvers --trace", {"--trace", "--json"});
  // simulate: options of another load type, heat options without --heat.
  const std::string base = "simulate --a11 1 --a12 0 --a22 1 --mu 0.5 ";
  bad(base + "--steps 10", {"--steps", "--load ramp", "fretting"});
  bad(base + "--load ramp --cycles 3", {"--cycles", "--load fretting"});
  bad(base + "--load ramp --period 2", {"--period"});
  bad(base + "--T-body 300 300", {"--T-body", "--heat"});
  bad(base + "--T-ref 300", {"--T-ref", "--heat"});
  CHECK(run_cpkit(base + "--heat --T-body 300 300 --conductance 0.1 0.1 --cycles 1").code == 0);
}

TEST_CASE("map summary: an open interval, as the sectors", "[cli][map]") {
  const CliRun r = run_cpkit("map --preset fig5b");
  REQUIRE(r.code == 0);
  // Sector (0.3514, 0.4636) has 3 solutions; its ends (L+ = 0, N = 0) have 2 each.
  CHECK(r.out.find("summary: 3 solutions for theta in (0.35, 0.46)") != std::string::npos);
  CHECK(r.out.find("0.3514 (L+=0)  2 solutions") != std::string::npos);
  CHECK(r.out.find("0.4636 (N=0)  2 solutions") != std::string::npos);
}

TEST_CASE("param-param: no solution for some directions and several for others is named",
          "[cli][map]") {
  // State d, kappa = 0.5 (preset state-d-mu-kappa): Lambda = 1.25 - 1.09375 mu, eqn (51), so
  // mu = 2 gives Lambda < 0 (two solutions where L_+ < 0, none where L_+ > 0), mu = 0.5 > 0.
  const CliRun r = run_cpkit("map --preset state-d-mu-kappa --param mu --from 0.5 --to 2 --n 2 "
                             "--param2 kappa --from2 0.5 --to2 0.5 --n2 1 --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  std::map<std::string, int> cells;
  for (const auto& c : j["classes"]) cells[c["class"]] = c["cells"];
  CHECK(cells["unique"] == 1);
  CHECK(cells["none-and-several"] == 1);
  CHECK(cells.count("no-solution") == 0);
}

TEST_CASE("simulate creates the --plot folder, names what it wrote, a failed plot fails",
          "[cli][simulate]") {
  const std::string sim = "simulate --a11 1 --a12 0 --a22 1 --mu 0.5 --load ramp --F_N1 1 --steps 4 ";
  const fs::path dir = scratch_dir() / "new" / "folder";
  const std::string prefix = (dir / "x").string();
  if (have_matplotlib()) {
    const CliRun r = run_cpkit(sim + "--plot '" + prefix + "'");
    CAPTURE(r.err);
    REQUIRE(r.code == 0);
    for (const char* f : {".csv", ".json", "_loop.png", "_wear.svg", "_state.png"}) {
      CHECK(fs::exists(prefix + f));
      CHECK(r.err.find("cpkit simulate: wrote " + prefix + f) != std::string::npos);
    }
  } else {
    CPKIT_SKIP_CHECK("the figures: /usr/bin/python3 has no matplotlib");
  }
  // A plotting program that fails: exit 4 and a message, the data still written and named.
  const fs::path dir2 = scratch_dir() / "failing";
  setenv("CPKIT_PYTHON", "/bin/false", 1);
  const CliRun r = run_cpkit(sim + "--plot '" + (dir2 / "y").string() + "'");
  unsetenv("CPKIT_PYTHON");
  CAPTURE(r.err);
  CHECK(r.code == 4);
  CHECK(r.err.find("the plot script failed") != std::string::npos);
  CHECK(fs::exists(dir2 / "y.csv"));
  CHECK(r.err.find("wrote " + (dir2 / "y.csv").string()) != std::string::npos);
}

TEST_CASE("simulate: paths in a config file are relative to the config file", "[cli][simulate]") {
  const fs::path dir = scratch_dir() / "cfg";
  fs::create_directories(dir);
  std::ofstream(dir / "load.csv") << "t,F_T,F_N\n0,0,0\n1,0,1\n2,0.1,1\n";
  std::ofstream(dir / "run.json")
      << R"({"parameters": {"a11": 1, "a12": 0, "a22": 1, "mu": 0.5},
            "load": {"type": "csv", "file": "load.csv"},
            "output": {"csv": "res/series.csv", "summary": "res/summary.json"}})";
  // Run from another folder: both the load and the outputs resolve against the config's folder.
  const CliRun r = run_cpkit("simulate --config '" + (dir / "run.json").string() + "'");
  CAPTURE(r.err);
  REQUIRE(r.code == 0);
  CHECK(fs::exists(dir / "res" / "series.csv"));
  CHECK(fs::exists(dir / "res" / "summary.json"));
  // The summary alone reproduces the run: settings, version, command.
  const auto s = nlohmann::json::parse(slurp(dir / "res" / "summary.json"));
  CHECK(s["settings"]["parameters"]["mu"] == 0.5);
  CHECK(s["settings"]["load"]["type"] == "csv");
  CHECK(s["run"]["cpkit_version"].is_string());
  CHECK(s["run"]["command"][0] == "simulate");
}

TEST_CASE("--theta-from/--theta-to zoom a param-direction map on a thin band", "[cli][map]") {
  // Fig. 5(b) model (a11 = 1, a12 = 0.5, C_T = 0.25, mu = 3): three solutions exactly between
  // L_+ = 0, tan theta = (1 + mu a12 C_T) / (mu (1 + a11 C_T)) = 1.375 / 3.75, and N = 0,
  // tan theta = a12 / a11 (docs/model.md Sec. 2.2): a wedge of 6.4 degrees.
  const double lo = std::atan(1.375 / 3.75), hi = std::atan(0.5);
  const double from = 0.3, to = 0.5;
  const int n = 1000;
  int expected = 0;  // cell centres strictly inside the wedge
  for (int j = 0; j < n; ++j) {
    const double t = from + (j + 0.5) * (to - from) / n;
    expected += t > lo && t < hi;
  }
  const CliRun r = run_cpkit("map --preset fig5b --kind param-direction --param C_T --from 0.25 "
                             "--to 0.25 --n 1 --theta-n 1000 --theta-from 0.3 --theta-to 0.5 --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["theta_from"] == from);
  CHECK(j["theta_to"] == to);
  int three = 0;
  for (const auto& c : j["classes"])
    if (c["count"] == 3) {
      three = c["cells"];
      CHECK(c["theta_min"].get<double>() > lo);
      CHECK(c["theta_max"].get<double>() < hi);
    }
  CHECK(three == expected);
  bad("map --preset fig5b --theta-from 0.3", {"--theta-from", "param-direction"});
  bad("map --preset fig5b --kind param-direction --param C_T --from 0 --to 1 --theta-from 1 "
      "--theta-to 0.5",
      {"--theta-from", "--theta-to"});
}
