#pragma once
/// \file io.hpp
/// Problem files; docs/file_formats.md describes every format exactly as read here.
/// - JSON: {"M": [[row], ...], "q": [...]} with M row-major, optional "name", "note", "source",
///   "expected"; or {"M_mtx": "M.mtx", "q_mtx": "q.mtx"} naming Matrix Market files (paths
///   relative to the JSON file, sparse storage). Any other top-level field is an error.
/// - Siconos .dat, as Siconos' linearComplementarity_newFromFile reads it: n, then M as a
///   NumericsMatrix (storage type 0 dense, column-major; 1 sparse block matrix), then q; free
///   text after q is kept as the note. Sparse block matrices give sparse storage.
/// - Matrix Market (coordinate or array; real, integer or double; general, symmetric) for M,
///   with q in a second Matrix Market file.
/// Malformed input throws InputError naming the file and the line or field, before anything is
/// allocated in proportion to a size the file states but does not back with data.
#include <Eigen/Core>
#include <string>

#include "cpkit/core/problem.hpp"

namespace cpkit {

/// Deepest JSON nesting read ({"M": [[1]]} has depth 3); deeper files are an InputError.
inline constexpr int kMaxJsonDepth = 64;
/// Largest number of rows or columns a Matrix Market file may declare. A sparse file declares
/// sizes that its entries do not back, and q is stored densely: this bounds that allocation.
inline constexpr Eigen::Index kMaxMatrixMarketDimension = 10'000'000;

LcpProblem read_lcp_json(const std::string& path);
LcpProblem parse_lcp_json(const std::string& text, const std::string& origin = "<string>");
LcpProblem read_lcp_dat(const std::string& path);
LcpProblem parse_lcp_dat(const std::string& text, const std::string& origin = "<string>");

/// The q file that belongs beside a Matrix Market M: "dir/A.mtx" -> "dir/A.q.mtx".
std::string matrix_market_q_path(const std::string& m_path);
/// M from the Matrix Market file `m_path` (sparse storage), q from `q_path`, or, when `q_path`
/// is empty, from matrix_market_q_path(m_path). Without a q file: InputError saying what to do.
LcpProblem read_lcp_matrix_market(const std::string& m_path, const std::string& q_path = {});

/// Dispatches on the extension (case-insensitive): .json, .dat or .mtx; otherwise InputError.
/// `q_path` (the q of a Matrix Market M) is accepted only with .mtx.
LcpProblem read_lcp_file(const std::string& path, const std::string& q_path = {});

void write_lcp_json(const LcpProblem& p, const std::string& path);
/// Writes the Siconos format that Siconos' reader reads back: dense storage (0) for a dense
/// problem, a sparse block matrix of 1 x 1 blocks (storage 1) for a sparse one; 17 significant
/// digits, so a round trip is exact.
void write_lcp_dat(const LcpProblem& p, const std::string& path);

/// Matrix Market matrix (coordinate or array format), as a sparse matrix.
SparseMat read_matrix_market(const std::string& path);
SparseMat parse_matrix_market(const std::string& text, const std::string& origin = "<string>");
/// Matrix Market vector: an n x 1 (or 1 x n) matrix.
Vec read_matrix_market_vector(const std::string& path);
Vec parse_matrix_market_vector(const std::string& text, const std::string& origin = "<string>");

}  // namespace cpkit
