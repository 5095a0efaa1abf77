// numpy .npy arrays (NEP 1, format versions 1.0, 2.0 and 3.0) of little-endian float64, C or
// Fortran order: the binary form of M and q (docs/file_formats.md). The header, a Python dict
// literal, is parsed strictly: exactly the keys 'descr', 'fortran_order' and 'shape', and the
// data must be exactly as long as the shape says, checked before anything is allocated.
#include <Eigen/Core>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"
#include "io_text.hpp"

namespace cpkit {
namespace {

/// The parsed header of a .npy file.
struct NpyHeader {
  bool fortran_order = false;
  std::vector<std::uint64_t> shape;
  std::size_t data_offset = 0;  ///< first byte of the data
};

/// Parser of the header dict, e.g. {'descr': '<f8', 'fortran_order': False, 'shape': (3, 3), }
class HeaderParser {
 public:
  HeaderParser(std::string_view text, const std::string& origin) : s_(text), origin_(origin) {}

  void parse(NpyHeader& h) {
    bool have_descr = false, have_order = false, have_shape = false;
    skip_spaces();
    expect('{');
    for (;;) {
      skip_spaces();
      if (peek() == '}') break;
      const std::string key = quoted_string();
      skip_spaces();
      expect(':');
      skip_spaces();
      if (key == "descr") {
        if (have_descr) fail("the key 'descr' appears twice");
        have_descr = true;
        const std::string d = quoted_string();
        if (d != "<f8")
          fail("dtype '" + io_text::quoted(d) +
               "' is not supported: cpkit reads little-endian float64 ('<f8'; in numpy "
               "a.astype('<f8'))");
      } else if (key == "fortran_order") {
        if (have_order) fail("the key 'fortran_order' appears twice");
        have_order = true;
        h.fortran_order = boolean();
      } else if (key == "shape") {
        if (have_shape) fail("the key 'shape' appears twice");
        have_shape = true;
        h.shape = tuple();
      } else {
        fail("unknown header key '" + io_text::quoted(key) +
             "' (a .npy header has 'descr', 'fortran_order' and 'shape')");
      }
      skip_spaces();
      if (peek() == ',') {
        ++at_;
        continue;
      }
      if (peek() != '}') fail("expected ',' or '}' in the header dict");
    }
    ++at_;  // '}'
    if (!have_descr || !have_order || !have_shape)
      fail(std::string("the header lacks the key '") +
           (!have_descr ? "descr" : !have_order ? "fortran_order" : "shape") + "'");
    // numpy pads the header with spaces and ends it with a newline
    while (at_ < s_.size() && s_[at_] == ' ') ++at_;
    if (at_ + 1 != s_.size() || s_[at_] != '\n')
      fail("the header dict must be followed only by spaces and a final newline");
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(origin_ + ": .npy header: " + what);
  }
  char peek() const { return at_ < s_.size() ? s_[at_] : '\0'; }
  void skip_spaces() {
    while (at_ < s_.size() && s_[at_] == ' ') ++at_;
  }
  void expect(char c) {
    if (peek() != c) fail(std::string("expected '") + c + "'");
    ++at_;
  }
  std::string quoted_string() {
    const char q = peek();
    if (q != '\'' && q != '"') fail("expected a quoted key or string");
    const std::size_t end = s_.find(q, at_ + 1);
    if (end == std::string_view::npos) fail("unterminated string");
    std::string out(s_.substr(at_ + 1, end - at_ - 1));
    at_ = end + 1;
    return out;
  }
  bool boolean() {
    if (s_.substr(at_, 4) == "True") {
      at_ += 4;
      return true;
    }
    if (s_.substr(at_, 5) == "False") {
      at_ += 5;
      return false;
    }
    fail("'fortran_order' must be True or False");
  }
  std::vector<std::uint64_t> tuple() {
    expect('(');
    std::vector<std::uint64_t> dims;
    for (;;) {
      skip_spaces();
      if (peek() == ')') break;
      if (!(peek() >= '0' && peek() <= '9')) fail("'shape' must be a tuple of integers");
      std::uint64_t v = 0;
      while (peek() >= '0' && peek() <= '9') {
        v = v * 10 + std::uint64_t(peek() - '0');
        if (v > (std::uint64_t(1) << 40)) fail("a dimension of 'shape' is too large");
        ++at_;
      }
      dims.push_back(v);
      if (dims.size() > 8) fail("'shape' has more than 8 dimensions");
      skip_spaces();
      if (peek() == ',') {
        ++at_;
        continue;
      }
      if (peek() != ')') fail("expected ',' or ')' in 'shape'");
    }
    ++at_;
    return dims;
  }

