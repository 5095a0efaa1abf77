// Hostile and extreme command-line input (issue 11, sec. 5): no input may run code, crash the
// program (exit 4 = internal error) or be silently converted. Every case expects exit 2 with a
// message naming the problem and nothing on stdout, unless stated otherwise. Runs the binary.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include "cli_runner.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
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
      {"{" + params + "}, \"load\": {\"F_N\": 1e999}}", "outside the range of double"},
      {"{\"name\": " + std::string(100, '[') + std::string(100, ']') + "}", "nesting deeper than 64"},
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

// ---- issue 24, items 13-16: the input readers and the limits around them ----

namespace {

const std::string kExamples = std::string(CPKIT_SOURCE_DIR) + "/docs/examples/";

/// `cpkit ARGS` run by bash (for `<(...)`, which /bin/sh lacks), bounded by `timeout`: a reader
/// that opened a pipe twice would wait forever for a second writer.
Run run_bash(const std::string& args) {
  const fs::path script = scratch_dir() / "run_bash.sh";
  const fs::path out = scratch_dir() / "bash_out.txt", err = scratch_dir() / "bash_err.txt";
  write(script, "exec timeout 60 '" + std::string(CPKIT_BINARY_DIR) + "/apps/cpkit' " + args +
                    " > '" + out.string() + "' 2> '" + err.string() + "'\n");
  const int status = std::system(("bash '" + script.string() + "'").c_str());
  Run r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = cpkit::test::slurp(out);
  r.err = cpkit::test::slurp(err);
  return r;
}

}  // namespace

TEST_CASE("a system file or an LCP given as a pipe is read once (item 13)", "[cli][hostile]") {
  struct Case {
    std::string command, file, rest;
  };
  const std::vector<Case> cases = {
      {"rate", kExamples + "elliptic_point_3d.json", "--json"},             // dim 3
      {"rate", kExamples + "two_point_system.json", "--json"},              // dim 2
      {"step", kExamples + "two_point_system.json", "--DF 0.1 0.2 0.1 0.3 --all --json"},
      {"step", kExamples + "elliptic_point_3d.json", "--DF 0.1 0.05 0.2 --all --json"}};
  for (const auto& c : cases) {
    CAPTURE(c.command, c.file);
    const Run file = run_cpkit(c.command + " --system '" + c.file + "' " + c.rest);
    const Run pipe = run_bash(c.command + " --system <(cat '" + c.file + "') " + c.rest);
    CAPTURE(file.err, pipe.err);
    REQUIRE(file.code == 0);
    CHECK(pipe.code == 0);
    // The same answer; only the file's name (echoed in "input") differs.
    auto jf = nlohmann::json::parse(file.out), jp = nlohmann::json::parse(pipe.out);
    for (auto* j : {&jf, &jp}) {
      j->erase("input");
      j->erase("run");
      j->erase("system");
    }
    CHECK(jf.dump() == jp.dump());
  }
  // An LCP file without an extension: the format is told by the content.
  const std::string lcp = std::string(CPKIT_TEST_DATA_DIR) + "/lcp/cps_4_qp.json";
  const Run json_pipe = run_bash("lcp solve <(cat '" + lcp + "') --json");
  INFO(json_pipe.err);
  CHECK(json_pipe.code == 0);
  CHECK(nlohmann::json::parse(json_pipe.out)["status"] == "solved");
  const Run garbage = run_bash("lcp solve <(echo 'hello') --json");
  CHECK(garbage.code == 2);
  CHECK(garbage.err.find("not a known problem format") != std::string::npos);
}

