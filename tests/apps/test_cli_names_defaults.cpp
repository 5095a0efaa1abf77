// Names, defaults and limits of the command line (issue 27): one spelling of the load increment
// (--dF, with --DF an accepted alias), every default that --help shows is the value used, the
// output limit of the maps (--max-output), material parameters accepted where they do not enter
// a state's equations, and the default `cpkit step` saying how many solutions it chose from.
// Independent sources: a run with the option given explicitly at the shown default (same result
// as without it), the issue's and docs/simulation.md's hand-stated three solutions of the step,
// the `--all` listing (a second route), and sizes counted by hand.
#include <catch2/catch.hpp>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace {

using cpkit::test::CliRun;
using cpkit::test::run_cpkit;
using cpkit::test::scratch_dir;
using nlohmann::json;

const std::string kExamples = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/";

/// The result without what may differ between two runs of the same computation: the run echo
/// (command line), timings and the up-front estimate (timed).
json stripped(json j) {
  if (j.is_object()) {
    for (const char* k : {"run", "seconds", "estimate"}) j.erase(k);
    for (auto& [k, v] : j.items()) v = stripped(v);
  } else if (j.is_array()) {
    for (auto& v : j) v = stripped(v);
  }
  return j;
}

json parsed(const CliRun& r) {
  INFO(r.err);
  REQUIRE(r.code == 0);
  return json::parse(r.out);
}

struct HelpDefault {
  std::string option, value;
};

/// The options of `cpkit <command> --help` that show a default (`--name TYPE=VALUE`).
std::vector<HelpDefault> help_defaults(const std::string& command) {
  const CliRun h = run_cpkit(command + " --help");
  REQUIRE(h.code == 0);
  std::vector<HelpDefault> out;
  const std::regex line(R"(^\s+(--[A-Za-z0-9_-]+)\s+[A-Z]+=(\S+))");
  std::istringstream in(h.out);
  for (std::string l; std::getline(in, l);) {
    std::smatch m;
    if (std::regex_search(l, m, line)) out.push_back({m[1], m[2]});
  }
  return out;
}

/// The echo of a default in "run"."options": numbers as numbers, words as words.
bool echo_matches(const json& echoed, const std::string& shown) {
  if (echoed.is_number()) return std::stod(shown) == echoed.get<double>();
  if (echoed.is_string()) return echoed.get<std::string>() == shown;
  return false;
}

/// For each default shown by `command --help`: the first of `bases` (none of which gives the
/// option) that takes the option explicitly at that value computes the same result as without
/// it, and its run echo shows that value. Every shown default must be taken by some base.
void check_help_defaults(const std::string& command, const std::vector<std::string>& bases) {
  const auto defaults = help_defaults(command);
  CAPTURE(command);
  CHECK_FALSE(defaults.empty());
  std::vector<json> plain;
  for (const auto& b : bases) plain.push_back(parsed(run_cpkit(b + " --json")));
  for (const auto& d : defaults) {
    CAPTURE(d.option, d.value);
    bool checked = false;
    for (std::size_t k = 0; k < bases.size() && !checked; ++k) {
      REQUIRE(bases[k].find(d.option + " ") == std::string::npos);  // not given by the base
      const CliRun explicit_run =
          run_cpkit(bases[k] + " " + d.option + " " + d.value + " --json");
      if (explicit_run.code != 0) continue;  // the option belongs to another mode
      CAPTURE(bases[k]);
      const json& options = plain[k]["run"]["options"];
      const std::string key = d.option.substr(2);
      REQUIRE(options.contains(key));
      CHECK(echo_matches(options[key], d.value));
      CHECK(stripped(json::parse(explicit_run.out)) == stripped(plain[k]));
      checked = true;
    }
    CHECK(checked);
  }
}

}  // namespace

