#include "sparse_from.hpp"

#include <pybind11/numpy.h>

#include <climits>
#include <cstddef>
#include <vector>

#include "cpkit/core/errors.hpp"

namespace cpkit::py {
namespace {

namespace pyb = pybind11;
using Triplet = Eigen::Triplet<double>;
using IndexArray = pyb::array_t<long long, pyb::array::c_style | pyb::array::forcecast>;
using ValueArray = pyb::array_t<double, pyb::array::c_style | pyb::array::forcecast>;

std::string dtype_name(const pyb::array& a) { return pyb::str(a.dtype()); }

/// m.<attr> as a numpy array (TypeError when m has no such attribute).
pyb::array array_attr(const pyb::handle& m, const char* attr, const std::string& name) {
  if (!pyb::hasattr(m, attr))
    throw pyb::type_error(name + " must be a scipy.sparse matrix (it has no '" + attr + "')");
  pyb::array a = pyb::array::ensure(m.attr(attr));
  if (!a || a.ndim() != 1)
    throw pyb::type_error(name + "." + attr + " must be a 1-D numpy array");
  return a;
}

/// An index array (indices, indptr, row, col) as 64-bit integers; TypeError for another dtype.
IndexArray index_array(const pyb::handle& m, const char* attr, const std::string& name) {
  pyb::array a = array_attr(m, attr, name);
  const char kind = a.dtype().kind();
  if (!(kind == 'i' || (kind == 'u' && a.itemsize() < 8)))
    throw pyb::type_error(name + "." + attr + " must hold integers, got dtype " + dtype_name(a));
  return IndexArray::ensure(a);
}

/// The stored values as float64; TypeError for complex (its imaginary part would be lost) or
/// anything that is not a real number.
ValueArray value_array(const pyb::handle& m, const std::string& name) {
  pyb::array a = array_attr(m, "data", name);
  const char kind = a.dtype().kind();
  if (kind == 'c')
    throw pyb::type_error(name + " has complex entries (dtype " + dtype_name(a) +
                          "): cpkit solves real problems");
  if (kind != 'b' && kind != 'i' && kind != 'u' && kind != 'f')
    throw pyb::type_error(name + " must hold real numbers, got dtype " + dtype_name(a));
  return ValueArray::ensure(a);
}

struct Shape {
  long long rows = 0, cols = 0;
};

Shape shape_of(const pyb::handle& m, const std::string& name) {
  if (!pyb::hasattr(m, "shape")) throw pyb::type_error(name + " must be a scipy.sparse matrix");
  const pyb::tuple s = pyb::tuple(m.attr("shape"));
  if (s.size() != 2)
    throw InputError(name + " must be 2-D, got " + std::to_string(s.size()) + " dimensions");
  const Shape out{s[0].cast<long long>(), s[1].cast<long long>()};
  for (const long long n : {out.rows, out.cols})
    if (n < 0 || n > INT_MAX)
      throw InputError(name + ": size " + std::to_string(n) + " outside [0, 2^31 - 1]");
  return out;
}

std::string size_text(const Shape& s) {
  return std::to_string(s.rows) + " x " + std::to_string(s.cols);
}

void check_entry(long long row, long long col, const Shape& s, const std::string& name) {
  if (row < 0 || row >= s.rows || col < 0 || col >= s.cols)
    throw InputError(name + ": entry (" + std::to_string(row) + ", " + std::to_string(col) +
                     ") outside its " + size_text(s) + " size");
}

void check_same_length(std::size_t a, const char* a_name, std::size_t b, const char* b_name,
                       const std::string& name) {
  if (a != b)
    throw InputError(name + ": " + a_name + " has " + std::to_string(a) + " entries but " +
                     b_name + " has " + std::to_string(b));
}

/// The entries of a CSC (by columns) or CSR (by rows) matrix, checked.
std::vector<Triplet> compressed_entries(const pyb::handle& m, const Shape& s, bool by_columns,
                                        const std::string& name) {
  const IndexArray ptr = index_array(m, "indptr", name);
  const IndexArray idx = index_array(m, "indices", name);
  const ValueArray val = value_array(m, name);
  const long long outer = by_columns ? s.cols : s.rows;
  const auto nnz = static_cast<long long>(idx.size());
  check_same_length(idx.size(), "indices", val.size(), "data", name);
  if (ptr.size() != outer + 1)
    throw InputError(name + ": indptr has " + std::to_string(ptr.size()) + " entries; a " +
                     size_text(s) + (by_columns ? " CSC" : " CSR") + " matrix needs " +
                     std::to_string(outer + 1));
  const long long* p = ptr.data();
  if (p[0] != 0) throw InputError(name + ": indptr[0] = " + std::to_string(p[0]) + ", must be 0");
  for (long long j = 0; j < outer; ++j)
    if (p[j + 1] < p[j])
      throw InputError(name + ": indptr decreases: indptr[" + std::to_string(j + 1) + "] = " +
                       std::to_string(p[j + 1]) + " < indptr[" + std::to_string(j) + "] = " +
                       std::to_string(p[j]));
  if (p[outer] != nnz)
    throw InputError(name + ": indptr ends at " + std::to_string(p[outer]) + " but " +
                     std::to_string(nnz) + " entries are stored (len(indices))");
  std::vector<Triplet> t;
  t.reserve(static_cast<std::size_t>(nnz));
  const long long* i = idx.data();
  const double* v = val.data();
  for (long long j = 0; j < outer; ++j)
    for (long long k = p[j]; k < p[j + 1]; ++k) {
      const long long row = by_columns ? i[k] : j, col = by_columns ? j : i[k];
      check_entry(row, col, s, name);
      t.emplace_back(static_cast<int>(row), static_cast<int>(col), v[k]);
    }
  return t;
}

/// The entries of a COO matrix (row, col, data), checked.
std::vector<Triplet> coordinate_entries(const pyb::handle& m, const Shape& s,
                                        const std::string& name) {
  const IndexArray row = index_array(m, "row", name);
  const IndexArray col = index_array(m, "col", name);
  const ValueArray val = value_array(m, name);
  check_same_length(row.size(), "row", col.size(), "col", name);
  check_same_length(row.size(), "row", val.size(), "data", name);
  std::vector<Triplet> t;
  t.reserve(static_cast<std::size_t>(row.size()));
  for (pyb::ssize_t k = 0; k < row.size(); ++k) {
    check_entry(row.data()[k], col.data()[k], s, name);
    t.emplace_back(static_cast<int>(row.data()[k]), static_cast<int>(col.data()[k]),
                   val.data()[k]);
  }
  return t;
}

}  // namespace

SparseMat sparse_from(const pybind11::handle& m, const std::string& name) {
  const std::string format =
      pyb::hasattr(m, "format") ? std::string(pyb::str(m.attr("format"))) : std::string();
  if (format != "csc" && format != "csr" && format != "coo")
    throw pyb::type_error(name + " must be a scipy.sparse matrix in CSC, CSR or COO format" +
                          (format.empty() ? std::string() : ", got '" + format + "'"));
  const Shape s = shape_of(m, name);
  // Eigen allocates one column start per declared column, whatever the entries: a huge declared
  // size with no entries must not become a huge allocation.
  constexpr long long kMaxColumns = (1LL << 30) / 4;  // 1 GiB of column starts, the module's bound
  if (s.cols > kMaxColumns)
    throw InputError(name + ": " + size_text(s) + " declares more than " +
                     std::to_string(kMaxColumns) + " columns (1 GiB of column starts)");
  const std::vector<Triplet> t =
      format == "coo" ? coordinate_entries(m, s, name)
                      : compressed_entries(m, s, format == "csc", name);
  SparseMat out(static_cast<Eigen::Index>(s.rows), static_cast<Eigen::Index>(s.cols));
  out.setFromTriplets(t.begin(), t.end());  // duplicates summed
  return out;
}

}  // namespace cpkit::py
