// Matrix Market files (https://math.nist.gov/MatrixMarket/formats.html): the header line, '%'
// comment lines, a size line, then one entry per line. Sizes are checked against
// kMaxMatrixMarketDimension and the entry count against the lines actually in the file before
// anything is allocated; duplicate entries (which Eigen would silently add) are errors.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <numeric>
#include <string>
#include <string_view>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"
#include "io_text.hpp"

namespace cpkit {
namespace {

struct Line {
  std::string_view text;
  int number = 0;
};

/// The lines of a text, in order, with 1-based numbers.
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {}
  bool next(Line& out) {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    out = {text_.substr(pos_, end - pos_), ++number_};
    pos_ = end + 1;
    return true;
  }
  /// The next line that is neither blank nor a '%' comment.
  bool next_data(Line& out) {
    while (next(out)) {
      const std::size_t first = out.text.find_first_not_of(" \t\r\v\f");
      if (first != std::string_view::npos && out.text[first] != '%') return true;
    }
    return false;
  }
  /// How many lines are left at most (an entry needs one).
  std::uint64_t lines_left() const {
    if (pos_ >= text_.size()) return 0;
    const auto rest = text_.substr(pos_);
    return static_cast<std::uint64_t>(std::count(rest.begin(), rest.end(), '\n')) + 1;
  }
  int number() const { return number_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int number_ = 0;
};

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

struct Entry {
  int row, col;
  double value;
  int line;
};

class MatrixMarketParser {
 public:
  MatrixMarketParser(const std::string& text, const std::string& origin)
      : lines_(text), origin_(origin) {}

  SparseMat parse() {
    read_header();
    read_sizes();
    read_entries();
    if (Line extra; lines_.next_data(extra))
      fail(extra.number, "more entries than the " + std::to_string(count_) +
                             " announced by the size line");
    if (coordinate_) reject_duplicates();
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(entries_.size());
    for (const Entry& e : entries_) triplets.emplace_back(e.row, e.col, e.value);
    SparseMat m(rows_, cols_);
    m.setFromTriplets(triplets.begin(), triplets.end());
    m.makeCompressed();
    return m;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& message) const {
    throw InputError(origin_ + ":" + std::to_string(line) + ": " + message);
  }

  void read_header() {
    Line l;
    if (!lines_.next(l))
      throw InputError(origin_ + ": empty file (expected a '%%MatrixMarket matrix ...' header)");
    const auto t = io_text::tokenize(l.text);
    const char* expected =
        " (expected '%%MatrixMarket matrix coordinate|array real|integer general|symmetric')";
    if (t.size() != 5 || lower(t[0].text) != "%%matrixmarket" || lower(t[1].text) != "matrix")
      fail(1, std::string("not a Matrix Market matrix header") + expected);
    const std::string format = lower(t[2].text), field = lower(t[3].text),
                      symmetry = lower(t[4].text);
    if (format != "coordinate" && format != "array")
      fail(1, "unsupported format '" + io_text::quoted(format) + "'" + expected);
    if (field != "real" && field != "integer" && field != "double")
      fail(1, "unsupported field '" + io_text::quoted(field) + "' (real or integer only)");
    if (symmetry != "general" && symmetry != "symmetric")
      fail(1, "unsupported symmetry '" + io_text::quoted(symmetry) + "' (general or symmetric only)");
    coordinate_ = format == "coordinate";
    symmetric_ = symmetry == "symmetric";
  }

  std::int64_t size_number(const io_text::Token& t, const Line& l, std::int64_t lo,
                           std::int64_t hi, const std::string& what) const {
    std::int64_t v = 0;
    if (!io_text::parse_integer(t.text, v))
      fail(l.number, "bad size line '" + io_text::quoted(l.text) + "': " + what +
                         " is not an integer");
    if (v < lo || v > hi)
      fail(l.number, what + " = " + std::to_string(v) + " is outside [" + std::to_string(lo) + ", " +
                         std::to_string(hi) + "]" +
                         (hi == kMaxMatrixMarketDimension ? " (the reader's size limit)" : ""));
    return v;
  }

  void read_sizes() {
    Line l;
    if (!lines_.next_data(l)) fail(lines_.number(), "the size line is missing");
    const auto t = io_text::tokenize(l.text);
    const std::size_t expected = coordinate_ ? 3 : 2;
    if (t.size() != expected)
      fail(l.number, "bad size line '" + io_text::quoted(l.text) + "' (expected " +
                         (coordinate_ ? "'rows columns entries'" : "'rows columns'") + ")");
    rows_ = size_number(t[0], l, 1, kMaxMatrixMarketDimension, "rows");
    cols_ = size_number(t[1], l, 1, kMaxMatrixMarketDimension, "columns");
    if (symmetric_ && rows_ != cols_)
      fail(l.number, "a symmetric matrix must be square, the size line says " +
                         std::to_string(rows_) + " x " + std::to_string(cols_));
    // At most 1e14 (both sizes <= 1e7): no overflow.
    const std::int64_t full = symmetric_ ? rows_ * (rows_ + 1) / 2 : rows_ * cols_;
    count_ = coordinate_ ? size_number(t[2], l, 0, full, "entries") : full;
    if (static_cast<std::uint64_t>(count_) > lines_.lines_left())
      fail(l.number, "the size line announces " + std::to_string(count_) +
                         " entries but the file has only " + std::to_string(lines_.lines_left()) +
                         " more lines");
  }

