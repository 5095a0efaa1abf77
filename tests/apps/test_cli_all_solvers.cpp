// `cpkit lcp solve FILE --solver ipopt|nlopt|auto` and `--all-solvers`: runs the built binary;
// checks exit codes, that JSON output is clean (Ipopt never writes to stdout) and that every
// verified answer is a solution of the file's LCP (recomputed here from the file's data).
#include <catch2/catch.hpp>

#include "cli_runner.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

using Run = cpkit::test::CliRun;
using cpkit::test::scratch_dir;
using cpkit::test::slurp;

Run run_cli(const std::string& args) { return cpkit::test::run_cpkit(args); }

std::string path(const std::string& name) {
  return std::string(CPKIT_TEST_DATA_DIR) + "/lcp/" + name + ".json";
}

/// z >= 0, w = M z + q >= 0, z.w = 0 to 1e-9 (relative), from the file's M and q.
bool solves_file(const std::string& name, const nlohmann::json& z) {
  const auto j = nlohmann::json::parse(slurp(path(name)));
  const auto& M = j.at("M");
  const auto& q = j.at("q");
  for (std::size_t i = 0; i < q.size(); ++i) {
    double w = q[i].get<double>();
    for (std::size_t k = 0; k < q.size(); ++k) w += M[i][k].get<double>() * z[k].get<double>();
    const double zi = z[i].get<double>();
    if (zi < -1e-9 || w < -1e-9 || std::abs(std::min(zi, w)) > 1e-9) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("cpkit lcp solve --solver ipopt|nlopt|auto on battle_of_the_sexes", "[cli][mpcc]") {
  const std::string solver = GENERATE(as<std::string>{}, "ipopt", "nlopt", "auto");
  CAPTURE(solver);
  const Run r = run_cli("lcp solve '" + path("battle_of_the_sexes") + "' --solver " + solver +
                      " --json");
  INFO(r.err);
  CHECK(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);  // throws if anything else reached stdout
  CHECK(j.at("status") == "solved");
  CHECK(solves_file("battle_of_the_sexes", j.at("z")));
  if (solver == "auto") {
    CHECK(j.at("attempts").at(0).at("solver") == "lemke");
    CHECK(j.at("attempts").at(0).at("status") == "ray_termination");
  }
}

TEST_CASE("cpkit lcp solve --all-solvers lists every solver side by side", "[cli][mpcc]") {
  SECTION("JSON: one object, its results one object per registered solver") {
    const Run r = run_cli("lcp solve '" + path("battle_of_the_sexes") + "' --all-solvers --json");
    CHECK(r.code == 0);
    const auto out = nlohmann::json::parse(r.out);
    REQUIRE(out.is_object());  // README: "With --json, stdout is one JSON object"
    CHECK(out.at("n") == 4);
    CHECK(out.at("solved_by_any") == true);
    const auto& arr = out.at("results");
    REQUIRE(arr.is_array());
    std::vector<std::string> entries;
    for (const auto& o : arr) {
      entries.push_back(o.at("entry"));
      if (o.at("status") == "solved") CHECK(solves_file("battle_of_the_sexes", o.at("z")));
    }
    for (const char* name : {"lemke", "fb-newton", "ipopt", "nlopt", "auto"})
      CHECK(std::find(entries.begin(), entries.end(), name) != entries.end());
  }
  SECTION("infeasible problem: exit 1, nobody solved") {
    const Run r = run_cli("lcp solve '" + path("pang_isolated_perturbed") +
                        "' --all-solvers --json");
    CHECK(r.code == 1);
    const auto out = nlohmann::json::parse(r.out);
    CHECK(out.at("solved_by_any") == false);
    for (const auto& o : out.at("results")) {
      CAPTURE(o.at("entry"));
      CHECK(o.at("status") != "solved");
      CHECK(o.at("status") != "solved_inaccurate");
    }
  }
  SECTION("--solver with --all-solvers would have no effect: bad input naming both") {
    const Run r = run_cli("lcp solve '" + path("deudeu") + "' --all-solvers --solver ipopt");
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find("--all-solvers") != std::string::npos);
    CHECK(r.err.find("--solver") != std::string::npos);
  }
  SECTION("text table") {
    const Run r = run_cli("lcp solve '" + path("deudeu") + "' --all-solvers");
    CHECK(r.code == 0);
    CHECK(r.out.find("answered by") != std::string::npos);
    CHECK(r.out.find("ipopt") != std::string::npos);
  }
}
