#pragma once
/// \file io.hpp
/// Problem files.
/// - JSON: {"M": [[row], ...], "q": [...]} with M row-major, optional "name", "note"; other
///   fields (e.g. "expected", "source") are ignored. A JSON file may instead name Matrix Market
///   files: {"M_mtx": "M.mtx", "q_mtx": "q.mtx"} (paths relative to the JSON file), giving
///   sparse storage.
/// - Siconos .dat: first token n, then M in column-major order (as Siconos stores it: the first
///   printed "row" is the first column), then q; trailing text is kept as the note.
/// - Matrix Market (coordinate or array, real, general/symmetric) for M and q.
/// Malformed input throws InputError naming the file and the line or field.
#include <string>

#include "cpkit/core/problem.hpp"

namespace cpkit {

LcpProblem read_lcp_json(const std::string& path);
LcpProblem parse_lcp_json(const std::string& text, const std::string& origin = "<string>");
LcpProblem read_lcp_dat(const std::string& path);
LcpProblem parse_lcp_dat(const std::string& text, const std::string& origin = "<string>");
/// Dispatches on the extension: .json or .dat (case-insensitive); otherwise InputError.
LcpProblem read_lcp_file(const std::string& path);

void write_lcp_json(const LcpProblem& p, const std::string& path);
void write_lcp_dat(const LcpProblem& p, const std::string& path);

/// Matrix Market: sparse matrix (coordinate or array format).
SparseMat read_matrix_market(const std::string& path);
/// Matrix Market vector (an n x 1 array or coordinate matrix).
Vec read_matrix_market_vector(const std::string& path);

}  // namespace cpkit
