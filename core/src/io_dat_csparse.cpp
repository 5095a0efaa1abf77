// Storage type 2 of a Siconos NumericsMatrix (NM_SPARSE) in .dat files: what Siconos 4.4's
// NSM_write_in_file writes (its origin, then CSparseMatrix_print_in_file of that matrix) and
// NSM_new_from_file / CSparseMatrix_new_from_file read back:
//   origin                               1 triplet, 2 compressed columns (csc)
//   CSparse Version 3.2.0, ...           the banner line (free text)
//   triplet: 3-by-3, nzmax: 5 nnz: 5     (csc: "3-by-3, nzmax: 5 nnz: 5, 1-norm: 3.5")
//       0 0 : 2                          triplet: "row col : value", nnz times
//       col 0 : locations 0 to 1         csc: per column its run of entries, then
//         0 : 2                          "row : value" per entry
// These are what Siconos writes for a problem built from a scipy.sparse matrix (coo and csr
// give a triplet, csc a csc). Origin 3 (compressed rows) is refused: Siconos 4.4 writes it as a
// csc ("col" runs that are rows) and later versions with a "csr:" header and n runs whatever
// the number of rows; neither is produced from Python, so there is no real file to read it from.
// Values are printed with %g (6 significant digits): a file written by Siconos holds W to
// that precision. Siconos checks nothing; here every count, index and location is checked
// against the header and against what is left in the file before anything is allocated.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "io_dat_matrix.hpp"

