// numpy .npy files: files written by numpy itself (tests/data/npy/make_npy.py, the values are
// literals there and here), C and Fortran order, format versions 1.0, 2.0 and 3.0, and every
// refusal as a clear InputError naming the file.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <fstream>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"
#include "cpkit/lcp/lemke.hpp"
#include "scratch_files.hpp"

namespace {

using Catch::Contains;
using cpkit::InputError;
using cpkit::Mat;
using cpkit::Vec;

const std::string kDir = std::string(CPKIT_TEST_DATA_DIR) + "/npy/";

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

const Mat kA = (Mat(3, 3) << 1.0, 2.0, 3.0, 4.0, 5.0, 6.5, -7.0, 8.25, 1e-300).finished();

/// A .npy file (format 1.0) with the given header dict and data bytes; the header is padded
/// with spaces and a newline as numpy does.
std::string npy(std::string dict, const std::string& data) {
  dict += "\n";
  std::string s = std::string("\x93NUMPY\x01\x00", 8);
  s += static_cast<char>(dict.size() & 0xff);
  s += static_cast<char>(dict.size() >> 8);
  return s + dict + data;
}

void fails_with(const std::string& bytes, const std::string& part, bool matrix = true) {
  CAPTURE(part);
  if (matrix) {
    CHECK_THROWS_AS(cpkit::parse_npy_matrix(bytes, "f.npy"), InputError);
    CHECK_THROWS_WITH(cpkit::parse_npy_matrix(bytes, "f.npy"), Contains("f.npy") && Contains(part));
  } else {
    CHECK_THROWS_WITH(cpkit::parse_npy_vector(bytes, "f.npy"), Contains("f.npy") && Contains(part));
  }
}

}  // namespace

TEST_CASE(".npy files written by numpy: C and Fortran order, versions 1, 2, 3", "[io][npy]") {
  for (const char* f : {"A_c.npy", "A_f.npy", "A_v2.npy", "A_v3.npy"}) {
    CAPTURE(f);
    const Mat A = cpkit::parse_npy_matrix(bytes_of(kDir + f), f);
    CHECK(A == kA);  // exact: float64 bytes copied, 1e-300 included
  }
  const Vec q = cpkit::parse_npy_vector(bytes_of(kDir + "q_column.npy"), "q_column.npy");
  CHECK(q == Vec{{-2.0, 0.0, 3.0}});
}

TEST_CASE(".npy LCP: q beside M or given, dispatch by extension, solved", "[io][npy]") {
  const cpkit::LcpProblem p = cpkit::read_lcp_file(kDir + "lcp3.npy");  // q from lcp3.q.npy
  CHECK(p.M == (Mat(3, 3) << 2, 1, 0, 1, 3, 1, 0, 1, 4).finished());
  CHECK(p.q == Vec{{-2.0, 0.0, 3.0}});
  CHECK(p.name == "lcp3");
  const cpkit::LcpProblem p2 = cpkit::read_lcp_file(kDir + "lcp3.npy", kDir + "q_column.npy");
  CHECK(p2.q == p.q);
  // unique solution z = (1, 0, 0), w = (0, 1, 3) (make_npy.py)
  const auto r = cpkit::lcp::solve_lemke(p);
  CHECK((r.z - Vec{{1.0, 0.0, 0.0}}).cwiseAbs().maxCoeff() < 1e-12);
  CHECK_THROWS_WITH(cpkit::read_lcp_file(kDir + "A_c.npy"),
                    Contains("A_c.q.npy") && Contains("does not exist"));
  CHECK_THROWS_WITH(cpkit::read_lcp_file(kDir + "rect_2x3.npy", kDir + "q_column.npy"),
                    Contains("rect_2x3.npy") && Contains("an LCP needs a square M"));
  CHECK_THROWS_WITH(cpkit::read_lcp_file(kDir + "lcp3.npy", kDir + "q_2d.npy"),
                    Contains("q_2d.npy") && Contains("a vector needs shape (n,) or (n, 1)"));
}

TEST_CASE(".npy refusals name the problem", "[io][npy]") {
  fails_with(bytes_of(kDir + "A_big_endian.npy"), "dtype '>f8' is not supported");
  fails_with(bytes_of(kDir + "A_int64.npy"), "dtype '<i8' is not supported");
  fails_with(bytes_of(kDir + "A_float32.npy"), "dtype '<f4' is not supported");
  fails_with(bytes_of(kDir + "A_3d.npy"), "a matrix needs a 2-D shape, the file has shape (2, 2, 2)");
  fails_with(bytes_of(kDir + "q_2d.npy"), "a vector needs shape (n,) or (n, 1)", false);
  fails_with("", "not a numpy .npy file");
  fails_with("{'descr': '<f8'}", "not a numpy .npy file");
  fails_with(std::string("\x93NUMPY\x04\x00\x10\x00", 10), "format version 4.0 is not supported");
  fails_with(std::string("\x93NUMPY\x01\x00\xff\x00{", 11), "header length 255 goes beyond");
  const std::string eight(8, '\0');
  const std::string base = "{'descr': '<f8', 'fortran_order': False, 'shape': (1, 1), }";
  CHECK(cpkit::parse_npy_matrix(npy(base, eight), "f.npy") == Mat::Zero(1, 1));
  fails_with(npy(base, eight + eight), "shape (1, 1) needs 8 bytes of float64 data, the file has 16");
  fails_with(npy(base, "1234"), "needs 8 bytes of float64 data, the file has 4");
  // a shape far beyond the data is refused before anything is allocated
  fails_with(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1000000, 1000000), }", eight),
             "needs more data than the 8 bytes after the header");
  fails_with(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (99999999999999999999, 1), }", eight),
             "a dimension of 'shape' is too large");
  fails_with(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 1), 'x': 1}", eight),
             "unknown header key 'x'");
  fails_with(npy("{'descr': '<f8', 'descr': '<f8', 'fortran_order': False, 'shape': (1, 1)}", eight),
             "the key 'descr' appears twice");
  fails_with(npy("{'descr': '<f8', 'shape': (1, 1)}", eight), "lacks the key 'fortran_order'");
  fails_with(npy("{'descr': '<f8', 'fortran_order': 0, 'shape': (1, 1)}", eight),
             "'fortran_order' must be True or False");
  fails_with(npy("{'descr': '<f8', 'fortran_order': False, 'shape': [1, 1]}", eight),
             "expected '('");
  fails_with(npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1, 1)} x", eight),
             "followed only by spaces and a final newline");
  fails_with(npy("{'descr': '<f8\xff', 'fortran_order': False, 'shape': (1, 1)}", eight),
             "not printable ASCII");
  // NaN data: the file reads, the problem does not validate
  const auto dir = cpkit::test::scratch_dir("cpkit_npy_");
  double nan = std::nan("");
  std::string nan_bytes(8, '\0');
  std::memcpy(&nan_bytes[0], &nan, 8);
  const std::string m = cpkit::test::write_file(dir, "m.npy", npy(base, nan_bytes));
  const std::string qf = cpkit::test::write_file(
      dir, "q.npy", npy("{'descr': '<f8', 'fortran_order': False, 'shape': (1,), }", eight));
  CHECK_THROWS_AS(cpkit::read_lcp_file(m, qf), InputError);
}
