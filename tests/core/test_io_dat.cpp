// Siconos .dat files: the real layout (n, storage type, sizes, M, q), read as Siconos' own
// linearComplementarity_newFromFile reads it. The expected problems come from outside cpkit:
// the statements of ../shared/problems/siconos/README.md, Siconos' own decoding
// (tests/data/siconos/siconos_decoded.json), and matrices stated by hand for files that Siconos'
// writer produced.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "scratch_files.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"

namespace {

using cpkit::InputError;
using cpkit::LcpProblem;
using cpkit::Mat;
using cpkit::Vec;
using Catch::Contains;
namespace fs = std::filesystem;

const fs::path kSiconosData = fs::path(CPKIT_TEST_DATA_DIR) / "siconos";

fs::path scratch() {
  static const fs::path dir = cpkit::test::scratch_dir("cpkit_test_io_dat_");
  return dir;
}

/// Largest |w_i| / (sum_j |M_ij z_j| + |q_i|): w = 0 up to rounding, relative to the row's own
/// magnitudes.
double relative_w(const LcpProblem& p, const Vec& z) {
  const Mat M = p.dense_M();
  const Vec w = M * z + p.q;
  const Vec scale = M.cwiseAbs() * z.cwiseAbs() + p.q.cwiseAbs();
  return (w.cwiseAbs().array() / scale.array()).maxCoeff();
}

/// The problems of ../shared/problems/siconos/README.md (Siconos' decoding), checked on the
/// copies in tests/data/siconos and on the originals where that folder exists.
void check_stated_problems(const fs::path& dir) {
  INFO("folder " << dir);
  {
    const auto p = cpkit::read_lcp_dat((dir / "lcp_CPS_1.dat").string());
    CHECK_FALSE(p.is_sparse());
    CHECK(p.M == Mat{{1, 1}, {1, 1}});
    CHECK(p.q == Vec{{-1, -1}});
    // Solutions: the segment z1 + z2 = 1, z >= 0 (w = 0 on it).
    for (double t : {0.0, 0.25, 1.0}) CHECK(p.w(Vec{{t, 1 - t}}).cwiseAbs().maxCoeff() == 0.0);
    CHECK_THAT(p.note, Contains("Remark 4.1.14 CPS 2009"));
  }
  for (const char* file : {"lcp_deudeu.dat", "lcp_deudeu_block.dat"}) {
    INFO(file);
    const auto p = cpkit::read_lcp_dat((dir / file).string());
    CHECK(p.is_sparse() == (std::string(file) == "lcp_deudeu_block.dat"));
    CHECK(p.dense_M() == Mat{{2, 1}, {1, 2}});
    CHECK(p.q == Vec{{-5, -6}});
    CHECK(relative_w(p, Vec{{4.0 / 3.0, 7.0 / 3.0}}) < 1e-15);  // the unique solution
  }
  {
    const auto p = cpkit::read_lcp_dat((dir / "lcp_trivial_block.dat").string());
    CHECK(p.is_sparse());
    Mat expected = Mat::Zero(9, 9);
    Vec z(9);
    for (int i = 0; i < 9; ++i) expected(i, i) = i + 1, z[i] = 1.0 / (i + 1);
    CHECK(p.dense_M() == expected);
    CHECK(p.q == Vec::Constant(9, -1.0));
    CHECK(relative_w(p, z) < 1e-15);  // the unique solution z_i = 1/i
  }
}

/// Where the unmodified originals are: $CPKIT_SICONOS_PROBLEMS, else ../shared/problems/siconos
/// beside the source tree.
fs::path shared_problems() {
  if (const char* env = std::getenv("CPKIT_SICONOS_PROBLEMS")) return env;
  return fs::path(CPKIT_SOURCE_DIR) / ".." / "shared" / "problems" / "siconos";
}

}  // namespace

TEST_CASE("The Siconos files decode to the problems they state", "[io][dat][siconos]") {
  check_stated_problems(kSiconosData);
  const fs::path shared = shared_problems();
  if (fs::exists(shared / "lcp_deudeu.dat")) {
    check_stated_problems(shared);
  } else {
    WARN("not found: " << shared.string()
                       << " (set CPKIT_SICONOS_PROBLEMS); checked the copies in tests/data/siconos");
  }
}

