// Problem files in general: dispatch on the extension, what can be opened, JSON round trips.
// Each format has its own test file: test_io_json.cpp, test_io_dat.cpp,
// test_io_matrix_market.cpp (and test_io_siconos_peer.cpp against Siconos' own reader).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "scratch_files.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"

namespace {

using cpkit::Mat;
using cpkit::Vec;
using Catch::Contains;
namespace fs = std::filesystem;

fs::path scratch() {
  static const fs::path dir = cpkit::test::scratch_dir("cpkit_test_io_");
  return dir;
}

std::string write(const std::string& name, const std::string& text) {
  return cpkit::test::write_file(scratch(), name, text);
}

}  // namespace

TEST_CASE("read_lcp_file dispatches on the extension", "[io]") {
  const auto j = write("a.JSON", R"({"M": [[2]], "q": [-1]})");
  CHECK(cpkit::read_lcp_file(j).M(0, 0) == 2);
  const auto d = write("b.dat", "1\n0\n1\n1\n1\t1\n3\n-1\n");
  CHECK(cpkit::read_lcp_file(d).M(0, 0) == 3);
  CHECK_THROWS_WITH(cpkit::read_lcp_file(write("c.txt", "1")),
                    Contains("unknown file type '.txt' (expected .json, .dat, .mtx or .npy, or no extension"));
  CHECK_THROWS_WITH(cpkit::read_lcp_file(j, "q.mtx"),
                    Contains("a separate q file is only read with a Matrix Market (.mtx) or numpy (.npy) M"));
  CHECK_THROWS_WITH(cpkit::read_lcp_file(d, "q.mtx"), Contains("a separate q file"));
}

TEST_CASE("What cannot be read is named", "[io]") {
  CHECK_THROWS_WITH(cpkit::read_lcp_file((scratch() / "missing.json").string()),
                    Contains("missing.json: cannot open file"));
  fs::create_directories(scratch() / "dir.json");
  CHECK_THROWS_WITH(cpkit::read_lcp_file((scratch() / "dir.json").string()),
                    Contains("dir.json: is a directory"));
  // A device would be read forever (/dev/zero) or block (a terminal).
  CHECK_THROWS_WITH(cpkit::read_lcp_json("/dev/zero"), Contains("/dev/zero: not a regular file"));
  CHECK_THROWS_WITH(cpkit::read_matrix_market("/dev/null"), Contains("not a regular file"));
  // A file name that is not UTF-8 is shown as valid UTF-8.
  CHECK_THROWS_WITH(cpkit::read_lcp_file((scratch() / "bad\xff.json").string()),
                    Contains("bad\xEF\xBF\xBD.json: cannot open file"));
  const auto p = cpkit::read_lcp_file(write("\xfe\xff.dat", "1\n0\n1\n1\n1\t1\n3\n-1\n"));
  CHECK(p.name == "\xEF\xBF\xBD\xEF\xBF\xBD");
}

TEST_CASE("JSON round trip", "[io][json]") {
  cpkit::LcpProblem p(Mat{{1.5, -2}, {1e-300, 4}}, Vec{{0.1, -7}}, "rt");
  p.note = "round trip";
  const auto path = (scratch() / "rt.json").string();
  cpkit::write_lcp_json(p, path);
  const auto a = cpkit::read_lcp_json(path);
  CHECK(a.M == p.M);
  CHECK(a.q == p.q);
  CHECK(a.name == "rt");
  CHECK(a.note == "round trip");
  // A note holding bytes that are not UTF-8 is written as valid JSON (U+FFFD).
  p.note = "bad \xff byte";
  cpkit::write_lcp_json(p, path);
  CHECK(cpkit::read_lcp_json(path).note == "bad \xEF\xBF\xBD byte");
}

TEST_CASE("Every reference problem of tests/data/lcp is read", "[io][json]") {
  int files = 0;
  for (const auto& e : fs::directory_iterator(CPKIT_TEST_DATA_DIR "/lcp")) {
    if (e.path().extension() != ".json") continue;
    INFO(e.path());
    CHECK_NOTHROW(cpkit::read_lcp_file(e.path().string()));
    ++files;
  }
  CHECK(files >= 14);
}
