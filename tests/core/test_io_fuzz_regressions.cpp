// Every input of tests/fuzz/regressions/<reader>/ (crashes, overflows and unbounded allocations
// found by fuzzing or named in issue 11) is refused with a clear InputError. The fuzz drivers
// replay the same files (ctest fuzz.<reader>); this test pins the message. A new regression
// file needs a row here.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"

namespace {

namespace fs = std::filesystem;
using Catch::Contains;

const fs::path kRegressions = fs::path(CPKIT_SOURCE_DIR) / "tests" / "fuzz" / "regressions";

/// The reader each folder fuzzes (as the harness calls it).
const std::map<std::string, std::function<void(const std::string&)>> kReaders = {
    {"json_lcp", [](const std::string& t) { cpkit::parse_lcp_json(t, "input.json"); }},
    {"dat", [](const std::string& t) { cpkit::parse_lcp_dat(t, "input.dat"); }},
    {"matrix_market", [](const std::string& t) { cpkit::parse_matrix_market(t, "input.mtx"); }},
    {"matrix_market_vector",
     [](const std::string& t) { cpkit::parse_matrix_market_vector(t, "input.q.mtx"); }},
    {"npy", [](const std::string& t) { cpkit::parse_npy_matrix(t, "input.npy"); }},
};

/// reader/file -> the message it must give (what used to happen, in the comment).
const std::map<std::string, std::string> kExpected = {
    // Stack overflow in nlohmann's recursive DOM destruction.
    {"json_lcp/nesting_10000.json", "input.json:1: nesting deeper than 64 levels"},
    // nlohmann's out_of_range exception escaped: exit 4, "internal error".
    {"json_lcp/number_1e400.json", "input.json:1: '1e400' is outside the range of double"},
    // Silently read as 0.
    {"json_lcp/number_underflow.json", "'-1e-400' is below the smallest double"},
    // Read as a bare matrix: "solved" for another problem.
    {"dat/headerless_old_layout.dat", "input.dat:3: the number of columns of M"},
    {"dat/n_beyond_data.dat", "input.dat:4: the file ends too early"},
    {"dat/sbm_blocks_beyond_data.dat", "input.dat:5: the number of non-zero blocks is 4000000000"},
    {"dat/storage_type_2.dat", "input.dat:2: storage type 2 (Siconos NM_SPARSE"},
    // Heap buffer overflow: the mirrored entry (3, 1) written outside a 2 x 3 matrix.
    {"matrix_market/symmetric_non_square.mtx", "input.mtx:2: a symmetric matrix must be square"},
    // reserve(2 * nnz) with nnz near INT64_MAX.
    {"matrix_market/nnz_int64_max.mtx", "input.mtx:2: entries = 9223372036854775807 is outside [0, 4]"},
    {"matrix_market/size_int64_max.mtx", "input.mtx:2: rows = 9223372036854775807 is outside"},
    // rows * cols overflowed.
    {"matrix_market/array_size_product_overflow.mtx", "input.mtx:2: rows = 4294967296 is outside"},
    // Heap buffer overflow: a symmetric q file with a non-square size.
    {"matrix_market_vector/symmetric_non_square_q.mtx", "input.q.mtx:2: a symmetric matrix must be square"},
    // .npy shapes that the data do not back: refused before M is allocated (no 128 PB resize).
    {"npy/shape_beyond_data.npy", "input.npy: shape (4000000000, 4000000000) needs more data than the 8 bytes"},
    {"npy/shape_product_overflow.npy", "needs more data than the 8 bytes after the header"},
    {"npy/header_length_beyond_file.npy", "input.npy: the .npy header length 4294967295 goes beyond"},
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

TEST_CASE("Fuzz regressions are refused with a clear message", "[io][fuzz]") {
  std::set<std::string> seen;
  for (const auto& [reader, read] : kReaders) {
    for (const auto& e : fs::directory_iterator(kRegressions / reader)) {
      const std::string key = reader + "/" + e.path().filename().string();
      INFO(key);
      seen.insert(key);
      const auto expected = kExpected.find(key);
      REQUIRE(expected != kExpected.end());  // every file has its message here
      const std::string text = slurp(e.path());
      CHECK_THROWS_AS(read(text), cpkit::InputError);
      CHECK_THROWS_WITH(read(text), Contains(expected->second));
    }
  }
  CHECK(seen.size() == kExpected.size());  // and every row has its file
}
