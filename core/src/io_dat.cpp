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
#include "io_text.hpp"

namespace cpkit {
namespace {

using io_text::Token;

constexpr std::int64_t kMaxIndex = std::numeric_limits<int>::max();  // Eigen's index type

/// Reads the tokens of a .dat file in order. Every error names the file and the line.
class DatReader {
 public:
  DatReader(const std::vector<Token>& tokens, const std::string& origin)
      : tokens_(tokens), origin_(origin) {}

  bool done() const { return next_ == tokens_.size(); }
  std::size_t position() const { return next_; }
  std::uint64_t remaining() const { return tokens_.size() - next_; }
  /// Line of the next token (of the last one at the end of the file).
  int line() const {
    if (tokens_.empty()) return 1;
    return tokens_[std::min(next_, tokens_.size() - 1)].line;
  }

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw InputError(origin_ + ":" + std::to_string(line) + ": " + message);
  }

  /// The next token as an integer in [lo, hi]. `what` names it: a string, or a callable that
  /// makes the string (only called for a message, so that loops over entries stay cheap).
  template <class What>
  std::int64_t integer(const What& what, std::int64_t lo, std::int64_t hi) {
    const Token& t = take(what);
    std::int64_t v = 0;
    if (!io_text::parse_integer(t.text, v))
      fail(t.line, "expected " + name(what) + " (an integer), got '" + io_text::quoted(t.text) + "'");
    if (v < lo || v > hi)
      fail(t.line, name(what) + " is " + std::to_string(v) + ", expected " + range(lo, hi));
    return v;
  }

  /// The next token as a finite double; `what` names it (as for integer()).
  template <class What>
  double real(const What& what) {
    const Token& t = take(what);
    double v = 0;
    if (const auto r = io_text::parse_real(t.text, v); r != io_text::Number::kOk)
      fail(t.line, name(what) + ": " + io_text::describe(r, t.text));
    return v;
  }

  /// InputError unless `count` more tokens are in the file; checked before allocating for them.
  void need(std::uint64_t count, const std::string& what) const {
    if (count > remaining())
      fail(tokens_.back().line, "the file ends too early: " + what + " need " + std::to_string(count) +
                       " more numbers, the file has " + std::to_string(remaining()));
  }

 private:
  template <class What>
  static std::string name(const What& what) {
    if constexpr (std::is_invocable_v<const What&>)
      return what();
    else
      return std::string(what);
  }
  template <class What>
  const Token& take(const What& what) {
    if (done()) fail(line(), "the file ends where " + name(what) + " was expected");
    return tokens_[next_++];
  }
  static std::string range(std::int64_t lo, std::int64_t hi) {
    if (lo == hi) return std::to_string(lo);
    if (hi == std::numeric_limits<std::int64_t>::max()) return ">= " + std::to_string(lo);
    return "in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  }

  const std::vector<Token>& tokens_;
  const std::string& origin_;
  std::size_t next_ = 0;
};

/// Storage 0: "size0 size1" repeated, then the n * n entries column-major.
Mat read_dense(DatReader& r, std::int64_t n) {
  const std::string ns = std::to_string(n);
  r.integer("the number of rows of the dense M (repeated)", n, n);
  r.integer("the number of columns of the dense M (repeated)", n, n);
  const auto count = static_cast<std::uint64_t>(n) * static_cast<std::uint64_t>(n);
  r.need(count + static_cast<std::uint64_t>(n),
         "the " + ns + " x " + ns + " entries of M and the " + ns + " entries of q");
  Mat M(n, n);
  for (std::int64_t c = 0; c < n; ++c)  // column-major: Siconos' matrix0 storage order
    for (std::int64_t i = 0; i < n; ++i)
      M(i, c) = r.real([&] { return "M(" + std::to_string(i) + ", " + std::to_string(c) + ")"; });
  return M;
}

/// Cumulative block sizes: strictly increasing, the last equal to n.
std::vector<std::int64_t> read_cumulative_sizes(DatReader& r, std::int64_t blocks, std::int64_t n,
                                                const std::string& what) {
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
    r.fail(line, "the " + what + " sizes add up to " + std::to_string(previous) + ", but M is " +
                         std::to_string(n) + " x " + std::to_string(n));
  return sizes;
}

/// Storage 1: a SparseBlockStructuredMatrix (SBM_new_from_file), as sparse storage.
SparseMat read_sparse_block(DatReader& r, std::int64_t n) {
  SparseMat M(n, n);
  const std::int64_t nbblocks =
      r.integer("the number of non-zero blocks", 0, static_cast<std::int64_t>(r.remaining()));
  if (nbblocks == 0) return M;  // Siconos writes only "0" for a matrix without blocks
  const std::int64_t rows = r.integer("the number of block rows", 1, n);
  const std::int64_t cols = r.integer("the number of block columns", 1, n);
  r.need(static_cast<std::uint64_t>(rows + cols), "the cumulative block sizes");
  const auto row_end = read_cumulative_sizes(r, rows, n, "block row");
  const auto col_end = read_cumulative_sizes(r, cols, n, "block column");
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
  std::vector<std::int64_t> seen_in_row(static_cast<std::size_t>(cols), -1);  // cols <= n
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
          return "M(" + std::to_string(i) + ", " + std::to_string(j) + ") in block " +
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
  const std::int64_t n = r.integer("the problem size n", 1, kMaxIndex);
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
    p.M = read_dense(r, n);
  else
    p.M_sparse = read_sparse_block(r, n);
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
