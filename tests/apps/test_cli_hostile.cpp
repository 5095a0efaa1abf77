// Hostile and extreme command-line input (issue 11, sec. 5): no input may run code, crash the
// program (exit 4 = internal error) or be silently converted. Every case expects exit 2 with a
// message naming the problem and nothing on stdout, unless stated otherwise. Runs the binary.
#include <catch2/catch.hpp>

#include "cli_runner.hpp"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Run = cpkit::test::CliRun;
using cpkit::test::run_cpkit;
using cpkit::test::scratch_dir;

const std::string kModel = "--a11 1 --a12 0.3 --a22 1 --mu 0.5 ";
// The model of a map whose axis is mu (--mu as well would have no effect: an error).
const std::string kModelMuAxis = "--a11 1 --a12 0.3 --a22 1 ";

void expect_bad_input(const std::string& args, const std::string& must_name) {
  const Run r = run_cpkit(args);
  CAPTURE(args, r.err, r.out);
  CHECK(r.code == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find(must_name) != std::string::npos);
}

std::string write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

}  // namespace

TEST_CASE("simulate: a plot path from a config file is data, never shell code",
          "[cli][simulate][hostile]") {
  const fs::path dir = scratch_dir() / "inject";
  fs::create_directories(dir);
  const fs::path marker = dir / "PWNED";
  // The issue's path: "out/x'; touch FILE; echo '". Under a shell this runs `touch FILE`.
  const std::string evil = (dir / "x").string() + "'; touch " + marker.string() + "; echo '";
  const nlohmann::json cfg = {
      {"parameters", {{"a11", 1}, {"a12", 0.3}, {"a22", 1}, {"mu", 0.5}}},
      {"load", {{"type", "ramp"}, {"F_N1", 1}, {"F_T1", 0.2}, {"steps", 5}}},
      {"output", {{"plot", evil}}}};
  const std::string cfg_path = write(dir / "evil.json", cfg.dump());
  const Run r = run_cpkit("simulate --config '" + cfg_path + "'");
  INFO(r.err);
  CHECK(r.code == 0);  // the run completes (the plot itself may fail without matplotlib)
  CHECK_FALSE(fs::exists(marker));
  // The data files carry the odd name literally.
  CHECK(fs::exists(evil + ".csv"));
  CHECK(fs::exists(evil + ".json"));
}

TEST_CASE("map: an --out prefix is data, never shell code", "[cli][map][hostile]") {
  const fs::path dir = scratch_dir() / "inject_map";
  fs::create_directories(dir);
  const fs::path marker = dir / "PWNED";
  const std::string evil = (dir / "m").string() + "'; touch " + marker.string() + "; echo '";
  // Double quotes for the test's own shell (the path has no $, `, " or \).
  const Run r = run_cpkit("map --kind direction --state b " + kModel + "--out \"" + evil +
                          "\" --plot");
  INFO(r.err);
  CHECK(r.code == 0);
  CHECK_FALSE(fs::exists(marker));
  CHECK(fs::exists(evil + ".json"));
}

