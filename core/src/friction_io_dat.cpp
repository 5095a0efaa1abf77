// Siconos FrictionContact / GlobalFrictionContact .dat files, read as Siconos numerics 4.4 reads
// them (frictionContact_newFromFile, globalFrictionContact_newFromFile):
//   local:  d, nc, W (NM_new_from_file: storage, size0, size1, then dense, sparse block or
//           sparse: io_dat_csparse.cpp), then
//           q (size1 numbers), then mu (nc numbers);
//   global: d, nc, M, H (each NM_new_from_file), then q (M's size1), b (H's size1), mu (nc).
// Siconos' q and b are cpkit's f and w (M v = H r + q, u = H^T v + b). Siconos ignores whatever
// follows mu; cpkit keeps one trailing number or text as the note and refuses more numbers
// (a global file read as a local one would otherwise pass). Every count is checked against what is left in
// the file before anything is allocated for it (io_dat_matrix.hpp).
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>
#include <filesystem>
#include <string>
#include <utility>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"
#include "friction_io_dat.hpp"
#include "io_dat_matrix.hpp"
#include "io_text.hpp"

namespace cpkit {
namespace {

using io_dat::DatReader;

/// The storage type of a NumericsMatrix: 0 dense, 1 sparse block, 2 sparse (CSparse).
std::int64_t read_storage(DatReader& r, const std::string& name) {
  const int storage_line = r.line();
  const std::int64_t storage = r.integer("the storage type of " + name,
                                         std::numeric_limits<std::int64_t>::min(),
                                         std::numeric_limits<std::int64_t>::max());
  if (storage < 0 || storage > 2)
    r.fail(storage_line, "storage type " + std::to_string(storage) + " of " + name +
                             " is not read (Siconos: 0 dense, 1 sparse block, 2 sparse)");
  return storage;
}

/// The body of a NumericsMatrix of the given storage and size, after its type and sizes;
/// `after` numbers must follow it.
Eigen::SparseMatrix<double> read_body(DatReader& r, std::int64_t storage, std::int64_t rows,
                                      std::int64_t cols, std::uint64_t after,
                                      const std::string& name, const std::string& after_what) {
  if (storage == 0)
    return io_dat::read_dense(r, rows, cols, after, name, after_what).sparseView(0.0, 0.0);
  if (storage == 1) return io_dat::read_sparse_block(r, rows, cols, name);
  return io_dat::read_csparse(r, rows, cols, after, name, after_what);
}

/// One NumericsMatrix of the given size; `after` numbers must follow it.
Eigen::SparseMatrix<double> read_matrix(DatReader& r, std::int64_t rows, std::int64_t cols,
                                        std::uint64_t after, const std::string& name,
                                        const std::string& after_what, const std::string& why) {
  const std::int64_t storage = read_storage(r, name);
  r.integer("the number of rows of " + name + why, rows, rows);
  r.integer("the number of columns of " + name + why, cols, cols);
  return read_body(r, storage, rows, cols, after, name, after_what);
}

Eigen::VectorXd read_vector(DatReader& r, std::int64_t n, const std::string& name) {
  r.need(static_cast<std::uint64_t>(n), "the " + std::to_string(n) + " entries of " + name);
  Eigen::VectorXd v(n);
  for (std::int64_t i = 0; i < n; ++i)
    v[i] = r.real([&] { return name + "[" + std::to_string(i) + "]"; });
  return v;
}

/// d (must be 3) and nc (at least 1, at most what the file can hold).
std::int64_t read_header(DatReader& r) {
  r.integer("the contact dimension d (cpkit reads 3-D problems)", 3, 3);
  return r.integer("the number of contacts nc", 1,
                   std::min<std::int64_t>(io_dat::kMaxIndex / 3,
                                          static_cast<std::int64_t>(r.remaining())));
}

/// What follows mu, as a note. Siconos' own files end with at most one number there (ignored,
/// as Siconos does); more numbers mean the header does not describe the file (a
/// GlobalFrictionContact file read as a local one, for one): an InputError, not a silent misread.
std::string trailing_note(DatReader& r, const std::vector<io_text::Token>& tokens,
                          const std::string& text, const char* other) {
  if (r.done()) return {};
  int numbers = 0;
  for (std::size_t k = r.position(); k < tokens.size() && numbers < 2; ++k) {
    double v = 0;
    if (io_text::parse_real(tokens[k].text, v) != io_text::Number::kNotANumber) ++numbers;
  }
  if (numbers >= 2)
    r.fail(r.line(), "more numbers follow mu than the header announces (Siconos' files end with "
                     "at most one): not a " + std::string(other) + " file, or a wrong header");
  std::string note = text.substr(tokens[r.position()].offset);
  note.erase(note.find_last_not_of(" \t\r\n\v\f") + 1);
  return io_text::valid_utf8(note);
}

std::vector<io_text::Token> tokens_of(const std::string& text, const std::string& origin,
                                      const char* expected) {
  auto tokens = io_text::tokenize(text);
  if (tokens.empty()) throw InputError(origin + ": empty file (expected " + expected + ")");
  return tokens;
}

/// A .dat file being read. Both kinds start with d and nc (read by the constructor) and end
/// with mu and what follows it (finish).
struct DatFile {
  DatFile(const std::string& text_in, const std::string& origin_in, const char* expected)
      : text(text_in),
        origin_raw(origin_in),
        origin(io_text::valid_utf8(origin_in)),
        tokens(tokens_of(text_in, origin, expected)),
        r(tokens, origin),
        nc(read_header(r)),
        n(3 * nc) {}
  DatFile(const DatFile&) = delete;
  DatFile& operator=(const DatFile&) = delete;

