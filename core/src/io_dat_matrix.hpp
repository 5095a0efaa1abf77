#pragma once
// The token reader of Siconos .dat files and the NumericsMatrix storages Siconos 4.4 writes
// (NM_new_from_file: 0 dense, 1 sparse block, 2 sparse), shared by the LCP reader (io_dat.cpp) and the
// friction problem readers (friction_io_dat.cpp). Internal to cpkit_core.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "cpkit/core/errors.hpp"
#include "io_text.hpp"

namespace cpkit::io_dat {

using io_text::Token;

inline constexpr std::int64_t kMaxIndex = std::numeric_limits<int>::max();  // Eigen's index type

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

  /// The next token as text, which must be `expected`; `what` names where it stands.
  template <class What>
  void literal(std::string_view expected, const What& what) {
    const Token& t = take(what);
    if (t.text != expected)
      fail(t.line, "expected '" + std::string(expected) + "' (" + name(what) + "), got '" +
                       io_text::quoted(t.text) + "'");
  }

  /// The next token as text (a word of a header line); `what` names it.
  const Token& word(const std::string& what) { return take(what); }

  /// Skips the tokens on `line` (the rest of a free-text line).
  void skip_line(int line) {
    while (!done() && tokens_[next_].line == line) ++next_;
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

/// Storage 0 after its type and sizes: "rows cols" repeated, then rows * cols entries
/// column-major. `after` numbers must still follow (checked with the entries before allocating).
Eigen::MatrixXd read_dense(DatReader& r, std::int64_t rows, std::int64_t cols, std::uint64_t after,
                           const std::string& name = "M", const std::string& after_what = "q");

/// Storage 1 after its type and sizes: a SparseBlockStructuredMatrix (SBM_new_from_file).
Eigen::SparseMatrix<double> read_sparse_block(DatReader& r, std::int64_t rows, std::int64_t cols,
                                              const std::string& name = "M");

/// Storage 2 after its type and sizes: a NumericsSparseMatrix as NSM_write_in_file writes it,
/// its origin (1 triplet, 2 compressed columns), the CSparse banner line, the header line
/// ("[triplet: ]R-by-C, nzmax: Z nnz: N[, 1-norm: X]"), then the entries ("i j : x" per
/// triplet; "col j : locations a to b" then "i : x" per entry in a column).
/// io_dat_csparse.cpp. `after` numbers must follow.
Eigen::SparseMatrix<double> read_csparse(DatReader& r, std::int64_t rows, std::int64_t cols,
                                         std::uint64_t after, const std::string& name,
                                         const std::string& after_what);

}  // namespace cpkit::io_dat