TEST_CASE("simulate: config integers must be integers in range", "[cli][simulate][hostile]") {
  const fs::path dir = scratch_dir() / "cfg_ints";
  fs::create_directories(dir);
  const std::string params = R"("parameters": {"a11": 1, "a12": 0.3, "a22": 1, "mu": 0.5)";
  struct Case {
    std::string json, field;
  };
  const std::vector<Case> cases = {
      {"{" + params + "}, \"load\": {\"cycles\": 4294967297}}", "load.cycles"},
      {"{" + params + "}, \"load\": {\"cycles\": -4294967295}}", "load.cycles"},
      {"{" + params + "}, \"load\": {\"steps_per_cycle\": 18446744073709551615}}",
       "load.steps_per_cycle"},
      {"{" + params + "}, \"load\": {\"type\": \"ramp\", \"steps\": 2.5}}", "load.steps"},
      {"{" + params + ", \"criterion\": 1e300}}", "parameters.criterion"},
      {"{" + params + ", \"criterion\": 38.7}}", "parameters.criterion"},
      {"{" + params + ", \"criterion\": 36}}", "parameters.criterion"},
      {"{" + params + "}, \"output\": {\"every\": -1}}", "output.every"},
      {"{" + params + "}, \"output\": {\"every\": 1e300}}", "output.every"},
      {"{" + params + "}, \"heat\": {\"T_body\": [300, \"hot\"]}}", "heat.T_body[1]"},
      {"{" + params + "}, \"load\": {\"F_N\": 1e999}}", "beyond the range of double"},
      {"{\"name\": " + std::string(100, '[') + std::string(100, ']') + "}", "nests deeper"},
  };
  int k = 0;
  for (const auto& c : cases) {
    const std::string path = write(dir / ("c" + std::to_string(k++) + ".json"), c.json);
    expect_bad_input("simulate --config '" + path + "'", c.field);
  }
  // An integral value written as a float is an integer (1e2 steps = 100).
  const std::string ok = write(
      dir / "ok.json", "{" + params + "}, \"load\": {\"type\": \"ramp\", \"F_N1\": 1, \"steps\": 1e2}}");
  const Run r = run_cpkit("simulate --config '" + ok + "' --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(nlohmann::json::parse(r.out)["steps"] == 100);
}

TEST_CASE("sizes that pass one by one but not together are refused before allocating",
          "[cli][hostile]") {
  // 1e9 cycles x 1e9 steps = 1e18 load points (24 bytes each): refused with the size needed.
  expect_bad_input("simulate " + kModel + "--cycles 1e9 --steps-per-cycle 1e9", "would need about");
  // Invalid parameters are reported first, even with a huge load.
  expect_bad_input("simulate --a11 1 --a12 0.3 --a22 1 --mu -1 --cycles 1e9 --steps-per-cycle 1e9",
                   "mu");
  // 1e5 x 1e6 cells = 1e11 cells: refused by the time estimate. --time-limit 60 keeps the
  // refusal independent of the machine's load (1e11 cells in 60 s would be 1.7e9 cells/s),
  // where the default 600 s depends on how fast the timed sample happened to run.
  expect_bad_input("map --kind param-direction --state b " + kModelMuAxis +
                       "--param mu --from 0.1 --to 1 --n 100000 --theta-n 1000000 --time-limit 60",
                   "would need about");
  expect_bad_input("map --kind param-param --state b " + kModelMuAxis +
                       "--param mu --from 0.1 --to 1 --n 100000 --param2 C_T --from2 0 --to2 0.5 "
                       "--n2 100000 --time-limit 60",
                   "would need about");
}

TEST_CASE("empty, non-finite and malformed option values are refused by every subcommand",
          "[cli][hostile]") {
  const std::string lcp = std::string(CPKIT_TEST_DATA_DIR) + "/lcp/cps_4_qp.json";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"rate --state b --a11 1 --a12 \"\" --a22 1 --mu 0.5 --dF 1 1", "--a12"},
      {"rate --state b " + kModel + "--dF \"\" 1", "--dF"},
      {"rate --state b " + kModel + "--dF 1 inf", "--dF"},
      {"rate --state b " + kModel + "--dF 1 1e400", "--dF"},
      {"rate --state d " + kModel + "--P_N 1 --sgnPT \"\" --dF 1 1", "--sgnPT"},
      {"rate --state b " + kModel + "--C_T -nan --dF 1 1", "--C_T"},
      {"rate --state b " + kModel + "--C_T 1e-400 --dF 1 1", "underflows"},
      {"rate --state b " + kModel + "--C_T 0x1p-3 --dF 1 1", "not a decimal number"},
      {"rate --state b " + kModel + "--C_T \" 1\" --dF 1 1", "--C_T"},
      {"step " + kModel + "--P_T0 \"\" --P_N0 0 --g0 0 --DF 1 1", "--P_T0"},
      {"step " + kModel + "--P_T0 0 --P_N0 0 --g0 0 --DF 1 1 --k_M nan", "--k_M"},
      {"map --kind direction --state b --a11 1 --a12 \"\" --a22 1 --mu 0.5", "--a12"},
      {"map --kind param-direction --state b " + kModel + "--param mu --from 0.1 --to 1 --n \"\"",
       "--n"},
      {"map --kind param-direction --state b " + kModel + "--param a11 --from 0.1 --to 1 --n 12.5",
       "--n"},
      {"map --kind direction --state b " + kModel + "--threads 99999999999", "--threads"},
      {"simulate --a11 1 --a12 \"\" --a22 1 --mu 0.5", "--a12"},
      {"simulate " + kModel + "--every \"\"", "--every"},
      {"simulate " + kModel + "--every -1", "every"},
      {"simulate " + kModel + "--every 5", "no effect"},  // no --csv/--plot: no series to thin
      {"simulate " + kModel + "--F_N inf", "--F_N"},
      {"simulate " + kModel + "--T-body 300 nan --heat", "--T-body"},
      {"lcp solve '" + lcp + "' --tol \"\"", "--tol"},
      {"lcp solve '" + lcp + "' --max-iter \"\"", "--max-iter"},
      {"lcp solve '" + lcp + "' --time-limit nan", "--time-limit"},
      {"lcp enumerate '" + lcp + "' --time-limit \"\"", "--time-limit"},
      {"lcp enumerate '" + lcp + "' --max-size 0x10", "--max-size"},
      {"lcp verify '" + lcp + "' --time-limit \"\"", "--time-limit"},
      {"lcp solve \"\"", "FILE"},
  };
  for (const auto& [args, name] : cases) expect_bad_input(args, name);
  // A leading zero is decimal, not octal: --n 010 is 10 values.
  const Run r = run_cpkit("map --kind param-direction --state b " + kModelMuAxis +
                          "--param mu --from 0.1 --to 1 --n 010 --theta-n 8 --json");
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(nlohmann::json::parse(r.out)["axis"]["n"] == 10);
}