TEST_CASE("Every Siconos LCP file decodes exactly as Siconos' own reader decodes it",
          "[io][dat][siconos]") {
  std::ifstream in(kSiconosData / "siconos_decoded.json");
  const auto decoded = nlohmann::json::parse(in);
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(kSiconosData)) {
    if (entry.path().extension() != ".dat") continue;
    const std::string file = entry.path().filename().string();
    INFO(file);
    REQUIRE(decoded.contains(file));
    const auto p = cpkit::read_lcp_dat(entry.path().string());
    const Mat M = p.dense_M();
    const auto& jm = decoded[file]["M"];
    const auto& jq = decoded[file]["q"];
    REQUIRE(static_cast<std::size_t>(p.size()) == jq.size());
    for (Eigen::Index i = 0; i < p.size(); ++i) {
      CHECK(p.q[i] == jq[static_cast<std::size_t>(i)].get<double>());
      for (Eigen::Index j = 0; j < p.size(); ++j)
        CHECK(M(i, j) == jm[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)].get<double>());
    }
    // Storage type 1 files give sparse storage.
    CHECK(p.is_sparse() == (file.find("block") != std::string::npos));
    ++compared;
  }
  CHECK(compared == 22);
}

TEST_CASE("Files written by Siconos' writer are column-major (non-symmetric cases)",
          "[io][dat][siconos]") {
  // Both written by Siconos' NM_write_in_filename from the matrices below (README there).
  const auto d = cpkit::read_lcp_dat((kSiconosData / "siconos_writer_dense_3x3.dat").string());
  CHECK_FALSE(d.is_sparse());
  CHECK(d.M == Mat{{1, 2, 0}, {3, 4, 5}, {0, 6, 7}});
  CHECK(d.q == Vec{{-1, -2, -3}});
  const auto b = cpkit::read_lcp_dat((kSiconosData / "siconos_writer_block_4x4.dat").string());
  CHECK(b.is_sparse());
  CHECK(b.dense_M() == Mat{{1, 2, 0, 0}, {3, 4, 0, 0}, {0, 0, 5, 6}, {7, 0, 8, 9}});
  CHECK(b.q == Vec{{-1, -2, -3, -4}});
  // The same layout typed by hand: the first printed line after the sizes is column 0.
  const auto h = cpkit::parse_lcp_dat("2\n0\n2\n2\n2\t2\n1 2\n3 4\n5 6\n", "h.dat");
  CHECK(h.M == Mat{{1, 3}, {2, 4}});
  CHECK(h.q == Vec{{5, 6}});
}

TEST_CASE("Sparse block layouts that Siconos' writer does not produce", "[io][dat]") {
  SECTION("filled1 < blocknumber0 + 1: trailing block rows are empty") {
    // 3 x 3, block rows/columns of sizes 1, 1, 1; one block (0, 0) = 5; filled1 = 2.
    const auto p = cpkit::parse_lcp_dat("3\n1\n3\n3\n1\n3\n3\n1 2 3\n1 2 3\n2\n1\n0 1\n0\n0\n5\n"
                                        "1 2 3\n",
                                        "t.dat");
    CHECK(p.dense_M() == Mat{{5, 0, 0}, {0, 0, 0}, {0, 0, 0}});
    CHECK(p.q == Vec{{1, 2, 3}});
  }
  SECTION("no blocks: M = 0 (Siconos' writer prints only \"0\")") {
    const auto p = cpkit::parse_lcp_dat("2\n1\n2\n2\n0\n1 2\n", "z.dat");
    CHECK(p.is_sparse());
    CHECK(p.dense_M() == Mat::Zero(2, 2));
    CHECK(p.q == Vec{{1, 2}});
  }
  SECTION("mixed block sizes, blocks listed out of column order") {
    // Block rows/columns of sizes 1 and 2. Row 0: blocks at columns 1 then 0; row 1: column 1.
    const auto p = cpkit::parse_lcp_dat("3\n1\n3\n3\n3\n2\n2\n1 3\n1 3\n3\n3\n0 2 3\n1 0 1\n"
                                        "0\n2 3\n1\n1\n2\n4 5 6 7\n-1 -1 -1\nnote text\n",
                                        "m.dat");
    CHECK(p.dense_M() == Mat{{1, 2, 3}, {0, 4, 6}, {0, 5, 7}});
    CHECK(p.note == "note text");
  }
}