TEST_CASE("--help shows only the defaults that are used", "[cli][options][help]") {
  // Issue 27: map showed --n INT=0 (200 used), --P_s FLOAT=0 (1 used), --others TEXT=zero.
  const std::string model = "--a11 1 --a12 0.5 --a22 1 ";
  check_help_defaults("rate", {"rate --state b " + model + "--mu 3 --dF 1 1",
                               "rate --state d " + model + "--mu 3 --P_N 1 --dF 1 1"});
  check_help_defaults("step", {"step " + model + "--mu 2 --P_T0 0.5 --P_N0 1 --g0 0 --dF 0.1 0.2"});
  const std::string out = (scratch_dir() / "help_defaults").string();
  check_help_defaults(
      "map", {"map --kind param-direction --state d " + model +
                  "--P_N 1 --param mu --from 0.5 --to 1.5 --n 3",
              "map --system " + kExamples + "sphere_point_3d.json --kind param-direction --param "
                  "mu --from 0.5 --to 1 --n 2 --theta-n 4",
              // --format applies with --out only (the same prefix each run: it is overwritten).
              "map --kind param-direction " + model + "--mu 1 --param C_T --from 0 --to 1 --n 2 "
                  "--theta-n 4 --out " + out + "/a"});
  const std::string lcp = std::string(CPKIT_TEST_DATA_DIR) + "/siconos/lcp_deudeu.dat";
  for (const char* sub : {"lcp solve", "lcp enumerate", "lcp verify"})
    check_help_defaults(sub, {std::string(sub) + " '" + lcp + "'"});
  // simulate takes its defaults from the config file or the documented model: it shows none.
  CHECK(help_defaults("simulate").empty());
  // The defaults that were wrong: now the value used, or none shown.
  for (const auto& d : help_defaults("map")) {
    CAPTURE(d.option);
    CHECK(d.option != "--n");
    CHECK(d.option != "--n2");
    CHECK(d.option != "--others");
    if (d.option == "--P_s") CHECK(d.value == "1");
  }
}

TEST_CASE("--dF is the load increment of rate and step; --DF stays an alias", "[cli][options]") {
  const std::string step = "step --a11 1 --a12 0.9 --a22 1 --mu 2 --P_T0 2 --P_N0 1 --g0 0 ";
  const std::string rate = "rate --state b --a11 1 --a12 0.5 --a22 1 --mu 3 ";
  for (const std::string& base : {step, rate}) {
    const json lower = parsed(run_cpkit(base + "--dF -0.01 0.02 --json"));
    const json upper = parsed(run_cpkit(base + "--DF -0.01 0.02 --json"));
    CHECK(stripped(lower) == stripped(upper));
    CHECK(lower["run"]["options"]["dF"] == json::array({-0.01, 0.02}));
    CHECK(upper["run"]["options"]["dF"] == json::array({-0.01, 0.02}));
    // --DF=... and --dF=... forms too.
    CHECK(run_cpkit(base + "--DF=-0.01 --DF=0.02").code == 0);
    // The help shows one spelling.
    const CliRun h = run_cpkit(base.substr(0, 4) + " --help");
    CHECK(std::regex_search(h.out, std::regex(R"(\n\s+--dF )")));
    CHECK_FALSE(std::regex_search(h.out, std::regex(R"(\n\s+--DF)")));
  }
  // Both at once is one option given twice: its values are the 4 numbers, refused for a point.
  const CliRun both = run_cpkit(step + "--dF -0.01 0 --DF 0.1 0");
  CHECK(both.code == 2);
  CHECK(both.err.find("--dF") != std::string::npos);
  // Commands without a load increment do not take either spelling.
  for (const char* c : {"map --preset fig5b --DF 1 1", "simulate --DF 1 1"}) {
    const CliRun r = run_cpkit(c);
    CHECK(r.code == 2);
    CHECK(r.err.find("unknown option --DF") != std::string::npos);
  }
}

TEST_CASE("map --max-output refuses an output above the limit up front", "[cli][map]") {
  const std::string out = (scratch_dir() / "max_output" / "m").string();
  const std::string grid = "map --preset fig5b --kind param-direction --param mu --from 0.5 "
                           "--to 3 --n 4 --theta-n 100 --out '" + out + "'";
  // 4 x 100 cells: two bytes each (count, types) and the same again in the checkpoint, the axes:
  // about 2.5 KiB by hand, above 1K, far below 1M.
  const CliRun small = run_cpkit(grid + " --max-output 1K");
  CHECK(small.code == 2);
  CHECK(small.out.empty());
  CHECK(small.err.find("--max-output 1 KiB") != std::string::npos);
  CHECK(small.err.find("KiB (estimated)") != std::string::npos);
  CHECK(run_cpkit(grid + " --max-output 1M").code == 0);
  CHECK(run_cpkit(grid + " --max-output 0.5m --json").code == 0);
  // The issue's map: 1e5 x 1e5 cells, ~37 GiB: refused by the default limit (4 GiB), at once.
  const CliRun huge = run_cpkit("map --preset fig5b --kind param-direction --param mu --from 0.5 "
                                "--to 3 --n 100000 --theta-n 100000 --time-limit 1e9 --out '" +
                                out + "_huge'");
  CHECK(huge.code == 2);
  CHECK(huge.err.find("more than --max-output 4 GiB") != std::string::npos);
  // N-point and 3-D maps have the same limit.
  const CliRun sys = run_cpkit("map --system " + kExamples +
                               "two_point_system.json --kind param-direction --param mu --from 1 "
                               "--to 2 --n 5 --theta-n 50 --max-output 100 --out '" + out + "_s'");
  CHECK(sys.code == 2);
  CHECK(sys.err.find("--max-output 100 B") != std::string::npos);
  const CliRun s3 = run_cpkit("map --system " + kExamples +
                              "sphere_point_3d.json --kind sphere --n 3 --n2 4 --max-output 1K "
                              "--out '" + out + "_3'");
  CHECK(s3.code == 2);
  CHECK(s3.err.find("--max-output 1 KiB") != std::string::npos);
  // Sizes that are not sizes.
  for (const char* bad : {"10X", "0", "-1G", "G", "1e400", "0x10", "inf"}) {
    const CliRun r = run_cpkit(grid + " --max-output " + bad);
    CAPTURE(bad, r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find("--max-output") != std::string::npos);
  }
}

