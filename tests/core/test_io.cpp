// Problem-file readers and writers: JSON, Siconos .dat (column-major), Matrix Market.
// Malformed files must give InputError naming the file and the line or field.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"

namespace {

using cpkit::InputError;
using cpkit::Mat;
using cpkit::Vec;
using Catch::Contains;
namespace fs = std::filesystem;

// A scratch directory unique to this test process.
fs::path scratch() {
  static const fs::path dir = [] {
    std::random_device rd;
    auto d = fs::temp_directory_path() / ("cpkit_test_io_" + std::to_string(rd()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

std::string write(const std::string& name, const std::string& text) {
  const auto path = (scratch() / name).string();
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST_CASE("JSON problems", "[io][json]") {
  const auto p = cpkit::parse_lcp_json(
      R"({"name": "t", "note": "n", "M": [[1, 2], [3, 4]], "q": [-1, 0.5], "expected": {}})");
  CHECK(p.name == "t");
  CHECK(p.note == "n");
  CHECK(p.M == Mat{{1, 2}, {3, 4}});  // row-major in the file
  CHECK(p.q == Vec{{-1, 0.5}});
  CHECK_FALSE(p.is_sparse());
}

TEST_CASE("Malformed JSON problems name the field", "[io][json]") {
  auto fails_with = [](const std::string& text, const std::string& part) {
    CAPTURE(text);
    CHECK_THROWS_AS(cpkit::parse_lcp_json(text, "f.json"), InputError);
    CHECK_THROWS_WITH(cpkit::parse_lcp_json(text, "f.json"), Contains("f.json") && Contains(part));
  };
  fails_with(R"({"M": [[1]], "q": [1)", "malformed JSON");
  fails_with(R"([1, 2])", "top level must be an object");
  fails_with(R"({"q": [1]})", "missing field \"M\"");
  fails_with(R"({"M": [[1]]})", "missing field \"q\"");
  fails_with(R"({"M": [[1]], "q": 1})", "\"q\" must be an array");
  fails_with(R"({"M": 1, "q": [1]})", "\"M\" must be an array of rows");
  fails_with(R"({"M": [], "q": []})", "\"q\" is empty");
  fails_with(R"({"M": [[1, 2]], "q": [1, 2]})", "has 1 rows but \"q\" has 2");
  fails_with(R"({"M": [[1, 2], [3]], "q": [1, 2]})", "M row 1 must be an array of 2");
  fails_with(R"({"M": [[1, 2], ["x", 4]], "q": [1, 2]})", "M[1][0] is not a number");
  fails_with(R"({"M": [[1, 2], [3, 4]], "q": [1, null]})", "q[1] is not a number");
  fails_with(R"({"M_mtx": "a.mtx"})", "\"M_mtx\" and \"q_mtx\" must both be file names");
}

TEST_CASE("Siconos .dat is read column-major", "[io][dat]") {
  // The first printed "row" is the first column of M.
  const auto p = cpkit::parse_lcp_dat("2\n1 2\n3 4\n5 6\nfree text here\n", "x/prob.dat");
  CHECK(p.M == Mat{{1, 3}, {2, 4}});
  CHECK(p.q == Vec{{5, 6}});
  CHECK(p.note == "free text here");
  CHECK(p.name == "prob");
  // The reference file cps_4_qp is solvable only when read column-major: M_ij from the JSON
  // (row-major) must equal the .dat written by write_lcp_dat and read back.
  const auto json = cpkit::read_lcp_json(CPKIT_TEST_DATA_DIR "/lcp/cps_4_qp.json");
  const auto path = (scratch() / "cps_4_qp.dat").string();
  cpkit::write_lcp_dat(json, path);
  const auto back = cpkit::read_lcp_dat(path);
  CHECK(back.M == json.M);
  CHECK(back.q == json.q);
  // And the first number after n in that .dat is M(0,0), the second M(1,0).
  std::ifstream in(path);
  double n = 0, m00 = 0, m10 = 0;
  in >> n >> m00 >> m10;
  CHECK(m00 == json.M(0, 0));
  CHECK(m10 == json.M(1, 0));
}

TEST_CASE("Malformed .dat files name the line", "[io][dat]") {
  CHECK_THROWS_WITH(cpkit::parse_lcp_dat("", "e.dat"), Contains("e.dat: empty file"));
  CHECK_THROWS_WITH(cpkit::parse_lcp_dat("two\n1 2\n", "e.dat"),
                    Contains("e.dat:1:") && Contains("size n"));
  CHECK_THROWS_WITH(cpkit::parse_lcp_dat("2.5\n", "e.dat"), Contains("size n"));
  CHECK_THROWS_WITH(cpkit::parse_lcp_dat("0\n", "e.dat"), Contains("size n"));
  CHECK_THROWS_WITH(cpkit::parse_lcp_dat("2\n1 2\n3 4\n5\n", "e.dat"),
                    Contains("found only 5 tokens"));
  CHECK_THROWS_WITH(cpkit::parse_lcp_dat("2\n1 2\n3 x\n5 6\n", "e.dat"),
                    Contains("e.dat:3:") && Contains("'x'"));
  CHECK_THROWS_WITH(cpkit::parse_lcp_dat("2\n1 2\n3 4\n5 inf\n", "e.dat"),
                    Contains("e.dat:4:") && Contains("finite number"));
}

TEST_CASE("read_lcp_file dispatches on the extension", "[io]") {
  const auto j = write("a.JSON", R"({"M": [[2]], "q": [-1]})");
  CHECK(cpkit::read_lcp_file(j).M(0, 0) == 2);
  const auto d = write("b.dat", "1\n3\n-1\n");
  CHECK(cpkit::read_lcp_file(d).M(0, 0) == 3);
  CHECK_THROWS_WITH(cpkit::read_lcp_file(write("c.txt", "1")), Contains("unknown file type"));
  CHECK_THROWS_WITH(cpkit::read_lcp_file((scratch() / "missing.json").string()),
                    Contains("cannot open file"));
}

TEST_CASE("JSON and .dat round trips", "[io]") {
  cpkit::LcpProblem p(Mat{{1.5, -2}, {1e-300, 4}}, Vec{{0.1, -7}}, "rt");
  p.note = "round trip";
  const auto jp = (scratch() / "rt.json").string();
  cpkit::write_lcp_json(p, jp);
  const auto a = cpkit::read_lcp_json(jp);
  CHECK(a.M == p.M);
  CHECK(a.q == p.q);
  CHECK(a.name == "rt");
  CHECK(a.note == "round trip");
  const auto dp = (scratch() / "rt.dat").string();
  cpkit::write_lcp_dat(p, dp);
  const auto b = cpkit::read_lcp_dat(dp);
  CHECK(b.M == p.M);  // 17 significant digits: exact
  CHECK(b.q == p.q);
  CHECK(b.note == "round trip");
}

TEST_CASE("Matrix Market matrices and vectors", "[io][mtx]") {
  SECTION("coordinate general, 1-based") {
    const auto m = cpkit::read_matrix_market(
        write("g.mtx", "%%MatrixMarket matrix coordinate real general\n% comment\n2 3 2\n"
                       "1 3 4.5\n2 1 -1\n"));
    CHECK(m.rows() == 2);
    CHECK(m.cols() == 3);
    CHECK(m.coeff(0, 2) == 4.5);
    CHECK(m.coeff(1, 0) == -1);
    CHECK(m.nonZeros() == 2);
  }
  SECTION("coordinate symmetric mirrors the off-diagonal entries") {
    const auto m = cpkit::read_matrix_market(
        write("s.mtx", "%%MatrixMarket matrix coordinate real symmetric\n2 2 2\n1 1 2\n2 1 3\n"));
    CHECK(Mat(m) == Mat{{2, 3}, {3, 0}});
  }
  SECTION("array format is column-major") {
    const auto m = cpkit::read_matrix_market(
        write("a.mtx", "%%MatrixMarket matrix array real general\n2 2\n1\n2\n3\n4\n"));
    CHECK(Mat(m) == Mat{{1, 3}, {2, 4}});
  }
  SECTION("vectors") {
    const auto v = cpkit::read_matrix_market_vector(
        write("v.mtx", "%%MatrixMarket matrix array real general\n3 1\n1\n-2\n3\n"));
    CHECK(v == Vec{{1, -2, 3}});
    CHECK_THROWS_WITH(cpkit::read_matrix_market_vector(write(
                          "nv.mtx", "%%MatrixMarket matrix array real general\n2 2\n1\n2\n3\n4\n")),
                      Contains("expected a vector"));
  }
  SECTION("malformed files name the line") {
    CHECK_THROWS_WITH(cpkit::read_matrix_market(write("h.mtx", "hello\n")),
                      Contains("h.mtx:1:") && Contains("header"));
    CHECK_THROWS_WITH(cpkit::read_matrix_market(
                          write("c.mtx", "%%MatrixMarket matrix coordinate complex general\n")),
                      Contains("unsupported field 'complex'"));
    CHECK_THROWS_WITH(cpkit::read_matrix_market(write(
                          "e.mtx", "%%MatrixMarket matrix coordinate real general\n2 2 2\n"
                                   "1 1 1\n3 1 2\n")),
                      Contains("e.mtx:4:") && Contains("bad entry"));
    CHECK_THROWS_WITH(cpkit::read_matrix_market(write(
                          "z.mtx", "%%MatrixMarket matrix coordinate real general\nx y\n")),
                      Contains("z.mtx:2:") && Contains("bad size line"));
    CHECK_THROWS_WITH(cpkit::read_matrix_market(write(
                          "t.mtx", "%%MatrixMarket matrix coordinate real general\n2 2 3\n1 1 1\n")),
                      Contains("expected 3 entries, found 1"));
  }
  SECTION("a JSON file naming Matrix Market files gives sparse storage") {
    write("M.mtx", "%%MatrixMarket matrix coordinate real general\n2 2 3\n1 1 2\n2 2 2\n1 2 1\n");
    write("q.mtx", "%%MatrixMarket matrix array real general\n2 1\n-5\n-6\n");
    const auto p =
        cpkit::read_lcp_json(write("sp.json", R"({"M_mtx": "M.mtx", "q_mtx": "q.mtx"})"));
    CHECK(p.is_sparse());
    CHECK(p.dense_M() == Mat{{2, 1}, {0, 2}});
    CHECK(p.q == Vec{{-5, -6}});
    // A size mismatch between the two files is named.
    write("q3.mtx", "%%MatrixMarket matrix array real general\n3 1\n1\n2\n3\n");
    CHECK_THROWS_WITH(
        cpkit::read_lcp_json(write("bad.json", R"({"M_mtx": "M.mtx", "q_mtx": "q3.mtx"})")),
        Contains("size mismatch"));
  }
}
