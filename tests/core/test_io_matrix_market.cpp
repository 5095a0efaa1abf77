// Matrix Market matrices and vectors, and LCPs made of a Matrix Market M and q: the layout,
// hand-checked values, and every refusal (sizes beyond the data, overflowing sizes, a symmetric
// non-square file, duplicates) as an InputError naming the line.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "scratch_files.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"

namespace {

using cpkit::InputError;
using cpkit::Mat;
using cpkit::Vec;
using Catch::Contains;
namespace fs = std::filesystem;

fs::path scratch() {
  static const fs::path dir = cpkit::test::scratch_dir("cpkit_test_io_mtx_");
  return dir;
}

std::string write(const std::string& name, const std::string& text) {
  return cpkit::test::write_file(scratch(), name, text);
}

Mat parse(const std::string& text) { return Mat(cpkit::parse_matrix_market(text, "m.mtx")); }

void fails_with(const std::string& text, const std::string& part) {
  CAPTURE(text.substr(0, 200));
  CHECK_THROWS_AS(cpkit::parse_matrix_market(text, "m.mtx"), InputError);
  CHECK_THROWS_WITH(cpkit::parse_matrix_market(text, "m.mtx"), Contains(part));
}

const std::string kCoordGeneral = "%%MatrixMarket matrix coordinate real general\n";
const std::string kCoordSymmetric = "%%MatrixMarket matrix coordinate real symmetric\n";
const std::string kArrayGeneral = "%%MatrixMarket matrix array real general\n";

}  // namespace

TEST_CASE("Matrix Market matrices and vectors", "[io][mtx]") {
  SECTION("coordinate general, 1-based, comments and blank lines skipped") {
    const auto m = cpkit::parse_matrix_market(
        kCoordGeneral + "% comment\n\n2 3 2\n1 3 4.5\n% between\n2 1 -1\n\n");
    CHECK(m.rows() == 2);
    CHECK(m.cols() == 3);
    CHECK(Mat(m) == Mat{{0, 0, 4.5}, {-1, 0, 0}});
    CHECK(m.nonZeros() == 2);
  }
  SECTION("coordinate symmetric mirrors the off-diagonal entries (either triangle)") {
    CHECK(parse(kCoordSymmetric + "2 2 2\n1 1 2\n2 1 3\n") == Mat{{2, 3}, {3, 0}});
    CHECK(parse(kCoordSymmetric + "2 2 2\n1 1 2\n1 2 3\n") == Mat{{2, 3}, {3, 0}});
  }
  SECTION("array format is column-major; integer field; CRLF lines; upper-case header") {
    CHECK(parse("%%MatrixMarket matrix array integer general\r\n2 2\r\n1\r\n2\r\n3\r\n4\r\n") ==
          Mat{{1, 3}, {2, 4}});
    CHECK(parse("%%MATRIXMARKET MATRIX ARRAY REAL GENERAL\n1 2\n5\n6\n") == Mat{{5, 6}});
  }
  SECTION("symmetric array lists the lower triangle column by column") {
    CHECK(parse("%%MatrixMarket matrix array real symmetric\n3 3\n1\n2\n3\n4\n5\n6\n") ==
          Mat{{1, 2, 3}, {2, 4, 5}, {3, 5, 6}});
  }
  SECTION("vectors") {
    CHECK(cpkit::parse_matrix_market_vector(kArrayGeneral + "3 1\n1\n-2\n3\n") == Vec{{1, -2, 3}});
    CHECK(cpkit::parse_matrix_market_vector(kArrayGeneral + "1 3\n1\n-2\n3\n") == Vec{{1, -2, 3}});
    CHECK(cpkit::parse_matrix_market_vector(kCoordGeneral + "3 1 1\n2 1 7\n") == Vec{{0, 7, 0}});
    CHECK_THROWS_WITH(cpkit::parse_matrix_market_vector(kArrayGeneral + "2 2\n1\n2\n3\n4\n", "v.mtx"),
                      Contains("v.mtx: expected a vector (n x 1), got 2 x 2"));
  }
}

