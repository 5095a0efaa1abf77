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
/// - numpy .npy (little-endian float64, C or Fortran order) for M, with q in a second .npy file.
/// Malformed input throws InputError naming the file and the line or field, before anything is
/// allocated in proportion to a size the file states but does not back with data.
#include <Eigen/Core>
#include <string>

#include "cpkit/core/json_read.hpp"  // kMaxJsonDepth
#include "cpkit/core/problem.hpp"

namespace cpkit {

/// Largest number of rows or columns a Matrix Market file may declare. A sparse file declares
/// sizes that its entries do not back, and q is stored densely: this bounds that allocation.
inline constexpr Eigen::Index kMaxMatrixMarketDimension = 10'000'000;

LcpProblem read_lcp_json(const std::string& path);
/// Reads a JSON problem. Dense files are parsed with simdjson (a small fraction of a solve even
/// for n in the thousands); every other case, and every error, with the reference reader below,
/// so that the result and every message are the reference reader's.
LcpProblem parse_lcp_json(const std::string& text, const std::string& origin = "<string>");
/// The reference JSON reader (nlohmann's SAX parser; slower): same result and messages as
/// parse_lcp_json. Public so that the tests can compare the two on every input.
LcpProblem parse_lcp_json_reference(const std::string& text,
                                    const std::string& origin = "<string>");
LcpProblem read_lcp_dat(const std::string& path);
LcpProblem parse_lcp_dat(const std::string& text, const std::string& origin = "<string>");

/// The q file that belongs beside a Matrix Market or .npy M: "dir/A.mtx" -> "dir/A.q.mtx",
/// "dir/A.npy" -> "dir/A.q.npy".
std::string matrix_market_q_path(const std::string& m_path);
/// M from the Matrix Market file `m_path` (sparse storage), q from `q_path`, or, when `q_path`
/// is empty, from matrix_market_q_path(m_path). Without a q file: InputError saying what to do.
LcpProblem read_lcp_matrix_market(const std::string& m_path, const std::string& q_path = {});

/// numpy .npy arrays (format 1.0, 2.0, 3.0) of little-endian float64 ('<f8'), C or Fortran
/// order; the header is parsed strictly and the data must be exactly as long as the shape says.
/// A matrix needs a 2-D shape, a vector (n,) or (n, 1). `origin` names the file in messages.
Mat parse_npy_matrix(const std::string& bytes, const std::string& origin = "<string>");
Vec parse_npy_vector(const std::string& bytes, const std::string& origin = "<string>");
/// M from the .npy file `m_path` (dense), q from `q_path`, or, when `q_path` is empty, from
/// matrix_market_q_path(m_path) ("dir/M.npy" -> "dir/M.q.npy").
LcpProblem read_lcp_npy(const std::string& m_path, const std::string& q_path = {});

/// Dispatches on the extension (case-insensitive): .json, .dat, .mtx or .npy. A path without an
/// extension (a pipe such as `<(cat f.json)`, /dev/fd/63) is read once and its format told by its
/// content: the .npy magic, the Matrix Market banner %%MatrixMarket, '{' (JSON), a number or '#'
/// (Siconos .dat). Any other extension is an InputError. `q_path` (the q of a Matrix Market or .npy M) is accepted only with .mtx, .npy.
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