TEST_CASE("a file name that is not UTF-8 is no internal error", "[cli][hostile]") {
  // A .dat problem is named after its file's stem: "\xff\xfe" made JSON output throw (exit 4,
  // "internal error"). It is now written with U+FFFD in place of each bad byte.
  const fs::path dir = scratch_dir() / "utf8";
  fs::create_directories(dir);
  // Siconos' lcp_deudeu.dat (dense storage): M = [[2, 1], [1, 2]], q = (-5, -6).
  const std::string name = (dir / "\xff\xfe.dat").string();
  write(name, "2\n0\n2\n2\n2\t2\n 2 1\n 1 2\n -5 -6\n");
  for (const char* action : {"solve", "enumerate", "verify"}) {
    const Run r = run_cpkit(std::string("lcp ") + action + " '" + name + "' --json");
    CAPTURE(action, r.err);
    CHECK(r.code != 4);
    CHECK(r.err.find("internal error") == std::string::npos);
    if (r.code == 2) {  // a reader may reject the file; then with a message, nothing on stdout
      CHECK(r.out.empty());
      CHECK_FALSE(r.err.empty());
      continue;
    }
    const auto j = nlohmann::json::parse(r.out);  // throws on invalid UTF-8
    REQUIRE(j.contains("problem"));
    CHECK(j["problem"] == "\xef\xbf\xbd\xef\xbf\xbd");
  }
  // The same with a .json file (no name inside): solved, valid JSON.
  const std::string json_name = (dir / "\xff\xfe.json").string();
  write(json_name, R"({"M": [[2, 1], [1, 2]], "q": [-3, -3]})");
  const Run ok = run_cpkit("lcp solve '" + json_name + "' --json");
  CHECK(ok.code == 0);
  CHECK(nlohmann::json::parse(ok.out)["status"] == "solved");
  // A missing file with such a name is bad input (exit 2).
  const Run r = run_cpkit("lcp solve '" + (dir / "\xff-missing.json").string() + "' --json");
  CHECK(r.code == 2);
  CHECK(r.out.empty());
}

TEST_CASE("siblings: typos, meaningless tolerances, unwritable outputs, overflowing runs",
          "[cli][hostile]") {
  const std::string lcp = std::string(CPKIT_TEST_DATA_DIR) + "/lcp/cps_4_qp.json";
  // A misspelt solver name must not silently run (verify) or drop (step) a solver.
  expect_bad_input("lcp verify '" + lcp + "' --skip ipopd", "--skip: unknown solver 'ipopd'");
  expect_bad_input("step " + kModel + "--P_T0 0 --P_N0 0 --g0 0 --DF 1 1 --chain active-set,lemkee",
                   "--chain: unknown solver 'lemkee'");
  // A tolerance of 1e300 on the scaled residual would call any z solved.
  expect_bad_input("lcp solve '" + lcp + "' --tol 1e300", "--tol must be at most 1e-3");
  expect_bad_input("map --kind direction --state b " + kModel + "--threads 100000", "--threads");
  // Output that cannot be written is an error, not a silent success.
  if (fs::exists("/dev/full")) {
    expect_bad_input("simulate " + kModel + "--cycles 1 --csv /dev/full", "error writing");
    expect_bad_input("simulate " + kModel + "--cycles 1 --summary /dev/full", "error writing");
  }
  // Loads near 1e300: the energies overflow. The run stops honestly (exit 1,
  // numerical_failure) instead of "completed" with inf/NaN (null in JSON) in its results.
  const Run r = run_cpkit("simulate " + kModel + "--cycles 1 --amplitude 1e300 --F_N 1e300 --json");
  INFO(r.err);
  CHECK(r.code == 1);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["outcome"] == "numerical_failure");
  CHECK(r.out.find("null") == std::string::npos);
  for (const char* k : {"external_work", "stored", "dissipation", "balance_error_rel"})
    CHECK(j["energy"][k].is_number());
}