  /// Reads mu and the trailing note (`kind` names the file kind in its message), names the
  /// problem after the file and validates it.
  template <class Problem>
  Problem finish(Problem p, const char* kind) {
    p.mu = read_vector(r, nc, "mu");
    p.note = trailing_note(r, tokens, text, kind);
    p.name = io_text::valid_utf8(std::filesystem::path(origin_raw).stem().string());
    throw_if_invalid(p.validate(), origin);
    return p;
  }

  const std::string& text;
  const std::string& origin_raw;
  const std::string origin;  // valid UTF-8, for messages
  const std::vector<io_text::Token> tokens;
  DatReader r;  // refers to tokens and origin above
  const std::int64_t nc;  // contacts
  const std::int64_t n;   // 3 nc
};

/// Runs `body` on `f`; when it fails, `reached` is how many tokens were read (the kind of a
/// file that neither reader reads is told by the reading that got further).
template <class Body>
auto reading(DatFile& f, std::size_t& reached, Body body) {
  try {
    return body();
  } catch (const InputError&) {
    reached = f.r.position();
    throw;
  }
}

}  // namespace

namespace friction_dat {

FrictionContactProblem parse_local(const std::string& text, const std::string& origin_in,
                                   std::size_t& reached) {
  reached = 0;
  DatFile f(text, origin_in, "d, nc, W, q, mu");
  return reading(f, reached, [&] {
    DatReader& r = f.r;
    const std::int64_t n = f.n;
    // Whatever W's storage, the file must still hold its type, sizes, q and mu.
    r.need(3 + static_cast<std::uint64_t>(n + f.nc), "the storage type and sizes of W, q and mu");
    const std::string why = " (3 nc = " + std::to_string(n) + ")";
    FrictionContactProblem p;
    p.W = read_matrix(r, n, n, static_cast<std::uint64_t>(n + f.nc), "W", "q and mu", why);
    p.q = read_vector(r, n, "q");
    p.W.makeCompressed();
    return f.finish(std::move(p), "FrictionContact (local problem)");
  });
}

GlobalFrictionContactProblem parse_global(const std::string& text, const std::string& origin_in,
                                          std::size_t& reached) {
  reached = 0;
  DatFile f(text, origin_in, "d, nc, M, H, q, b, mu");
  return reading(f, reached, [&] {
    DatReader& r = f.r;
    const std::int64_t n = f.n;
    const std::int64_t nc = f.nc;
    r.need(6 + static_cast<std::uint64_t>(n + nc), "the storage types and sizes of M and H, b and mu");
    // M's size is the number of degrees of freedom m; it is read before M's storage is known.
    const std::int64_t storage = read_storage(r, "M");
    const std::int64_t m = r.integer(
        "the number of rows of M (the degrees of freedom)", 1,
        std::min<std::int64_t>(io_dat::kMaxIndex, static_cast<std::int64_t>(r.remaining())));
    const std::string why = " (M is m x m, m = " + std::to_string(m) + ")";
    r.integer("the number of columns of M" + why, m, m);
    GlobalFrictionContactProblem p;
    const auto after_M = static_cast<std::uint64_t>(3 + m + n + nc);  // H's header, q, b, mu
    p.M = read_body(r, storage, m, m, after_M, "M", "H, q, b and mu");
    p.H = read_matrix(r, m, n, static_cast<std::uint64_t>(m + n + nc), "H", "q, b and mu",
                      " (H is m x 3 nc = " + std::to_string(m) + " x " + std::to_string(n) + ")");
    p.f = read_vector(r, m, "q (cpkit's f)");
    p.w = read_vector(r, n, "b (cpkit's w)");
    p.M.makeCompressed();
    p.H.makeCompressed();
    return f.finish(std::move(p), "GlobalFrictionContact");
  });
}

}  // namespace friction_dat

FrictionContactProblem parse_friction_dat(const std::string& text, const std::string& origin) {
  std::size_t reached = 0;
  return friction_dat::parse_local(text, origin, reached);
}

GlobalFrictionContactProblem parse_global_friction_dat(const std::string& text,
                                                       const std::string& origin) {
  std::size_t reached = 0;
  return friction_dat::parse_global(text, origin, reached);
}

}  // namespace cpkit