TEST_CASE("Malformed Matrix Market files name the line", "[io][mtx]") {
  fails_with("", "m.mtx: empty file");
  fails_with("hello\n", "m.mtx:1: not a Matrix Market matrix header");
  fails_with("%%MatrixMarket matrix coordinate real\n", "m.mtx:1: not a Matrix Market matrix header");
  fails_with("%%MatrixMarket vector coordinate real general\n", "m.mtx:1: not a Matrix Market");
  fails_with("%%MatrixMarket matrix coordinate complex general\n", "m.mtx:1: unsupported field 'complex'");
  fails_with("%%MatrixMarket matrix coordinate pattern general\n", "unsupported field 'pattern'");
  fails_with("%%MatrixMarket matrix coordinate real hermitian\n", "unsupported symmetry 'hermitian'");
  fails_with("%%MatrixMarket matrix coordinate real skew-symmetric\n", "unsupported symmetry");
  fails_with("%%MatrixMarket matrix dense real general\n", "unsupported format 'dense'");
  fails_with(kCoordGeneral, "m.mtx:1: the size line is missing");
  fails_with(kCoordGeneral + "x y\n", "m.mtx:2: bad size line 'x y'");
  fails_with(kCoordGeneral + "2 2\n", "m.mtx:2: bad size line '2 2' (expected 'rows columns entries')");
  fails_with(kArrayGeneral + "2 2 4\n", "m.mtx:2: bad size line '2 2 4' (expected 'rows columns')");
  fails_with(kCoordGeneral + "0 2 0\n", "m.mtx:2: rows = 0 is outside [1, 10000000]");
  fails_with(kCoordGeneral + "2 2 5\n", "m.mtx:2: entries = 5 is outside [0, 4]");
  fails_with(kCoordGeneral + "2 2 2\n1 1 1\n3 1 2\n", "m.mtx:4: bad entry '3 1 2': (3, 1) is outside the 2 x 2 matrix");
  fails_with(kCoordGeneral + "2 2 2\n1 1 1\n0 1 2\n", "m.mtx:4: bad entry '0 1 2': (0, 1)");
  fails_with(kCoordGeneral + "2 2 1\n1 1\n", "m.mtx:3: bad entry '1 1' (expected 'row column value')");
  fails_with(kCoordGeneral + "2 2 1\n1 1 1 1\n", "m.mtx:3: bad entry '1 1 1 1'");
  fails_with(kCoordGeneral + "2 2 1\n1.5 1 1\n", "m.mtx:3: bad entry '1.5 1 1'");
  fails_with(kCoordGeneral + "2 2 1\n1 1 x\n", "m.mtx:3: bad entry: expected a number, got 'x'");
  fails_with(kCoordGeneral + "2 2 1\n1 1 nan\n", "m.mtx:3: bad entry: 'nan' is not a finite number");
  fails_with(kCoordGeneral + "2 2 1\n1 1 1e400\n", "'1e400' is outside the range of double");
  fails_with(kCoordGeneral + "2 2 1\n1 1 1e-400\n", "'1e-400' is below the smallest double");
  fails_with(kArrayGeneral + "2 1\n1\n2 3\n", "m.mtx:4: bad entry '2 3' (expected one value)");
  fails_with(kCoordGeneral + "2 2 3\n1 1 1\n", "m.mtx:2: the size line announces 3 entries but the file has only 2 more lines");
  fails_with(kCoordGeneral + "2 2 2\n1 1 1\n%\n%\n", "m.mtx:5: expected 2 entries, found 1");
  fails_with(kCoordGeneral + "2 2 1\n1 1 1\n2 2 2\n", "m.mtx:4: more entries than the 1 announced");
  fails_with(kCoordGeneral + "2 2 2\n1 2 1\n1 2 5\n", "m.mtx:4: entry (1, 2) is given twice (also line 3)");
  fails_with(kCoordSymmetric + "2 2 2\n2 1 1\n1 2 1\n",
             "m.mtx:4: entry (2, 1) is given twice (also line 3); a symmetric file gives each off-diagonal pair once");
}

