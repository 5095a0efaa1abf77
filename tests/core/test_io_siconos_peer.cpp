// cpkit's .dat reader against Siconos' own reader, live, through python3-siconos
// (tests/core/siconos_peer.py): on the Siconos files of tests/data/siconos, on random
// non-symmetric dense and sparse block problems written by Siconos' writer, and on files written
// by cpkit's write_lcp_dat (Siconos must read what cpkit writes). Exits 77, which ctest reports
// as skipped, with the reason printed, when python3-siconos is not importable.
#include <catch2/catch.hpp>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "peer_skip.hpp"
#include "scratch_files.hpp"
#include "cpkit/core/io.hpp"

namespace {

using cpkit::Mat;
using cpkit::Vec;
namespace fs = std::filesystem;

fs::path scratch() {
  static const fs::path dir = cpkit::test::scratch_dir("cpkit_test_io_peer_");
  return dir;
}

/// Debian's interpreter (where python3-siconos lives) unless $CPKIT_PYTHON names another.
std::string python() {
  if (const char* env = std::getenv("CPKIT_PYTHON")) return env;
  return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

/// Runs the peer script; returns its exit code. Its output goes to `log`.
int run_peer(const std::string& args, const fs::path& log) {
  const std::string cmd = "'" + python() + "' '" CPKIT_SOURCE_DIR "/tests/core/siconos_peer.py' " +
                          args + " > '" + log.string() + "' 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Problems that cpkit writes for Siconos to read: non-symmetric, dense and sparse.
std::vector<std::string> write_with_cpkit(const fs::path& dir) {
  std::mt19937 rng(11);
  std::normal_distribution<double> g;
  std::vector<std::string> files;
  for (int n : {1, 3, 7}) {
    Mat M(n, n);
    Vec q(n);
    for (int i = 0; i < n; ++i) {
      q[i] = g(rng);
      for (int j = 0; j < n; ++j) M(i, j) = g(rng) * std::pow(10.0, 40 * g(rng));
    }
    cpkit::LcpProblem dense(M, q);
    files.push_back((dir / ("cpkit_dense_" + std::to_string(n) + ".dat")).string());
    cpkit::write_lcp_dat(dense, files.back());
    cpkit::LcpProblem sparse;
    sparse.M_sparse = M.sparseView();
    for (int i = 0; i < n; ++i) sparse.M_sparse.coeffRef(i, (i + 1) % n) = 0;  // holes
    sparse.M_sparse.prune(0.0);
    sparse.q = q;
    files.push_back((dir / ("cpkit_sparse_" + std::to_string(n) + ".dat")).string());
    cpkit::write_lcp_dat(sparse, files.back());
  }
  return files;
}

}  // namespace

TEST_CASE("cpkit reads .dat files exactly as Siconos' own reader does", "[io][dat][siconos]") {
  const fs::path dir = scratch();
  const int rc = run_peer("write '" + (dir / "gen").string() + "'", dir / "write.log");
  if (rc == 77 || rc == 127)  // python3-siconos not importable / no interpreter at all
    cpkit::test::skip_program(rc == 77 ? slurp(dir / "write.log")
                                       : "no Python interpreter '" + python() + "' (" +
                                             slurp(dir / "write.log") + ")");
  INFO(slurp(dir / "write.log"));
  REQUIRE(rc == 0);

  std::vector<std::string> files;
  for (const auto& root : {fs::path(CPKIT_TEST_DATA_DIR) / "siconos", dir / "gen"})
    for (const auto& e : fs::directory_iterator(root))
      if (e.path().extension() == ".dat") files.push_back(e.path().string());
  const auto own = write_with_cpkit(dir);
  files.insert(files.end(), own.begin(), own.end());
  std::string args = "decode '" + (dir / "decoded.json").string() + "'";
  for (const auto& f : files) args += " '" + f + "'";
  REQUIRE(run_peer(args, dir / "decode.log") == 0);

  std::ifstream in(dir / "decoded.json");
  const auto decoded = nlohmann::json::parse(in);
  int compared = 0, sparse = 0;
  for (const auto& f : files) {
    const std::string key = fs::path(f).filename().string();
    INFO(f);
    REQUIRE(decoded.contains(key));
    const auto p = cpkit::read_lcp_dat(f);
    const Mat M = p.dense_M();
    const auto& jm = decoded[key]["M"];
    const auto& jq = decoded[key]["q"];
    REQUIRE(static_cast<std::size_t>(p.size()) == jq.size());
    bool equal = true;
    for (Eigen::Index i = 0; i < p.size(); ++i) {
      equal &= p.q[i] == jq[static_cast<std::size_t>(i)].get<double>();
      for (Eigen::Index j = 0; j < p.size(); ++j)
        equal &= M(i, j) == jm[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)].get<double>();
    }
    CHECK(equal);  // bit for bit (-0 == 0 aside)
    sparse += p.is_sparse();
    ++compared;
  }
  std::cout << "compared " << compared << " .dat files with Siconos' reader (" << sparse
            << " sparse block)\n";
  CHECK(compared >= 22 + 13 + 6);
  CHECK(sparse >= 3 + 7 + 3);
}