TEST_CASE("a broken 3-D system file is reported as such, not read as 2-D (item 13)",
          "[cli][hostile]") {
  const fs::path dir = scratch_dir() / "broken3d";
  fs::create_directories(dir);
  const std::string syntax = write(dir / "syntax.json", R"({"dim": 3, "A": [[1, 0, 0], )");
  const std::string tiny = write(
      dir / "tiny.json",
      R"({"dim": 3, "A": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "points": [{"state": "b", "mu": 1e-400}]})");
  const std::string dim = write(dir / "dim.json", R"({"dim": "3", "A": [[1]], "points": []})");
  for (const char* cmd : {"rate --system ", "step --DF 1 0 1 --all --system ",
                          "simulate --orbit 1 1 --system ", "map --system "}) {
    expect_bad_input(cmd + ("'" + syntax + "'"), "not valid JSON");
    expect_bad_input(cmd + ("'" + tiny + "'"), "'1e-400' is below the smallest double");
    expect_bad_input(cmd + ("'" + dim + "'"), "dim must be 2 (2-D points) or 3 (3-D points), got \"3\"");
  }
  // Valid JSON, wrong for 3-D: the 3-D reader's message (3N rows of T_X, T_Y, N; the 2-D
  // reader knows no such layout), from a file and from a pipe (read once, dimension kept).
  const std::string rows = write(
      dir / "rows.json", R"({"dim": 3, "A": [[1, 0], [0, 1]], "points": [{"state": "b", "mu": 1}]})");
  const std::string want = "A must be an array of 3N = 3 rows (T_X, T_Y, N per point)";
  for (const char* cmd : {"rate --system ", "step --DF 1 0 1 --all --system ",
                          "simulate --orbit 1 1 --system ", "map --kind sphere --system "}) {
    expect_bad_input(cmd + ("'" + rows + "'"), want);
    const Run pipe = run_bash(cmd + ("<(cat '" + rows + "')"));
    CAPTURE(cmd, pipe.err);
    CHECK(pipe.code == 2);
    CHECK(pipe.err.find(want) != std::string::npos);
  }
}

