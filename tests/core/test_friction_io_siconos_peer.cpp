// cpkit's friction problem readers against Siconos' own (python3-siconos, Siconos numerics 4.4:
// frictionContact_new_from_filename, globalFrictionContact_new_from_filename), run live through
// tests/core/friction_siconos_peer.py on every .dat file of tests/data/fclib: same n_c, mu, q
// and every entry of W (M, H, q, b for global problems), bit for bit. Exits 77, which ctest
// reports as skipped, with the reason printed, when python3-siconos is not importable.
#include <catch2/catch.hpp>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
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

/// The .dat files the peer decodes as `kind` (local or global): those of local/ or global/ and
/// the sparse (storage 2) ones of sparse/ (GFC3D_* are global).
std::vector<std::string> peer_files(const std::string& kind) {
  std::vector<std::string> files = dat_files(kind.c_str());
  for (const auto& f : dat_files("sparse"))
    if ((fs::path(f).filename().string().rfind("GFC3D", 0) == 0) == (kind == "global"))
      files.push_back(f);
  return files;
}

/// The peer's decoding of every file of `kind`, once per program (a Python start each).
const nlohmann::json& peer_of(const std::string& kind) {
  static std::map<std::string, nlohmann::json> decoded;
  auto it = decoded.find(kind);
  if (it == decoded.end()) it = decoded.emplace(kind, decode(kind, peer_files(kind))).first;
  return it->second;
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
  const auto& peer = peer_of("local");
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
  const auto& peer = peer_of("global");
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

TEST_CASE("sparse (storage 2) .dat files read as Siconos reads them, and as the dense originals",
          "[friction][io][siconos][sparse]") {
  // Written by Siconos' own writer (tests/data/fclib/sparse/generate.py) from the dense or
  // sparse-block files of local/ and global/; Siconos prints their entries with %g.
  const auto files = dat_files("sparse");
  REQUIRE(files.size() == 7);
  std::vector<std::string> local;
  for (const auto& f : files)
    if (fs::path(f).filename().string().rfind("GFC3D", 0) != 0) local.push_back(f);
  REQUIRE(local.size() == 6);
  const auto& peer = peer_of("local");
  int compared = 0;
  for (const auto& f : local) {
    INFO(f);
    const auto& d = peer.at(fs::path(f).filename().string());
    const auto p = cpkit::read_friction_problem(f);
    REQUIRE(p.contacts() == d["contacts"].get<Eigen::Index>());
    require_same(p.W, d["W"]);
    require_same(p.q, d["q"]);
    require_same(p.mu, d["mu"]);
    // The dense original, its W entries printed with %g as Siconos' writer does.
    const std::string stem = fs::path(f).stem().string();
    const fs::path original = fs::path(CPKIT_TEST_DATA_DIR) / "fclib" / "local" /
                              (stem.substr(0, stem.rfind('_')) + ".dat");
    if (!fs::exists(original)) continue;  // empty_column_csc: built in generate.py
    const auto o = cpkit::read_friction_problem(original.string());
    Eigen::MatrixXd rounded = Eigen::MatrixXd(o.W);
    for (Eigen::Index i = 0; i < rounded.rows(); ++i)
      for (Eigen::Index j = 0; j < rounded.cols(); ++j) {
        char text[64];
        std::snprintf(text, sizeof text, "%g", rounded(i, j));
        rounded(i, j) = std::strtod(text, nullptr);
      }
    CHECK((Eigen::MatrixXd(p.W).array() == rounded.array()).all());
    CHECK(p.q == o.q);
    CHECK(p.mu == o.mu);
    ++compared;
  }
  CHECK(compared == 5);
  const std::string global = (fs::path(CPKIT_TEST_DATA_DIR) / "fclib" / "sparse" / "GFC3D_Example1_csc.dat").string();
  const auto& g = peer_of("global").at("GFC3D_Example1_csc.dat");
  const auto p = cpkit::read_global_friction_problem(global);
  require_same(p.M, g["M"]);
  require_same(p.H, g["H"]);
  require_same(p.f, g["q"]);
  require_same(p.w, g["b"]);
  require_same(p.mu, g["mu"]);
}