TEST_CASE("Malformed .dat files are errors naming the line", "[io][dat]") {
  auto fails_with = [](const std::string& text, const std::string& part) {
    CAPTURE(text);
    CHECK_THROWS_AS(cpkit::parse_lcp_dat(text, "e.dat"), InputError);
    CHECK_THROWS_WITH(cpkit::parse_lcp_dat(text, "e.dat"), Contains(part));
  };
  const std::string dense_head = "2\n0\n2\n2\n2\t2\n";
  fails_with("", "e.dat: empty file");
  fails_with("two\n", "e.dat:1: expected the problem size n (an integer), got 'two'");
  fails_with("2.5\n0\n2\n2\n", "e.dat:1: expected the problem size n");
  fails_with("0\n", "e.dat:1: the problem size n is 0, expected in [1, ");
  // The old headerless layout (n, then M and q) is not guessed at.
  fails_with("2\n1 2\n3 4\n5 6\n", "e.dat:3: the number of columns of M (an LCP needs an n x n matrix");
  fails_with("2\n2\n2\n2\n0\n1 2\n", "e.dat:2: storage type 2 (Siconos NM_SPARSE");
  fails_with("2\n3\n2\n2\n0\n1 2\n", "e.dat:2: unknown storage type 3");
  fails_with("2\n-1\n2\n2\n0\n1 2\n", "e.dat:2: unknown storage type -1");
  fails_with("2\n0\n3\n2\n3\t2\n1 2 3 4 5 6\n7 8\n", "e.dat:3: the number of rows of M");
  fails_with("2\n0\n2\n2\n2\t3\n1 2\n3 4\n5 6\n", "e.dat:5: the number of columns of the dense M (repeated) is 3");
  fails_with(dense_head + "1 2\n3 4\n5\n", "e.dat:8: the file ends too early");
  fails_with(dense_head + "1 2\n3 x\n5 6\n", "e.dat:7: M(1, 1): expected a number, got 'x'");
  fails_with(dense_head + "1 2\n3 4\n5 inf\n", "e.dat:8: q[1]: 'inf' is not a finite number");
  fails_with(dense_head + "1 2\n3 4\n5 nan\n", "'nan' is not a finite number");
  fails_with(dense_head + "1 1e400\n3 4\n5 6\n", "e.dat:6: M(1, 0): '1e400' is outside the range of double");
  fails_with(dense_head + "1 -1e-400\n3 4\n5 6\n", "'-1e-400' is below the smallest double");
  fails_with(dense_head + "1 2\n3 4\n5 6\n7\n", "e.dat:9: '7' follows the 2 entries of q");
  // Sizes far beyond the data: rejected before anything is allocated.
  fails_with("2000000000\n0\n", "e.dat:2: the file ends too early");
  fails_with("3\n0\n3\n3\n3\t3\n1 2 3\n", "e.dat:6: the file ends too early: the 3 x 3 entries");
  fails_with("9223372036854775807\n", "e.dat:1: the problem size n is 9223372036854775807");
  fails_with("99999999999999999999\n", "e.dat:1: expected the problem size n (an integer)");
  // Sparse block matrices that do not match their header.
  const std::string sbm_head = "2\n1\n2\n2\n";
  fails_with(sbm_head + "1\n1\n1\n2\n2\n2\n1\n0 1\n0\n1\n2 1 1 2\n-5 -6\n",
             "e.dat:14: the number of block 0 is 1, expected 0");
  fails_with(sbm_head + "1\n1\n1\n2\n2\n2\n2\n0 1\n0\n0\n2 1 1 2\n-5 -6\n",
             "e.dat:11: filled2 (the number of non-zero blocks, as nbblocks) is 2, expected 1");
  fails_with(sbm_head + "2\n2\n2\n1 1\n1 2\n3\n2\n0 1 2\n0 1\n0\n1\n1\n2\n-5 -6\n",
             "e.dat:8: cumulative block row sizes must increase: 1 follows 1");
  fails_with(sbm_head + "1\n1\n1\n3\n2\n2\n1\n0 1\n0\n0\n1 2 3 4\n-5 -6\n",
             "e.dat:8: the cumulative block row size 0 is 3, expected in [1, 2]");
  fails_with(sbm_head + "1\n2\n2\n1 2\n1 3\n3\n1\n0 1 1\n0\n0\n1\n-5 -6\n",
             "e.dat:9: the cumulative block column size 1 is 3");
  fails_with(sbm_head + "1\n2\n1\n1 2\n1\n3\n1\n0 1 1\n0\n0\n1\n-5 -6\n",
             "e.dat:9: the block column sizes add up to 1, but M is 2 x 2");
  fails_with(sbm_head + "2\n1\n1\n2\n2\n2\n2\n0 1\n0 0\n0\n1 2 3 4\n1\n1 2 3 4\n-5 -6\n",
             "e.dat:12: the last block-row pointer is 1, but the header announces 2 blocks");
  fails_with(sbm_head + "2\n1\n1\n2\n2\n2\n2\n0 2\n0 0\n0\n1 2 3 4\n1\n1 2 3 4\n-5 -6\n",
             "e.dat:16: block 1 repeats block (0, 0)");
  fails_with(sbm_head + "1\n1\n1\n2\n2\n2\n1\n0 1\n1\n0\n2 1 1 2\n-5 -6\n",
             "e.dat:13: the block column of block 0 (index2_data) is 1, expected 0");
  fails_with(sbm_head + "1\n1\n1\n2\n2\n2\n1\n1 1\n0\n0\n2 1 1 2\n-5 -6\n",
             "e.dat:12: block-row pointer 0 (index1_data) is 1, expected 0");
  fails_with(sbm_head + "1\n1\n1\n2\n2\n2\n1\n0 1\n0\n0\n2 1 1\n", "the file ends too early");
  fails_with(sbm_head + "4000000000\n-5 -6\n", "e.dat:5: the number of non-zero blocks is 4000000000");
  // Messages stay valid UTF-8 whatever the file holds.
  CHECK_THROWS_WITH(cpkit::parse_lcp_dat("\xff\xfe\n", "e.dat"), Contains("got '\xEF\xBF\xBD\xEF\xBF\xBD'"));
}