TEST_CASE("Matrix Market sizes are checked before anything is allocated", "[io][mtx]") {
  // The heap overflow of issue 11: a symmetric file with a non-square size mirrored (3, 1)
  // into row 1 of a 2-row matrix... now a clear error.
  fails_with(kCoordSymmetric + "2 3 1\n1 3 1\n",
             "m.mtx:2: a symmetric matrix must be square, the size line says 2 x 3");
  fails_with("%%MatrixMarket matrix array real symmetric\n3 1\n1\n2\n3\n",
             "a symmetric matrix must be square");
  // Sizes and counts near and beyond INT64_MAX, and products that overflow.
  fails_with(kCoordGeneral + "9223372036854775807 9223372036854775807 9223372036854775807\n",
             "m.mtx:2: rows = 9223372036854775807 is outside [1, 10000000] (the reader's size limit)");
  fails_with(kCoordGeneral + "99999999999999999999 1 1\n", "m.mtx:2: bad size line");
  fails_with(kCoordGeneral + "10000000 10000000 9223372036854775807\n",
             "m.mtx:2: entries = 9223372036854775807 is outside [0, 100000000000000]");
  fails_with(kCoordGeneral + "10000000 10000000 100000000000000\n1 1 1\n",
             "m.mtx:2: the size line announces 100000000000000 entries but the file has only");
  fails_with(kArrayGeneral + "10000000 10000000\n1\n", "announces 100000000000000 entries");
  fails_with(kCoordGeneral + "-1 2 1\n", "rows = -1 is outside");
  // A large but sparse matrix within the limit is fine: the entries are what is stored.
  const auto big = cpkit::parse_matrix_market(kCoordGeneral + "10000000 10000000 1\n10000000 1 2\n");
  CHECK(big.rows() == 10'000'000);
  CHECK(big.coeff(9'999'999, 0) == 2);
}

TEST_CASE("An LCP from a Matrix Market M and q", "[io][mtx]") {
  const std::string m_text = kCoordGeneral + "2 2 3\n1 1 2\n2 2 2\n1 2 1\n";
  const std::string q_text = kArrayGeneral + "2 1\n-5\n-6\n";
  SECTION("q beside M as NAME.q.mtx") {
    const auto m = write("A.mtx", m_text);
    write("A.q.mtx", q_text);
    CHECK(cpkit::matrix_market_q_path(m) == (scratch() / "A.q.mtx").string());
    for (const auto& p : {cpkit::read_lcp_matrix_market(m), cpkit::read_lcp_file(m)}) {
      CHECK(p.is_sparse());
      CHECK(p.dense_M() == Mat{{2, 1}, {0, 2}});
      CHECK(p.q == Vec{{-5, -6}});
      CHECK(p.name == "A");
    }
  }
  SECTION("q given explicitly") {
    const auto m = write("B.mtx", m_text);
    const auto q = write("qq.mtx", q_text);
    CHECK(cpkit::read_lcp_file(m, q).q == Vec{{-5, -6}});
  }
  SECTION("without q: the message says what to do") {
    const auto m = write("C.mtx", m_text);
    CHECK_THROWS_WITH(cpkit::read_lcp_file(m),
                      Contains("C.mtx: a Matrix Market file holds M only; q is read from") &&
                          Contains("C.q.mtx beside it, which does not exist (give q with --q FILE"));
  }
  SECTION("sizes that do not match, a non-square M") {
    const auto m = write("D.mtx", m_text);
    const auto q3 = write("q3.mtx", kArrayGeneral + "3 1\n1\n2\n3\n");
    CHECK_THROWS_WITH(cpkit::read_lcp_file(m, q3), Contains("size mismatch"));
    const auto rect = write("E.mtx", kCoordGeneral + "2 3 1\n1 1 1\n");
    CHECK_THROWS_WITH(cpkit::read_lcp_file(rect, q3), Contains("M is not square (2 x 3)"));
  }
  SECTION("a JSON file naming Matrix Market files gives sparse storage") {
    write("M.mtx", m_text);
    write("q.mtx", q_text);
    const auto p = cpkit::read_lcp_json(write("sp.json", R"({"M_mtx": "M.mtx", "q_mtx": "q.mtx"})"));
    CHECK(p.is_sparse());
    CHECK(p.dense_M() == Mat{{2, 1}, {0, 2}});
    CHECK(p.q == Vec{{-5, -6}});
    write("q3j.mtx", kArrayGeneral + "3 1\n1\n2\n3\n");
    CHECK_THROWS_WITH(
        cpkit::read_lcp_json(write("bad.json", R"({"M_mtx": "M.mtx", "q_mtx": "q3j.mtx"})")),
        Contains("size mismatch"));
  }
  SECTION("the reference obstacle problem of tests/data/sparse") {
    const std::string dir = CPKIT_TEST_DATA_DIR "/sparse/";
    const auto a = cpkit::read_lcp_file(dir + "obstacle_6x6_M.mtx", dir + "obstacle_6x6_q.mtx");
    const auto b = cpkit::read_lcp_file(dir + "obstacle_6x6.json");
    CHECK(a.dense_M() == b.dense_M());
    CHECK(a.q == b.q);
  }
}
