// Siconos .dat LCP files, read as Siconos numerics 4.4 reads them:
//   linearComplementarity_newFromFile: n, then M (NM_new_from_file), then q (M's size1 numbers);
//   NM_new_from_file: storage type, size0, size1, then
//     0 (NM_DENSE): size0 size1 again, then size0 * size1 entries in column-major order;
//     1 (NM_SPARSE_BLOCK, SBM_new_from_file): nbblocks; if non-zero, blocknumber0,
//       blocknumber1, the cumulative block row sizes, the cumulative block column sizes,
//       filled1, filled2, index1_data (block-row pointers), index2_data (block columns), then
//       for each block in order its number and its entries (column-major within the block).
// Siconos checks nothing; here every count is checked against the header and against what is
// left in the file before anything is allocated for it.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"
#include "io_dat_matrix.hpp"
#include "io_text.hpp"

namespace cpkit {
namespace io_dat {
namespace {

std::string size_text(std::int64_t rows, std::int64_t cols) {
  return std::to_string(rows) + " x " + std::to_string(cols);
}

/// Cumulative block sizes: strictly increasing, the last equal to n.
std::vector<std::int64_t> read_cumulative_sizes(DatReader& r, std::int64_t blocks, std::int64_t n,
                                                const std::string& what, const std::string& name,
                                                const std::string& size) {
  std::vector<std::int64_t> sizes;
  sizes.reserve(static_cast<std::size_t>(blocks));  // blocks <= remaining tokens (checked)
  std::int64_t previous = 0;
  int line = r.line();
  for (std::int64_t b = 0; b < blocks; ++b) {
    line = r.line();
    const std::int64_t s = r.integer(
        [&] { return "the cumulative " + what + " size " + std::to_string(b); }, 1, n);
    if (s <= previous)
      r.fail(line, "cumulative " + what + " sizes must increase: " + std::to_string(s) +
                       " follows " + std::to_string(previous));
    sizes.push_back(s);
    previous = s;
  }
  if (previous != n)
    r.fail(line, "the " + what + " sizes add up to " + std::to_string(previous) + ", but " + name +
                     " is " + size);
  return sizes;
}

}  // namespace

Eigen::MatrixXd read_dense(DatReader& r, std::int64_t n_rows, std::int64_t n_cols,
                           std::uint64_t after, const std::string& name,
                           const std::string& after_what) {
  r.integer("the number of rows of the dense " + name + " (repeated)", n_rows, n_rows);
  r.integer("the number of columns of the dense " + name + " (repeated)", n_cols, n_cols);
  const auto count = static_cast<std::uint64_t>(n_rows) * static_cast<std::uint64_t>(n_cols);
  r.need(count + after, "the " + size_text(n_rows, n_cols) + " entries of " + name + " and the " +
                            std::to_string(after) + " entries of " + after_what);
  Eigen::MatrixXd M(n_rows, n_cols);
  for (std::int64_t c = 0; c < n_cols; ++c)  // column-major: Siconos' matrix0 storage order
    for (std::int64_t i = 0; i < n_rows; ++i)
      M(i, c) = r.real(
          [&] { return name + "(" + std::to_string(i) + ", " + std::to_string(c) + ")"; });
  return M;
}

Eigen::SparseMatrix<double> read_sparse_block(DatReader& r, std::int64_t n_rows,
                                              std::int64_t n_cols, const std::string& name) {
  const std::string size = size_text(n_rows, n_cols);
  Eigen::SparseMatrix<double> M(n_rows, n_cols);
  const std::int64_t nbblocks =
      r.integer("the number of non-zero blocks", 0, static_cast<std::int64_t>(r.remaining()));
  if (nbblocks == 0) return M;  // Siconos writes only "0" for a matrix without blocks
  const std::int64_t rows = r.integer("the number of block rows", 1, n_rows);
  const std::int64_t cols = r.integer("the number of block columns", 1, n_cols);
  r.need(static_cast<std::uint64_t>(rows + cols), "the cumulative block sizes");
  const auto row_end = read_cumulative_sizes(r, rows, n_rows, "block row", name, size);
  const auto col_end = read_cumulative_sizes(r, cols, n_cols, "block column", name, size);
  // filled1 = number of block-row pointers: trailing empty block rows may be left out.
  const std::int64_t filled1 = r.integer("filled1 (the number of block-row pointers)", 1, rows + 1);
  r.integer("filled2 (the number of non-zero blocks, as nbblocks)", nbblocks, nbblocks);
  r.need(static_cast<std::uint64_t>(filled1 + nbblocks), "the block-row pointers and block columns");
  std::vector<std::int64_t> row_ptr(static_cast<std::size_t>(filled1));
  for (std::int64_t k = 0; k < filled1; ++k) {
    const std::int64_t lo = k == 0 ? 0 : row_ptr[static_cast<std::size_t>(k - 1)];
    const std::int64_t hi = k == 0 ? 0 : nbblocks;
    const int line = r.line();
    row_ptr[static_cast<std::size_t>(k)] =
        r.integer([&] { return "block-row pointer " + std::to_string(k) + " (index1_data)"; }, lo, hi);
    if (k == filled1 - 1 && row_ptr[static_cast<std::size_t>(k)] != nbblocks)
      r.fail(line, "the last block-row pointer is " + std::to_string(row_ptr.back()) +
                       ", but the header announces " + std::to_string(nbblocks) + " blocks");
  }
  std::vector<std::int64_t> block_col(static_cast<std::size_t>(nbblocks));
  for (std::int64_t b = 0; b < nbblocks; ++b)
    block_col[static_cast<std::size_t>(b)] =
        r.integer([&] { return "the block column of block " + std::to_string(b) + " (index2_data)"; },
                  0, cols - 1);

  std::vector<Eigen::Triplet<double>> entries;
  std::vector<std::int64_t> seen_in_row(static_cast<std::size_t>(cols), -1);  // cols <= n_cols
  for (std::int64_t br = 0; br + 1 < filled1; ++br) {
    const std::int64_t r0 = br == 0 ? 0 : row_end[static_cast<std::size_t>(br - 1)];
    const std::int64_t nr = row_end[static_cast<std::size_t>(br)] - r0;
    for (std::int64_t b = row_ptr[static_cast<std::size_t>(br)];
         b < row_ptr[static_cast<std::size_t>(br + 1)]; ++b) {
      const std::int64_t bc = block_col[static_cast<std::size_t>(b)];
      const int line = r.line();
      if (seen_in_row[static_cast<std::size_t>(bc)] == br)
        r.fail(line, "block " + std::to_string(b) + " repeats block (" + std::to_string(br) + ", " +
                         std::to_string(bc) + ")");
      seen_in_row[static_cast<std::size_t>(bc)] = br;
      r.integer([&] { return "the number of block " + std::to_string(b); }, b, b);
      const std::int64_t c0 = bc == 0 ? 0 : col_end[static_cast<std::size_t>(bc - 1)];
      const std::int64_t nc = col_end[static_cast<std::size_t>(bc)] - c0;
      const auto count = static_cast<std::uint64_t>(nr) * static_cast<std::uint64_t>(nc);
      r.need(count, "the " + std::to_string(nr) + " x " + std::to_string(nc) + " entries of block " +
                        std::to_string(b));
      for (std::int64_t k = 0; k < nr * nc; ++k) {  // column-major within the block
        const std::int64_t i = r0 + k % nr, j = c0 + k / nr;
        const double v = r.real([&] {
          return name + "(" + std::to_string(i) + ", " + std::to_string(j) + ") in block " +
                 std::to_string(b);
        });
        entries.emplace_back(static_cast<int>(i), static_cast<int>(j), v);
      }
    }
  }
  M.setFromTriplets(entries.begin(), entries.end());  // no duplicates: blocks are distinct
  M.makeCompressed();
  return M;
}

}  // namespace io_dat

namespace {

using io_dat::DatReader;
using io_text::Token;

bool starts_with_number(const std::vector<Token>& tokens, std::size_t k) {
  double v = 0;
  const auto r = io_text::parse_real(tokens[k].text, v);
  return r != io_text::Number::kNotANumber;
}

}  // namespace

LcpProblem parse_lcp_dat(const std::string& text, const std::string& origin_in) {
  const std::string origin = io_text::valid_utf8(origin_in);
  const auto tokens = io_text::tokenize(text);
  if (tokens.empty())
    throw InputError(origin + ": empty file (expected n, the storage type of M, M, then q)");
  DatReader r(tokens, origin);
  const std::int64_t n = r.integer("the problem size n", 1, io_dat::kMaxIndex);
  // Whatever M's storage, the file must still hold its type, two sizes and the n entries of q.
  r.need(3 + static_cast<std::uint64_t>(n), "the storage type and sizes of M and the entries of q");
  const int storage_line = r.line();
  const std::int64_t storage = r.integer("the storage type of M", std::numeric_limits<std::int64_t>::min(),
                                         std::numeric_limits<std::int64_t>::max());
  if (storage == 2)
    r.fail(storage_line, "storage type 2 (Siconos NM_SPARSE, a CSparse matrix) is not supported: "
                         "cpkit reads 0 (dense) and 1 (sparse block); for other sparse data use "
                         "Matrix Market");
  if (storage != 0 && storage != 1)
    r.fail(storage_line, "unknown storage type " + std::to_string(storage) +
                             " (Siconos: 0 dense, 1 sparse block, 2 sparse; cpkit reads 0 and 1)");
  const std::string need_n = " (an LCP needs an n x n matrix, n = " + std::to_string(n) + ")";
  r.integer("the number of rows of M" + need_n, n, n);
  r.integer("the number of columns of M" + need_n, n, n);
  LcpProblem p;
  if (storage == 0)
    p.M = io_dat::read_dense(r, n, n, static_cast<std::uint64_t>(n));
  else
    p.M_sparse = io_dat::read_sparse_block(r, n, n);
  r.need(static_cast<std::uint64_t>(n), "the " + std::to_string(n) + " entries of q");
  p.q.resize(n);
  for (std::int64_t i = 0; i < n; ++i)
    p.q[i] = r.real([&] { return "q[" + std::to_string(i) + "]"; });
  if (!r.done()) {
    // Free text after q is a comment. A number there means the header undercounts the data.
    if (starts_with_number(tokens, r.position()))
      r.fail(r.line(), "'" + io_text::quoted(tokens[r.position()].text) +
                           "' follows the " + std::to_string(n) +
                           " entries of q: the file holds more numbers than its header announces");
    std::string note = text.substr(tokens[r.position()].offset);
    note.erase(note.find_last_not_of(" \t\r\n\v\f") + 1);
    p.note = io_text::valid_utf8(note);
  }
  p.name = io_text::valid_utf8(std::filesystem::path(origin_in).stem().string());
  throw_if_invalid(p.validate(), origin);
  return p;
}

LcpProblem read_lcp_dat(const std::string& path) {
  return parse_lcp_dat(io_text::read_text(path), path);
}

void write_lcp_dat(const LcpProblem& p, const std::string& path) {
  throw_if_invalid(p.validate(), "write_lcp_dat");
  std::ostringstream out;
  out << std::setprecision(17);
  const Eigen::Index n = p.size();
  out << n << '\n';
  if (p.is_sparse() && p.M_sparse.nonZeros() > 0) {
    // Sparse block matrix of 1 x 1 blocks: block-row pointers and block columns are CSR.
    Eigen::SparseMatrix<double, Eigen::RowMajor, int> R = p.M_sparse;
    R.makeCompressed();
    const Eigen::Index nnz = R.nonZeros();
    out << "1\n" << n << '\n' << n << '\n' << nnz << '\n' << n << '\n' << n << '\n';
    for (int pass = 0; pass < 2; ++pass) {  // cumulative block row sizes, then column sizes
      for (Eigen::Index i = 1; i <= n; ++i) out << i << '\t';
      out << '\n';
    }
    out << n + 1 << '\n' << nnz << '\n';
    for (Eigen::Index i = 0; i <= n; ++i) out << R.outerIndexPtr()[i] << '\t';
    out << '\n';
    for (Eigen::Index k = 0; k < nnz; ++k) out << R.innerIndexPtr()[k] << '\t';
    out << '\n';
    for (Eigen::Index k = 0; k < nnz; ++k) out << k << '\n' << R.valuePtr()[k] << '\n';
  } else {
    const Mat m = p.dense_M();
    out << "0\n" << n << '\n' << n << '\n' << n << '\t' << n << '\n';
    for (Eigen::Index c = 0; c < n; ++c) {  // column-major, one column per line, as Siconos
      for (Eigen::Index r = 0; r < n; ++r) out << (r ? " " : "") << m(r, c);
      out << '\n';
    }
  }
  for (Eigen::Index i = 0; i < n; ++i) out << (i ? " " : "") << p.q[i];
  out << '\n';
  if (!p.note.empty()) {
    // The note is free text after q; one starting with a number would read as data.
    const auto first = io_text::tokenize(p.note);
    const bool numeric = !first.empty() && starts_with_number(first, 0);
    out << '\n' << (numeric ? "# " : "") << p.note << '\n';
  }
  std::ofstream file(path);
  if (!file) throw InputError(io_text::valid_utf8(path) + ": cannot write file");
  file << out.str();
}

}  // namespace cpkit
