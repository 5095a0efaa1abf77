// cpkit's friction problem readers against Siconos' own (python3-siconos, Siconos numerics 4.4:
// frictionContact_new_from_filename, globalFrictionContact_new_from_filename), run live through
// tests/core/friction_siconos_peer.py on every .dat file of tests/data/fclib: same n_c, mu, q
// and every entry of W (M, H, q, b for global problems), bit for bit. Exits 77, which ctest
// reports as skipped, with the reason printed, when python3-siconos is not importable.
#include <catch2/catch.hpp>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cpkit/core/friction_io.hpp"
#include "peer_skip.hpp"
#include "scratch_files.hpp"

namespace {

namespace fs = std::filesystem;

std::string python() {
  if (const char* env = std::getenv("CPKIT_PYTHON")) return env;
  return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<std::string> dat_files(const char* folder) {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(fs::path(CPKIT_TEST_DATA_DIR) / "fclib" / folder))
    if (e.path().extension() == ".dat") files.push_back(e.path().string());
  return files;
}

/// The peer's decoding of `files`; the program is skipped when the peer is missing.
nlohmann::json decode(const std::string& kind, const std::vector<std::string>& files) {
  const fs::path dir = cpkit::test::scratch_dir("cpkit_test_friction_io_peer_");
  std::string cmd = "'" + python() + "' '" CPKIT_SOURCE_DIR "/tests/core/friction_siconos_peer.py' " +
                    kind + " '" + (dir / "out.json").string() + "'";
  for (const auto& f : files) cmd += " '" + f + "'";
  cmd += " > '" + (dir / "log").string() + "' 2>&1";
  const int status = std::system(cmd.c_str());
  const int rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (rc == 77 || rc == 127)  // python3-siconos not importable / no interpreter at all
    cpkit::test::skip_program(rc == 77 ? slurp(dir / "log")
                                       : "no Python interpreter '" + python() + "'");
  INFO(slurp(dir / "log"));
  REQUIRE(rc == 0);
  std::ifstream in(dir / "out.json");
  return nlohmann::json::parse(in);
}

/// Every entry of `m` equals the peer's (the peer lists its non-zeros; the rest must be 0).
void require_same(const Eigen::SparseMatrix<double>& m, const nlohmann::json& peer) {
  REQUIRE(m.rows() == peer["rows"].get<Eigen::Index>());
  REQUIRE(m.cols() == peer["cols"].get<Eigen::Index>());
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(m.rows(), m.cols());
  for (const auto& e : peer["entries"]) expected(e[0].get<int>(), e[1].get<int>()) = e[2].get<double>();
  const Eigen::MatrixXd got = m;
  CHECK(static_cast<std::size_t>((got.array() != 0).count()) == peer["entries"].size());
  CHECK((got.array() == expected.array()).all());
}

void require_same(const Eigen::VectorXd& v, const nlohmann::json& peer) {
  REQUIRE(static_cast<std::size_t>(v.size()) == peer.size());
  for (std::size_t i = 0; i < peer.size(); ++i) CHECK(v[static_cast<Eigen::Index>(i)] == peer[i].get<double>());
}

}  // namespace

TEST_CASE("every local .dat file reads as Siconos reads it", "[friction][io][siconos]") {
  const auto files = dat_files("local");
  REQUIRE(files.size() == 10);
  const auto peer = decode("local", files);
  for (const auto& f : files) {
    INFO(f);
    const auto& d = peer.at(fs::path(f).filename().string());
    const auto p = cpkit::read_friction_problem(f);
    CHECK(d["dimension"] == 3);
    REQUIRE(p.contacts() == d["contacts"].get<Eigen::Index>());
    require_same(p.W, d["W"]);
    require_same(p.q, d["q"]);
    require_same(p.mu, d["mu"]);
  }
}

TEST_CASE("every global .dat file reads as Siconos reads it", "[friction][io][siconos]") {
  const auto files = dat_files("global");
  REQUIRE(files.size() == 2);
  const auto peer = decode("global", files);
  for (const auto& f : files) {
    INFO(f);
    const auto& d = peer.at(fs::path(f).filename().string());
    const auto p = cpkit::read_global_friction_problem(f);
    REQUIRE(p.contacts() == d["contacts"].get<Eigen::Index>());
    require_same(p.M, d["M"]);
    require_same(p.H, d["H"]);
    require_same(p.f, d["q"]);  // Siconos' q is cpkit's f
    require_same(p.w, d["b"]);  // Siconos' b is cpkit's w
    require_same(p.mu, d["mu"]);
  }
}
