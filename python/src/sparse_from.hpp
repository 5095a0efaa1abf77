#pragma once
// Sparse matrices handed over from Python, checked before Eigen sees them (issue 34, F4-06).
// pybind11's own Eigen caster maps scipy's (data, indices, indptr) without looking at them, and
// scipy's constructor checks index bounds only when asked for a full check: an index out of
// range crashed the interpreter, a negative one silently dropped an entry. Every binding that
// takes a sparse matrix takes it through sparse_from.
#include <pybind11/pybind11.h>

#include <string>

#include "cpkit/core/problem.hpp"

namespace cpkit::py {

/// The scipy.sparse matrix (or array) `m`, in format "csc", "csr" or "coo", as a column-major
/// Eigen matrix, read from its own arrays after checking every size and index:
/// - shape: two sizes in [0, 2^31 - 1], at most 2^28 columns (Eigen's column starts within the
///   module's 1 GiB bound);
/// - data: bool, integer or float entries; complex or anything else raises TypeError;
/// - csc/csr: indptr has (columns or rows) + 1 integers, starts at 0, never decreases and ends at
///   the number of stored entries (len(indices) == len(data)); coo: row, col and data of one
///   length;
/// - every row index in [0, rows) and column index in [0, cols).
/// A bad size or index raises ValueError (InputError) naming it, as the FCLIB reader does:
/// "W: entry (7, 2) outside its 3 x 3 size" (row, column, counted from 0). Duplicate entries
/// are summed and unsorted indices accepted (scipy's meaning of both).
SparseMat sparse_from(const pybind11::handle& m, const std::string& name);

}  // namespace cpkit::py