TEST_CASE("material parameters that do not enter a state are accepted and echoed",
          "[cli][options]") {
  const std::string model = "--a11 1 --a12 0.5 --a22 1 --mu 3 ";
  for (const char* st : {"a", "b"}) {
    const std::string rate = std::string("rate --state ") + st + " " + model + "--dF 1 1 --json";
    const CliRun r = run_cpkit(rate + " --k_a 0.2 --P_s 3");
    CAPTURE(st, r.err);
    REQUIRE(r.code == 0);
    CHECK(r.err.find("note: --k_a does not enter state") != std::string::npos);
    const json j = json::parse(r.out);
    CHECK(j["run"]["options"]["k_a"] == 0.2);
    CHECK(j["run"]["options"]["P_s"] == 3);
    // They do not change the answer of that state.
    CHECK(stripped(j) == stripped(parsed(run_cpkit(rate))));
    // ... but are still checked.
    const CliRun neg = run_cpkit(rate + " --P_s -1");
    CHECK(neg.code == 2);
  }
  const CliRun m = run_cpkit("map --preset fig5b --k_a 0.3 --P_s 2 --json");
  REQUIRE(m.code == 0);
  CHECK(m.err.find("note: --k_a does not enter state b") != std::string::npos);
  const json jm = json::parse(m.out);
  CHECK(jm["model"]["k_a"] == 0.3);
  CHECK(jm["model"]["P_s"] == 2);
  // Conflicts and options without any effect stay errors.
  const CliRun conflict = run_cpkit("map --preset fig5b --kind param-direction --param mu --from "
                                    "0.5 --to 2 --mu 3");
  CHECK(conflict.code == 2);
  CHECK(conflict.err.find("--mu has no effect") != std::string::npos);
  const CliRun threads = run_cpkit("map --preset fig5b --threads 4");
  CHECK(threads.code == 2);
  CHECK(threads.err.find("--threads") != std::string::npos);
  const CliRun pn = run_cpkit("map --preset fig5b --P_N 1");
  CHECK(pn.code == 2);
}

TEST_CASE("default cpkit step says how many solutions it chose from", "[cli][step]") {
  // docs/simulation.md and issue 27: this step has three solutions (separation, stick, slip+);
  // the default answer picks the one closest to the start state (stick).
  const std::string step =
      "step --a11 1 --a12 0.9 --a22 1 --mu 2 --P_T0 2 --P_N0 1 --g0 0 --dF -0.01 0";
  const CliRun text = run_cpkit(step);
  REQUIRE(text.code == 0);
  CHECK(text.out.find("1 of 3 solutions; --all lists them") != std::string::npos);
  const json j = parsed(run_cpkit(step + " --json"));
  CHECK(j["solutions_found"] == 3);
  CHECK(j["listed"] == 1);
  CHECK(j["enumeration_complete"] == true);
  CHECK(j["type"] == "stick");
  CHECK(j["status"] == "solved");  // the existing fields stay
  const json all = parsed(run_cpkit(step + " --all --json"));
  CHECK(all["count"] == 3);
  // A step with one solution, counted by the --all route.
  const std::string one =
      "step --a11 1 --a12 0 --a22 1 --mu 0.5 --P_T0 0 --P_N0 1 --g0 0 --dF 0.1 0";
  const json j1 = parsed(run_cpkit(one + " --json"));
  CHECK(j1["solutions_found"] == parsed(run_cpkit(one + " --all --json"))["count"]);
  CHECK(run_cpkit(one).out.find("1 of " + j1["solutions_found"].dump() + " solution") !=
        std::string::npos);
  // A chain without the enumeration does not claim a count.
  const json lemke = parsed(run_cpkit(step + " --chain lemke --json"));
  CHECK_FALSE(lemke.contains("solutions_found"));
}
