// `cpkit lcp solve FILE --solver fb-newton` on every LCP file of tests/data/lcp and on the sparse
// Matrix Market example: runs the built binary, checks the exit code against each file's stated
// outcome (0 for solvable files, 1 for infeasible ones) and re-checks the printed z against the
// file's data here.
#include <sys/wait.h>

#include <algorithm>
#include <catch2/catch.hpp>

#include "cli_runner.hpp"
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cpkit/core/io.hpp"
#include "peer_skip.hpp"

namespace {

namespace fs = std::filesystem;

using Run = cpkit::test::CliRun;
using cpkit::test::run_cpkit;

// ||min(z, Mz + q)||_inf / (1 + ||q||_inf) from the file's data.
double scaled_natural(const cpkit::LcpProblem& p, const cpkit::Vec& z) {
  const cpkit::Vec w = p.w(z);
  return z.cwiseMin(w).lpNorm<Eigen::Infinity>() / (1 + p.q.lpNorm<Eigen::Infinity>());
}

}  // namespace

TEST_CASE("cpkit lcp solve --solver fb-newton on every LCP file", "[fb][cli]") {
  if (!fs::exists(fs::path(CPKIT_BINARY_DIR) / "apps" / "cpkit")) {
    CPKIT_SKIP_CHECK("the cpkit program is not built (target cpkit_cli)");
    return;
  }
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(fs::path(CPKIT_TEST_DATA_DIR) / "lcp"))
    if (e.path().extension() == ".json") files.push_back(e.path());
  files.push_back(fs::path(CPKIT_TEST_DATA_DIR) / "sparse" / "obstacle_6x6.json");
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    CAPTURE(f.string());
    std::ifstream in(f);
    const auto j = nlohmann::json::parse(in);
    const bool solvable = j.at("expected").at("status") == "solvable";
    const auto r = run_cpkit("lcp solve '" + f.string() + "' --solver fb-newton --json");
    CHECK(r.code == (solvable ? 0 : 1));
    const auto out = nlohmann::json::parse(r.out);
    CHECK(out.at("solver") == "fb-newton");
    if (!solvable) {
      CHECK(out.at("status") != "solved");
      continue;
    }
    const auto p = cpkit::read_lcp_file(f.string());
    cpkit::Vec z(p.size());
    for (Eigen::Index i = 0; i < p.size(); ++i)
      z[i] = out.at("z").at(static_cast<size_t>(i)).get<double>();
    CHECK(scaled_natural(p, z) <= 1e-9);
  }
}