  std::string_view s_;
  const std::string& origin_;
  std::size_t at_ = 0;
};

std::uint32_t little_endian(const std::string& b, std::size_t at, int bytes) {
  std::uint32_t v = 0;
  for (int k = bytes - 1; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(b[at + size_t(k)]);
  return v;
}

NpyHeader parse_header(const std::string& bytes, const std::string& origin) {
  static const char kMagic[] = "\x93NUMPY";
  if (bytes.size() < 10 || std::memcmp(bytes.data(), kMagic, 6) != 0)
    throw InputError(origin + ": not a numpy .npy file (it must begin with \\x93NUMPY)");
  const int major = static_cast<unsigned char>(bytes[6]);
  const int minor = static_cast<unsigned char>(bytes[7]);
  if ((major != 1 && major != 2 && major != 3) || minor != 0)
    throw InputError(origin + ": .npy format version " + std::to_string(major) + "." +
                     std::to_string(minor) + " is not supported (1.0, 2.0 or 3.0)");
  const std::size_t len_bytes = major == 1 ? 2 : 4;
  if (bytes.size() < 8 + len_bytes)
    throw InputError(origin + ": the .npy file ends inside its header");
  const std::size_t header_len = little_endian(bytes, 8, int(len_bytes));
  const std::size_t start = 8 + len_bytes;
  if (header_len > bytes.size() - start)
    throw InputError(origin + ": the .npy header length " + std::to_string(header_len) +
                     " goes beyond the end of the file");
  NpyHeader h;
  const std::string_view text(bytes.data() + start, header_len);
  for (const char c : text)  // ASCII (and printable) in every header numpy writes
    if (static_cast<unsigned char>(c) >= 0x80 || (c < 0x20 && c != '\n'))
      throw InputError(origin + ": .npy header: a byte that is not printable ASCII");
  HeaderParser(text, origin).parse(h);
  h.data_offset = start + header_len;
  return h;
}

std::string shape_text(const std::vector<std::uint64_t>& s) {
  std::string t = "(";
  for (std::size_t k = 0; k < s.size(); ++k) t += (k ? ", " : "") + std::to_string(s[k]);
  return t + (s.size() == 1 ? ",)" : ")");
}

/// The data must be exactly rows x cols float64 values: checked before anything is allocated
/// (rows, cols <= 2^40 each, so the products below cannot overflow once cols is bounded).
void check_length(const std::string& bytes, const NpyHeader& h, std::uint64_t rows,
                  std::uint64_t cols, const std::string& origin) {
  const std::uint64_t have = bytes.size() - h.data_offset;
  if (rows != 0 && cols > have / 8 / rows + 1)
    throw InputError(origin + ": shape " + shape_text(h.shape) + " needs more data than the " +
                     std::to_string(have) + " bytes after the header");
  if (rows * cols * 8 != have)
    throw InputError(origin + ": shape " + shape_text(h.shape) + " needs " +
                     std::to_string(rows * cols * 8) + " bytes of float64 data, the file has " +
                     std::to_string(have));
}

/// The data of an array of `rows` x `cols` (length checked) into `out` (column-major), read
/// in the file's order.
void read_data(const std::string& bytes, const NpyHeader& h, std::uint64_t rows,
               std::uint64_t cols, double* out) {
  const std::uint64_t need = rows * cols * 8;
  const char* src = bytes.data() + h.data_offset;
  const auto r = static_cast<Eigen::Index>(rows), c = static_cast<Eigen::Index>(cols);
  std::uint16_t probe = 1;
  unsigned char first = 0;
  std::memcpy(&first, &probe, 1);
  const bool host_little = first == 1;
  auto value = [&](std::uint64_t k) {
    char b[8];
    std::memcpy(b, src + 8 * k, 8);
    if (!host_little)
      for (int i = 0; i < 4; ++i) std::swap(b[i], b[7 - i]);
    double v = 0;
    std::memcpy(&v, b, 8);
    return v;
  };
  if (h.fortran_order || rows == 1 || cols == 1) {
    if (host_little) {
      std::memcpy(out, src, need);
    } else {
      for (std::uint64_t k = 0; k < rows * cols; ++k) out[k] = value(k);
    }
  } else {  // C order: row-major in the file
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic>> dst(out, r, c);
    if (host_little) {
      using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
      dst = Eigen::Map<const RowMajor>(reinterpret_cast<const double*>(src), r, c);
    } else {
      for (std::uint64_t i = 0; i < rows; ++i)
        for (std::uint64_t k = 0; k < cols; ++k)
          dst(Eigen::Index(i), Eigen::Index(k)) = value(i * cols + k);
    }
  }
}

}  // namespace

Mat parse_npy_matrix(const std::string& bytes, const std::string& origin_in) {
  const std::string origin = io_text::valid_utf8(origin_in);
  const NpyHeader h = parse_header(bytes, origin);
  if (h.shape.size() != 2)
    throw InputError(origin + ": a matrix needs a 2-D shape, the file has shape " +
                     shape_text(h.shape));
  check_length(bytes, h, h.shape[0], h.shape[1], origin);
  Mat M;
  M.resize(static_cast<Eigen::Index>(h.shape[0]), static_cast<Eigen::Index>(h.shape[1]));
  read_data(bytes, h, h.shape[0], h.shape[1], M.data());
  return M;
}

Vec parse_npy_vector(const std::string& bytes, const std::string& origin_in) {
  const std::string origin = io_text::valid_utf8(origin_in);
  const NpyHeader h = parse_header(bytes, origin);
  const bool column = h.shape.size() == 2 && h.shape[1] == 1;
  if (h.shape.size() != 1 && !column)
    throw InputError(origin + ": a vector needs shape (n,) or (n, 1), the file has shape " +
                     shape_text(h.shape));
  check_length(bytes, h, h.shape[0], 1, origin);
  Vec v(static_cast<Eigen::Index>(h.shape[0]));
  read_data(bytes, h, h.shape[0], 1, v.data());
  return v;
}

LcpProblem read_lcp_npy(const std::string& m_path, const std::string& q_path) {
  namespace fs = std::filesystem;
  const std::string shown = io_text::valid_utf8(m_path);
  std::string qp = q_path;
  if (qp.empty()) {
    qp = matrix_market_q_path(m_path);  // dir/M.npy -> dir/M.q.npy
    std::error_code ec;
    if (!fs::exists(qp, ec))
      throw InputError(shown + ": a .npy file holds M only; q is read from " +
                       io_text::valid_utf8(qp) + " beside it, which does not exist (give q with "
                       "--q FILE)");
  }
  const std::string q_shown = io_text::valid_utf8(qp);
  LcpProblem p;
  p.M = parse_npy_matrix(io_text::read_text(m_path), m_path);
  if (p.M.rows() != p.M.cols())
    throw InputError(shown + ": M has shape (" + std::to_string(p.M.rows()) + ", " +
                     std::to_string(p.M.cols()) + "); an LCP needs a square M");
  p.q = parse_npy_vector(io_text::read_text(qp), qp);
  if (p.q.size() != p.M.rows())
    throw InputError(q_shown + ": q has " + std::to_string(p.q.size()) + " entries but M (" +
                     shown + ") is " + std::to_string(p.M.rows()) + " x " +
                     std::to_string(p.M.cols()));
  p.name = io_text::valid_utf8(fs::path(m_path).stem().string());
  throw_if_invalid(p.validate(), shown + " with q from " + q_shown);
  return p;
}

}  // namespace cpkit