namespace cpkit::io_dat {
namespace {

constexpr std::int64_t kAny = std::numeric_limits<std::int64_t>::max();

/// "R-by-C," (the size token of the header line) as R and C; false when it is not that.
bool parse_size(std::string_view t, std::int64_t& rows, std::int64_t& cols) {
  const auto by = t.find("-by-");
  if (by == std::string_view::npos || t.empty() || t.back() != ',') return false;
  return io_text::parse_integer(t.substr(0, by), rows) &&
         io_text::parse_integer(t.substr(by + 4, t.size() - by - 5), cols);
}

/// The compressed columns after the header: `cols` runs, each "col j : locations a to b" and
/// its b - a + 1 entries "i : x", contiguous from location 0 to nnz - 1.
void read_columns(DatReader& r, std::int64_t rows, std::int64_t cols, std::int64_t nnz,
                  const std::string& name, std::vector<Eigen::Triplet<double>>& entries) {
  std::int64_t next = 0;  // the location the next column starts at
  for (std::int64_t j = 0; j < cols; ++j) {
    const std::string where = name + "'s col " + std::to_string(j);
    r.literal("col", [&] { return "the start of " + where; });
    r.integer([&] { return "the index of " + where; }, j, j);
    r.literal(":", where);
    r.literal("locations", where);
    r.integer([&] { return "the first location of " + where; }, next, next);
    r.literal("to", where);
    const int line = r.line();
    const std::int64_t last = r.integer([&] { return "the last location of " + where; }, next - 1, kAny);
    if (last >= nnz)
      r.fail(line, "the last location of " + where + " is " + std::to_string(last) +
                       ", but the header announces " + std::to_string(nnz) + " entries");
    for (std::int64_t k = next; k <= last; ++k) {
      const std::int64_t i = r.integer(
          [&] { return "the row of entry " + std::to_string(k) + " of " + name; }, 0, rows - 1);
      r.literal(":", [&] { return "entry " + std::to_string(k) + " of " + name; });
      const double v = r.real([&] { return "entry " + std::to_string(k) + " of " + name; });
      entries.emplace_back(static_cast<int>(i), static_cast<int>(j), v);
    }
    next = last + 1;
  }
  if (next != nnz)
    r.fail(r.line(), "the columns of " + name + " hold " + std::to_string(next) +
                         " entries, but the header announces nnz " + std::to_string(nnz));
}

}  // namespace

Eigen::SparseMatrix<double> read_csparse(DatReader& r, std::int64_t rows, std::int64_t cols,
                                         std::uint64_t after, const std::string& name,
                                         const std::string& after_what) {
  const int origin_line = r.line();
  const std::int64_t origin = r.integer("the sparse origin of " + name, -kAny, kAny);
  if (origin != 1 && origin != 2)
    r.fail(origin_line, "sparse origin " + std::to_string(origin) + " of " + name +
                            " is not read (Siconos NSM origins: 1 triplet, 2 compressed "
                            "columns, which cpkit reads; 3 compressed rows, 4 half triplet)");
  const int banner = r.line();
  r.literal("CSparse", "the banner line that starts a CSparse matrix (" + name + ")");
  r.skip_line(banner);

  const int header = r.line();
  const std::string header_what = "the header line of the sparse " + name;
  const io_text::Token* t = &r.word(header_what);
  if ((origin == 1) != (t->text == "triplet:"))
    r.fail(t->line, "the sparse origin " + std::to_string(origin) + " of " + name +
                        (origin == 1 ? " announces a 'triplet:' header, got '"
                                     : " announces compressed columns, got a header starting '") +
                        io_text::quoted(t->text) + "'");
  if (origin == 1) t = &r.word(header_what);
  std::int64_t size_rows = 0, size_cols = 0;
  if (!parse_size(t->text, size_rows, size_cols))
    r.fail(t->line, "expected the size 'R-by-C,' in " + header_what + ", got '" +
                        io_text::quoted(t->text) + "'");
  if (size_rows != rows || size_cols != cols)
    r.fail(t->line, "the sparse " + name + " is " + std::to_string(size_rows) + "-by-" +
                        std::to_string(size_cols) + ", but its NumericsMatrix header says " +
                        std::to_string(rows) + " x " + std::to_string(cols));
  r.literal("nzmax:", header_what);
  const std::int64_t nzmax = r.integer("nzmax (the allocated entries) of " + name, 0, kAny);
  r.literal("nnz:", header_what);
  // nnz: "5" (triplet) or "5," (csc, before its 1-norm).
  const io_text::Token& nnz_token = r.word("nnz (the stored entries) of " + name);
  const int nnz_line = nnz_token.line;
  std::string_view nnz_text = nnz_token.text;
  if (origin != 1 && !nnz_text.empty() && nnz_text.back() == ',') nnz_text.remove_suffix(1);
  std::int64_t nnz = 0;
  if (!io_text::parse_integer(nnz_text, nnz) || nnz < 0)
    r.fail(nnz_line, "expected nnz (the stored entries) of " + name +
                         " (an integer >= 0), got '" + io_text::quoted(nnz_token.text) + "'");
  if (nnz > nzmax)
    r.fail(nnz_line, "nnz " + std::to_string(nnz) + " of " + name + " exceeds its nzmax " +
                         std::to_string(nzmax));
  r.skip_line(header);  // "1-norm: X" of a csc

  // Tokens per entry: "i j : x" (triplet) or "i : x"; per run: "col j : locations a to b".
  const auto need = origin == 1 ? 4 * static_cast<std::uint64_t>(nnz)
                                : 3 * static_cast<std::uint64_t>(nnz) +
                                      7 * static_cast<std::uint64_t>(cols);
  if (static_cast<std::uint64_t>(nnz) > r.remaining() || need + after < need)
    r.fail(nnz_line, "nnz " + std::to_string(nnz) + " of " + name +
                         " is more entries than the file holds");
  r.need(need + after, "the " + std::to_string(nnz) + " entries of the sparse " + name +
                           " and the " + std::to_string(after) + " entries of " + after_what);

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(nnz));  // nnz <= tokens left (checked)
  if (origin == 1) {
    for (std::int64_t k = 0; k < nnz; ++k) {
      const std::int64_t i = r.integer(
          [&] { return "the row of entry " + std::to_string(k) + " of " + name; }, 0, rows - 1);
      const std::int64_t j = r.integer(
          [&] { return "the column of entry " + std::to_string(k) + " of " + name; }, 0, cols - 1);
      r.literal(":", [&] { return "entry " + std::to_string(k) + " of " + name; });
      const double v = r.real([&] { return "entry " + std::to_string(k) + " of " + name; });
      entries.emplace_back(static_cast<int>(i), static_cast<int>(j), v);
    }
  } else {
    read_columns(r, rows, cols, nnz, name, entries);
  }
  // Repeated (i, j) add up, as CSparse's products treat them; stored zeros are dropped, as
  // the dense storage's are (the same W whatever the storage).
  Eigen::SparseMatrix<double> M(rows, cols);
  M.setFromTriplets(entries.begin(), entries.end());
  M.prune(0.0, 0.0);
  return M;
}

}  // namespace cpkit::io_dat