  void read_entries() {
    entries_.reserve(static_cast<std::size_t>(symmetric_ ? 2 * count_ : count_));  // backed by lines
    std::int64_t ai = 0, aj = 0;  // array format: the position of the next value
    for (std::int64_t k = 0; k < count_; ++k) {
      Line l;
      if (!lines_.next_data(l))
        fail(lines_.number(), "expected " + std::to_string(count_) + " entries, found " +
                                  std::to_string(k));
      const auto t = io_text::tokenize(l.text);
      std::int64_t i = ai, j = aj;
      if (coordinate_) {
        if (t.size() != 3 || !io_text::parse_integer(t[0].text, i) ||
            !io_text::parse_integer(t[1].text, j))
          fail(l.number, "bad entry '" + io_text::quoted(l.text) + "' (expected 'row column value')");
        if (i < 1 || i > rows_ || j < 1 || j > cols_)
          fail(l.number, "bad entry '" + io_text::quoted(l.text) + "': (" + std::to_string(i) + ", " +
                             std::to_string(j) + ") is outside the " + std::to_string(rows_) + " x " +
                             std::to_string(cols_) + " matrix");
        --i, --j;
      } else {
        if (t.size() != 1) fail(l.number, "bad entry '" + io_text::quoted(l.text) + "' (expected one value)");
        // Column-major; a symmetric array lists the lower triangle column by column.
        if (++ai == rows_) {
          ++aj;
          ai = symmetric_ ? aj : 0;
        }
      }
      double v = 0;
      if (const auto r = io_text::parse_real(t.back().text, v); r != io_text::Number::kOk)
        fail(l.number, "bad entry: " + io_text::describe(r, t.back().text));
      if (!coordinate_ && v == 0) continue;  // array format lists zeros; sparse storage does not
      add(i, j, v, l.number);
      if (symmetric_ && i != j) add(j, i, v, l.number);
    }
  }

  void add(std::int64_t i, std::int64_t j, double v, int line) {
    entries_.push_back({static_cast<int>(i), static_cast<int>(j), v, line});
  }

  void reject_duplicates() const {
    std::vector<std::size_t> order(entries_.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    const auto key = [&](std::size_t k) { return std::make_pair(entries_[k].col, entries_[k].row); };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return key(a) != key(b) ? key(a) < key(b) : entries_[a].line < entries_[b].line;
    });
    for (std::size_t k = 1; k < order.size(); ++k) {
      const Entry& a = entries_[order[k - 1]];
      const Entry& b = entries_[order[k]];
      if (a.row == b.row && a.col == b.col)
        fail(b.line, "entry (" + std::to_string(b.row + 1) + ", " + std::to_string(b.col + 1) +
                         ") is given twice (also line " + std::to_string(a.line) + ")" +
                         (symmetric_ ? "; a symmetric file gives each off-diagonal pair once" : ""));
    }
  }

  Lines lines_;
  const std::string& origin_;
  bool coordinate_ = true;
  bool symmetric_ = false;
  std::int64_t rows_ = 0, cols_ = 0, count_ = 0;
  std::vector<Entry> entries_;
};

}  // namespace

SparseMat parse_matrix_market(const std::string& text, const std::string& origin_in) {
  const std::string origin = io_text::valid_utf8(origin_in);
  return MatrixMarketParser(text, origin).parse();
}

SparseMat read_matrix_market(const std::string& path) {
  return parse_matrix_market(io_text::read_text(path), path);
}

Vec parse_matrix_market_vector(const std::string& text, const std::string& origin) {
  const SparseMat m = parse_matrix_market(text, origin);
  if (m.cols() != 1 && m.rows() != 1)
    throw InputError(io_text::valid_utf8(origin) + ": expected a vector (n x 1), got " +
                     std::to_string(m.rows()) + " x " + std::to_string(m.cols()));
  Vec v = Vec::Zero(std::max(m.rows(), m.cols()));  // <= kMaxMatrixMarketDimension
  for (Eigen::Index k = 0; k < m.outerSize(); ++k)
    for (SparseMat::InnerIterator it(m, k); it; ++it) v[m.cols() == 1 ? it.row() : it.col()] = it.value();
  return v;
}

Vec read_matrix_market_vector(const std::string& path) {
  return parse_matrix_market_vector(io_text::read_text(path), path);
}

}  // namespace cpkit