TEST_CASE("10^6 nested brackets in a system file or a checkpoint manifest: exit 2 (item 15)",
          "[cli][hostile]") {
  const fs::path dir = scratch_dir() / "deep";
  fs::create_directories(dir);
  const std::string deep = std::string(1'000'000, '[') + std::string(1'000'000, ']');
  const std::string f2 = write(dir / "deep2.json", "{\"A\": " + deep + "}");
  const std::string f3 = write(dir / "deep3.json", "{\"dim\": 3, \"A\": " + deep + "}");
  for (const std::string& f : {f2, f3}) {
    expect_bad_input("rate --system '" + f + "'", "nesting deeper than 64 levels");
    expect_bad_input("map --system '" + f + "'", "nesting deeper than 64 levels");
  }
  // A checkpoint whose manifest is 10^6 brackets deep (2 MB): --resume refuses it by its size
  // (a manifest is at most 1 MiB); 10^5 deep (200 kB): by its nesting, before any DOM exists.
  const fs::path prefix = dir / "map";
  fs::create_directories(prefix.string() + ".parts");
  const std::string resume = "map --system '" + kExamples + "coupled_grazing_points.json' --kind "
                             "param-direction --param coupling --from 0 --to 1 --n 2 --theta-n 8 "
                             "--threads 1 --out '" + prefix.string() + "' --resume";
  write(prefix.string() + ".parts/manifest.json", deep);
  expect_bad_input(resume, "more than the 1048576 a file of this map can have");
  write(prefix.string() + ".parts/manifest.json",
        std::string(100'000, '[') + std::string(100'000, ']'));
  expect_bad_input(resume, "nesting deeper than 64 levels");
}

TEST_CASE("load CSVs: strict decimals, no hexadecimal, no underflow to 0 (item 16)",
          "[cli][hostile]") {
  const fs::path dir = scratch_dir() / "csv";
  fs::create_directories(dir);
  struct Case {
    std::string rows, names;
  };
  const std::vector<Case> one_point = {
      {"t,F_T,F_N\n0.5,0,1\n1,0x1,1\n", "expected a number, got '0x1'"},
      {"0x1p-1,0,1\n1,0,1\n", "expected a number, got '0x1p-1'"},  // first line: not a header
      {"0.5,0,1\n1,1e-400,1\n", "'1e-400' is below the smallest double"},
      {"0.5,0,1\n1,0,1e400\n", "'1e400' is outside the range of double"},
      {"0.5,0,1\n1,inf,1\n", "'inf' is not a finite number"}};
  int k = 0;
  for (const auto& c : one_point) {
    const std::string f = write(dir / ("l" + std::to_string(k++) + ".csv"), c.rows);
    expect_bad_input("simulate " + kModel + "--load-csv '" + f + "'", c.names);
  }
  // The N-point load CSV (t and 2N forces per row) reads numbers the same way.
  const std::string sys = kExamples + "two_point_system.json";
  const std::string hex = write(dir / "n_hex.csv", "t,a,b,c,d\n1,0,0x10,0,1\n");
  expect_bad_input("simulate --system '" + sys + "' --load-csv '" + hex + "'", "got '0x10'");
  const std::string tiny = write(dir / "n_tiny.csv", "1,0,1e-400,0,1\n");
  expect_bad_input("simulate --system '" + sys + "' --load-csv '" + tiny + "'", "'1e-400' is below");
  // A config file refuses 1e-400 as a system file does.
  const std::string cfg = write(dir / "tiny.json", R"({"parameters": {"a11": 1, "a12": 0, "a22": 1, "mu": 1e-400}})");
  expect_bad_input("simulate --config '" + cfg + "'", "'1e-400' is below the smallest double");
}

TEST_CASE("multistart and simulation lengths have documented caps (item 16)", "[cli][hostile]") {
  const std::string p3 = kExamples + "elliptic_point_3d.json";
  expect_bad_input("step --system '" + p3 + "' --DF 0.1 0.05 0.2 --multistart 1000000000",
                   "--multistart = 1000000000 starts exceeds the cap of 10000");
  const std::string p6 = kExamples + "two_point_system_3d.json";
  expect_bad_input("step --system '" + p6 + "' --DF 0 0 1 0 0 1 --multistart 1000000000",
                   "exceeds the cap of 10000");
  expect_bad_input("simulate " + kModel + "--ramp-steps 1e9",
                   "the cap is 100000000 steps (kMaxSimulationSteps)");
  expect_bad_input("simulate " + kModel + "--load ramp --F_N1 1 --steps 1e9", "kMaxSimulationSteps");
  // N points and 3-D points: 0.1-0.2 ms a step, capped at 10^6 steps.
  expect_bad_input("simulate --system '" + kExamples + "fretting_point_3d.json' --orbit 1 1 "
                   "--cycles 1e6 --steps-per-cycle 1000",
                   "the cap is 1000000 steps (kMaxSystemSimulationSteps");
  expect_bad_input("simulate --system '" + kExamples + "two_point_system.json' --cycles 1e4 "
                   "--steps-per-cycle 1000",
                   "the cap is 1000000 steps (kMaxSystemSimulationSteps");
}

namespace {

/// Runs `cpkit ARGS...` without a shell and measures it: exit code (-1: a signal), peak
/// resident memory (kB, wait4's rusage of that one process) and wall seconds.
struct Measured {
  int code = -1;
  long peak_kb = 0;
  double seconds = 0;
  std::string err;
};
Measured run_measured(const std::vector<std::string>& args) {
  const fs::path err = scratch_dir() / "measured_err.txt";
  std::vector<std::string> argv = {std::string(CPKIT_BINARY_DIR) + "/apps/cpkit"};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> c;
  for (auto& a : argv) c.push_back(a.data());
  c.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen(err.c_str(), "w", stderr);
    execv(c[0], c.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  Measured m;
  if (pid > 0 && wait4(pid, &status, 0, &usage) == pid) {
    m.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    m.peak_kb = usage.ru_maxrss;
  }
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  m.err = cpkit::test::slurp(err);
  return m;
}

std::string hostile_fclib(const std::string& name) {
  return std::string(CPKIT_TEST_DATA_DIR) + "/fclib/hostile/" + name;
}

}  // namespace

TEST_CASE("fc: hostile FCLIB files are bad input naming the dataset, never a signal or exit 1 "
          "(issue 34: F4-05, F4-07)", "[cli][fc][hostile]") {
  // The READMEs' answers: exit 2 with the dataset named (exit 134/139 before: heap overflow in
  // libfclib; exit 1, "proved to have no solution", from libfclib's exit(1)).
  const std::pair<const char*, const char*> refused[] = {
      {"title_array.hdf5", "/fclib_local/info/title"},
      {"description_vlen_array.hdf5", "/fclib_local/info/description"},
      {"q_lzf.hdf5", "/fclib_local/vectors/q"},
      {"q_gzip_corrupt.hdf5", "/fclib_local/vectors/q"}};
  for (const auto& [file, dataset] : refused) {
    for (const char* command : {"fc solve", "fc solutions"}) {
      CAPTURE(file, command);
      const Run r = run_cpkit(std::string(command) + " '" + hostile_fclib(file) + "' --json");
      CAPTURE(r.err);
      CHECK(r.code == 2);
      CHECK(r.out.empty());
      CHECK(r.err.find(std::string("bad input: ") + hostile_fclib(file)) != std::string::npos);
      CHECK(r.err.find(dataset) != std::string::npos);
    }
  }
  // title_vlen.hdf5: the title read as the README says, "a vlen title" (a heap pointer's bytes
  // before); its valid 2-contact problem is solved or honestly not (0 or 5), never refused.
  const Run vlen = run_cpkit("fc solve '" + hostile_fclib("title_vlen.hdf5") + "' --json");
  INFO(vlen.err);
  CHECK((vlen.code == 0 || vlen.code == 5));
  CHECK(nlohmann::json::parse(vlen.out)["problem"] == "a vlen title");
  // The undamaged gzip file: 100 contacts, W = I, q = (-1, 0, 0): r = (1, 0, 0) per contact,
  // u = 0 (all in contact, stick), by hand.
  const Run ok = run_cpkit("fc solve '" + hostile_fclib("q_gzip_ok.hdf5") + "' --json");
  INFO(ok.err);
  REQUIRE(ok.code == 0);
  const auto j = nlohmann::json::parse(ok.out);
  REQUIRE(j["r"].size() == 300);
  for (int k = 0; k < 300; ++k) CHECK(j["r"][k].get<double>() == Approx(k % 3 == 0 ? 1 : 0).margin(1e-6));
}

TEST_CASE("fc: a file declaring more than it holds is refused at once, in little memory "
          "(issue 34: F4-11)", "[cli][fc][hostile]") {
  // amp.hdf5 (64 KB, 9e6 rows declared, 1 chunk in 8 written): 1.6 GB and 9.9 s before. The
  // README's bound: <= 10 s and <= 256 MB.
  const Measured m = run_measured({"fc", "solve", hostile_fclib("amp.hdf5"), "--time-limit", "2"});
  CAPTURE(m.err, m.seconds, m.peak_kb);
  CHECK(m.code == 2);
  CHECK(m.err.find("amp.hdf5") != std::string::npos);
  CHECK(m.seconds <= 10);
  CHECK(m.peak_kb > 0);
  CHECK(m.peak_kb <= 256 * 1024);
}

TEST_CASE("fc: a friction file given as a pipe or a FIFO is read once (issue 34: F4-10)",
          "[cli][fc][hostile]") {
  const std::string fclib = std::string(CPKIT_TEST_DATA_DIR) + "/fclib/";
  // The README's answer: solved as the regular file is ("empty file", exit 2, before).
  for (const std::string& f : {fclib + "local/FC3D_Example1.dat", fclib + "global/GFC3D_Example1.dat"}) {
    CAPTURE(f);
    const Run file = run_cpkit("fc solve '" + f + "' --json");
    const Run pipe = run_bash("fc solve <(cat '" + f + "') --json");
    CAPTURE(file.err, pipe.err);
    REQUIRE((file.code == 0 || file.code == 5));
    CHECK(pipe.code == file.code);
    auto jf = nlohmann::json::parse(file.out), jp = nlohmann::json::parse(pipe.out);
    for (auto* j : {&jf, &jp}) {
      j->erase("file");
      j->erase("problem");   // named after the file
      j->erase("run");       // echoes the file name
      j->erase("seconds");
      j->erase("attempts");  // each with its seconds
    }
    CHECK(jf.dump() == jp.dump());
  }
  // A named FIFO whose writer goes away after writing: read, not blocked forever (timeout's
  // exit 124 before).
  const fs::path dir = scratch_dir() / "fifo";
  fs::create_directories(dir);
  const fs::path fifo = dir / "p.dat";
  const fs::path script = dir / "fifo.sh";
  write(script, "mkfifo '" + fifo.string() + "' && (cat '" + fclib + "local/FC3D_Example1.dat' > '" +
                    fifo.string() + "' &) && exec timeout 20 '" + CPKIT_BINARY_DIR +
                    "/apps/cpkit' fc solve '" + fifo.string() + "' > /dev/null 2>&1\n");
  const int status = std::system(("bash '" + script.string() + "'").c_str());
  REQUIRE(WIFEXITED(status));
  CHECK((WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == 5));
  // HDF5 needs to seek: an FCLIB file through a pipe is refused with a true message.
  const Run h5 = run_bash("fc solve <(cat '" + fclib + "local/Capsules-i125-1213.hdf5')");
  CHECK(h5.code == 2);
  CHECK(h5.err.find("pipe or FIFO") != std::string::npos);
}