TEST_CASE(".dat name and note", "[io][dat]") {
  const auto p = cpkit::parse_lcp_dat("1\n0\n1\n1\n1 1\n2\n-1\n\n# first line\nsecond \xff line\n",
                                      "dir/prob\xfe.dat");
  CHECK(p.note == "# first line\nsecond \xEF\xBF\xBD line");  // free text, valid UTF-8
  CHECK(p.name == "prob\xEF\xBF\xBD");                       // the stem, valid UTF-8
  CHECK(p.M(0, 0) == 2);
  CHECK(p.q[0] == -1);
}

TEST_CASE("write_lcp_dat writes what the reader (and Siconos) reads back exactly", "[io][dat]") {
  SECTION("dense") {
    LcpProblem p(Mat{{1.5, -2, 0.1}, {1e-300, 4, -0.0}, {5e-324, 1.7976931348623157e308, 3}},
                 Vec{{0.1, -7, 1.0 / 3.0}}, "rt");
    p.note = "round trip";
    const auto path = (scratch() / "rt.dat").string();
    cpkit::write_lcp_dat(p, path);
    const auto b = cpkit::read_lcp_dat(path);
    CHECK_FALSE(b.is_sparse());
    CHECK(b.M == p.M);
    CHECK(b.q == p.q);
    CHECK(b.note == "round trip");
    // Siconos' dense header: n, storage 0, size0, size1, then "size0<TAB>size1".
    std::ifstream in(path);
    std::string line;
    std::vector<std::string> head;
    for (int k = 0; k < 6 && std::getline(in, line); ++k) head.push_back(line);
    CHECK(head == std::vector<std::string>{"3", "0", "3", "3", "3\t3", "1.5 1e-300 4.9406564584124654e-324"});
  }
  SECTION("sparse: a sparse block matrix of 1 x 1 blocks") {
    LcpProblem p;
    p.M_sparse = Mat{{2, 0, -1}, {0, 0, 0}, {3, 0, 4}}.sparseView();
    p.q = Vec{{-1, 0, 1}};
    const auto path = (scratch() / "rt_sparse.dat").string();
    cpkit::write_lcp_dat(p, path);
    const auto b = cpkit::read_lcp_dat(path);
    CHECK(b.is_sparse());
    CHECK(b.dense_M() == p.dense_M());
    CHECK(b.q == p.q);
  }
  SECTION("a note that starts with a number is written as a comment") {
    LcpProblem p(Mat{{1}}, Vec{{-1}});
    p.note = "2009 remark";
    const auto path = (scratch() / "note.dat").string();
    cpkit::write_lcp_dat(p, path);
    CHECK(cpkit::read_lcp_dat(path).note == "# 2009 remark");
  }
}
