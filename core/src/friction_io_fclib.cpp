// FCLIB files (HDF5) through Debian's libfclib 3.1.0. libfclib trusts its input: read_matrix
// mallocs from the declared sizes, reads whole datasets into those buffers and exits the process
// on any HDF5 error (its IO/ASSERT macros). So every dataset libfclib will touch is checked here
// first with HDF5's own API (exists, class, one dimension, extent equal to what libfclib will
// allocate, a plausible size for the file's length); only then is fclib_read_local/global called.
// fclib_read_solution is never called (it aborts on files without /solution).
extern "C" {  // fclib.h has no C++ guards
#include <fclib.h>
}
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "friction_io_fclib.hpp"
#include "io_text.hpp"

namespace cpkit::fclib_io {
namespace {

/// Silences HDF5's error stack printing for the lifetime of the object (restores it after).
class QuietHdf5 {
 public:
  QuietHdf5() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

/// Checks an open file's datasets before libfclib reads them.
class Checker {
 public:
  Checker(hid_t file, std::string origin, std::uintmax_t file_bytes)
      : file_(file), origin_(std::move(origin)), file_bytes_(file_bytes) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(origin_ + ": " + message);
  }

  bool exists(const std::string& path) const {
    // H5Lexists on "/a/b" needs "/a" to exist: check each prefix.
    std::size_t pos = 1;
    while (true) {
      const std::size_t next = path.find('/', pos);
      const std::string prefix = path.substr(0, next);
      if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
      if (next == std::string::npos) return true;
      pos = next + 1;
    }
  }

  /// The dataset's number of elements; fails unless it exists, has class `cls`, rank <= 1 and
  /// (when expected >= 0) exactly `expected` elements (at most, when `at_most`: libfclib reads a
  /// whole dataset into a buffer of the declared size), stored in a plausible number of bytes.
  std::uint64_t dataset(const std::string& path, H5T_class_t cls, std::int64_t expected,
                        bool at_most = false) const {
    if (!exists(path)) fail("the FCLIB dataset " + path + " is missing");
    const hid_t d = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
    if (d < 0) fail(path + " is not a dataset");
    const hid_t t = H5Dget_type(d);
    const hid_t s = H5Dget_space(d);
    const H5T_class_t c = t >= 0 ? H5Tget_class(t) : H5T_NO_CLASS;
    const int rank = s >= 0 ? H5Sget_simple_extent_ndims(s) : -1;
    hsize_t dims[1] = {0};
    if (rank == 1) H5Sget_simple_extent_dims(s, dims, nullptr);
    const std::uint64_t count = rank == 0 ? 1 : rank == 1 ? dims[0] : 0;
    const hsize_t stored = H5Dget_storage_size(d);
    if (s >= 0) H5Sclose(s);
    if (t >= 0) H5Tclose(t);
    H5Dclose(d);
    if (c != cls)
      fail(path + " has the wrong type (expected " +
           (cls == H5T_INTEGER ? "integers" : cls == H5T_FLOAT ? "floating-point numbers" : "a string") + ")");
    if (rank != 0 && rank != 1) fail(path + " is not a vector (rank " + std::to_string(rank) + ")");
    if (expected >= 0 && (at_most ? count > static_cast<std::uint64_t>(expected)
                                  : count != static_cast<std::uint64_t>(expected)))
      fail(path + " holds " + std::to_string(count) + " entries, the header declares " +
           (at_most ? "at most " : "") + std::to_string(expected));
    // A declared extent whose data is not in the file (unallocated or absurdly compressed)
    // would make libfclib allocate gigabytes for a small file: 8 bytes per entry, at most
    // 1000 entries per stored byte (deflate's limit is ~1032).
    if (cls != H5T_STRING && count > 0 &&
        (stored == 0 || count > 1000 * static_cast<std::uint64_t>(stored) ||
         count > (std::uint64_t{1} << 31) || stored > file_bytes_))
      fail(path + " declares " + std::to_string(count) + " entries but the file stores " +
           std::to_string(stored) + " bytes for it");
    return count;
  }

  int scalar_int(const std::string& path) const {
    dataset(path, H5T_INTEGER, 1);
    int v = 0;
    const hid_t d = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
    const herr_t status = d < 0 ? -1 : H5Dread(d, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, &v);
    if (d >= 0) H5Dclose(d);
    if (status < 0) fail("cannot read " + path);
    return v;
  }

  /// A matrix group as libfclib's read_matrix will read it: its sizes, and how many entries of
  /// i and x the file really holds (libfclib leaves the rest of its nzmax buffers unset).
  struct Shape {
    int m = 0, n = 0;
    std::uint64_t stored = 0;
  };
  Shape matrix(const std::string& g) const {
    const int nzmax = scalar_int(g + "/nzmax");
    const int m = scalar_int(g + "/m");
    const int n = scalar_int(g + "/n");
    const int nz = scalar_int(g + "/nz");
    if (m < 0 || n < 0 || nzmax < 0)
      fail(g + " declares negative sizes (m " + std::to_string(m) + ", n " + std::to_string(n) +
           ", nzmax " + std::to_string(nzmax) + ")");
    std::uint64_t stored = 0;
    if (nz >= 0) {
      if (nz > nzmax) fail(g + ": nz " + std::to_string(nz) + " exceeds nzmax " + std::to_string(nzmax));
      dataset(g + "/p", H5T_INTEGER, nz);
      stored = dataset(g + "/i", H5T_INTEGER, nz);
    } else if (nz == -1 || nz == -2) {
      dataset(g + "/p", H5T_INTEGER, static_cast<std::int64_t>(nz == -1 ? n : m) + 1);
      stored = dataset(g + "/i", H5T_INTEGER, nzmax, true);
    } else {
      fail(g + ": nz = " + std::to_string(nz) +
           " is no FCLIB storage (>= 0 triplet, -1 compressed columns, -2 compressed rows)");
    }
    stored = std::min(stored, dataset(g + "/x", H5T_FLOAT, nzmax, true));
    if (nz >= 0 && stored < static_cast<std::uint64_t>(nz))
      fail(g + "/x holds " + std::to_string(stored) + " entries, nz declares " + std::to_string(nz));
    // libfclib allocates nzmax entries: a declared nzmax far beyond the stored entries would
    // allocate memory the file does not justify.
    if (static_cast<std::uint64_t>(nzmax) > 4 * stored + 1024)
      fail(g + ": nzmax " + std::to_string(nzmax) + " is far larger than the " +
           std::to_string(stored) + " entries stored");
    if (exists(g + "/conditioning")) {
      if (exists(g + "/comment")) dataset(g + "/comment", H5T_STRING, -1);
      dataset(g + "/conditioning", H5T_FLOAT, 1);
      dataset(g + "/determinant", H5T_FLOAT, 1);
      dataset(g + "/rank", H5T_INTEGER, 1);
    }
    return {m, n, stored};
  }

  void info(const std::string& g) const {
    for (const char* k : {"/title", "/description", "/math_info"})
      if (exists(g + k)) dataset(g + k, H5T_STRING, -1);
  }

 private:
  hid_t file_;
  std::string origin_;
  std::uintmax_t file_bytes_;
};

/// An fclib_matrix (triplet, CSC or CSR; CSparse's layout: in triplet form i holds rows and p
/// columns) as an Eigen matrix, every index checked.
Eigen::SparseMatrix<double> to_eigen(const fclib_matrix& a, std::uint64_t stored,
                                     const std::string& name, const std::string& origin) {
  auto fail = [&](const std::string& what) { throw InputError(origin + ": " + name + ": " + what); };
  std::vector<Eigen::Triplet<double>> t;
  auto add = [&](long long row, long long col, double v) {
    if (row < 0 || row >= a.m || col < 0 || col >= a.n)
      fail("entry (" + std::to_string(row) + ", " + std::to_string(col) + ") outside its " +
           std::to_string(a.m) + " x " + std::to_string(a.n) + " size");
    if (!std::isfinite(v))
      fail("entry (" + std::to_string(row) + ", " + std::to_string(col) + ") is not finite");
    t.emplace_back(static_cast<int>(row), static_cast<int>(col), v);
  };
  if (a.nz >= 0) {
    t.reserve(static_cast<std::size_t>(a.nz));
    for (int k = 0; k < a.nz; ++k) add(a.i[k], a.p[k], a.x[k]);
  } else {
    const int outer = a.nz == -1 ? a.n : a.m;  // -1: compressed columns, -2: compressed rows
    if (a.p[0] != 0) fail("the first pointer is " + std::to_string(a.p[0]) + ", not 0");
    for (int k = 0; k < outer; ++k)
      if (a.p[k + 1] < a.p[k] || static_cast<std::uint64_t>(a.p[k + 1]) > stored)
        fail("pointer " + std::to_string(k + 1) + " = " + std::to_string(a.p[k + 1]) +
             " decreases or exceeds the " + std::to_string(stored) + " entries stored");
    t.reserve(static_cast<std::size_t>(a.p[outer]));
    for (int k = 0; k < outer; ++k)
      for (int e = a.p[k]; e < a.p[k + 1]; ++e)
        if (a.nz == -1)
          add(a.i[e], k, a.x[e]);
        else
          add(k, a.i[e], a.x[e]);
  }
  Eigen::SparseMatrix<double> out(a.m, a.n);
  out.setFromTriplets(t.begin(), t.end());  // duplicates are summed, as CSparse does
  out.makeCompressed();
  return out;
}

Eigen::VectorXd to_vector(const double* v, Eigen::Index n) {
  return Eigen::Map<const Eigen::VectorXd>(v, n);
}

std::string title_of(const fclib_info* info) {
  return info && info->title ? io_text::valid_utf8(info->title) : std::string{};
}
std::string description_of(const fclib_info* info) {
  return info && info->description ? io_text::valid_utf8(info->description) : std::string{};
}

struct File {
  hid_t id = -1;
  ~File() {
    if (id >= 0) H5Fclose(id);
  }
};

/// Opens and runs `check`; InputError when the file is no readable HDF5 file.
template <class Check>
void precheck(const std::string& path, const std::string& origin, Check check) {
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(origin + ": cannot read the file (" + ec.message() + ")");
  File f;
  f.id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f.id < 0) throw InputError(origin + ": not a readable HDF5 file (truncated or corrupted?)");
  check(Checker(f.id, origin, bytes));
}

}  // namespace

FrictionContactProblem read_local(const std::string& path) {
  const std::string origin = io_text::valid_utf8(path);
  QuietHdf5 quiet;
  int rows = 0;
  std::uint64_t w_stored = 0;
  precheck(path, origin, [&](const Checker& c) {
    if (!c.exists("/fclib_local")) {
      if (c.exists("/fclib_global"))
        c.fail("holds an FCLIB global problem (/fclib_global), not a local one: read it with "
               "read_global_friction_problem");
      c.fail("is an HDF5 file without an FCLIB problem (/fclib_local)");
    }
    const int dim = c.scalar_int("/fclib_local/spacedim");
    if (dim != 3) c.fail("spacedim is " + std::to_string(dim) + "; cpkit reads 3-D problems");
    const auto [m, n, stored] = c.matrix("/fclib_local/W");
    w_stored = stored;
    if (m != n || m % 3 != 0 || m == 0)
      c.fail("W is " + std::to_string(m) + " x " + std::to_string(n) +
             ", expected square with 3 rows per contact");
    if (c.exists("/fclib_local/V") || c.exists("/fclib_local/R"))
      c.fail("has the optional V, R, s constraints of FCLIB's mixed problem, which cpkit does not read");
    c.dataset("/fclib_local/vectors/q", H5T_FLOAT, m);
    c.dataset("/fclib_local/vectors/mu", H5T_FLOAT, m / 3);
    c.info("/fclib_local/info");
    rows = m;
  });
  std::unique_ptr<fclib_local, void (*)(fclib_local*)> raw(fclib_read_local(path.c_str()),
                                                           fclib_delete_local);
  if (!raw) throw InputError(origin + ": libfclib could not read the local problem");
  FrictionContactProblem p;
  p.W = to_eigen(*raw->W, w_stored, "W", origin);
  p.q = to_vector(raw->q, rows);
  p.mu = to_vector(raw->mu, rows / 3);
  p.name = title_of(raw->info);
  if (p.name.empty()) p.name = io_text::valid_utf8(std::filesystem::path(path).stem().string());
  p.note = description_of(raw->info);
  throw_if_invalid(p.validate(), origin);
  return p;
}

GlobalFrictionContactProblem read_global(const std::string& path) {
  const std::string origin = io_text::valid_utf8(path);
  QuietHdf5 quiet;
  int dofs = 0, cols = 0;
  std::uint64_t m_stored = 0, h_stored = 0;
  precheck(path, origin, [&](const Checker& c) {
    if (!c.exists("/fclib_global")) {
      if (c.exists("/fclib_local"))
        c.fail("holds an FCLIB local problem (/fclib_local), not a global one: read it with "
               "read_friction_problem");
      c.fail("is an HDF5 file without an FCLIB problem (/fclib_global)");
    }
    const int dim = c.scalar_int("/fclib_global/spacedim");
    if (dim != 3) c.fail("spacedim is " + std::to_string(dim) + "; cpkit reads 3-D problems");
    const auto [mm, mn, ms] = c.matrix("/fclib_global/M");
    m_stored = ms;
    if (mm != mn || mm == 0)
      c.fail("M is " + std::to_string(mm) + " x " + std::to_string(mn) + ", expected square");
    const auto [hm, hn, hs] = c.matrix("/fclib_global/H");
    h_stored = hs;
    if (hm != mm || hn % 3 != 0 || hn == 0)
      c.fail("H is " + std::to_string(hm) + " x " + std::to_string(hn) + ", expected " +
             std::to_string(mm) + " x 3 n_c");
    if (c.exists("/fclib_global/G"))
      c.fail("has FCLIB's optional equality constraints G, b, which cpkit does not read");
    c.dataset("/fclib_global/vectors/f", H5T_FLOAT, mm);
    c.dataset("/fclib_global/vectors/w", H5T_FLOAT, hn);
    c.dataset("/fclib_global/vectors/mu", H5T_FLOAT, hn / 3);
    c.info("/fclib_global/info");
    dofs = mm;
    cols = hn;
  });
  std::unique_ptr<fclib_global, void (*)(fclib_global*)> raw(fclib_read_global(path.c_str()),
                                                             fclib_delete_global);
  if (!raw) throw InputError(origin + ": libfclib could not read the global problem");
  GlobalFrictionContactProblem p;
  p.M = to_eigen(*raw->M, m_stored, "M", origin);
  p.H = to_eigen(*raw->H, h_stored, "H", origin);
  p.f = to_vector(raw->f, dofs);
  p.w = to_vector(raw->w, cols);
  p.mu = to_vector(raw->mu, cols / 3);
  p.name = title_of(raw->info);
  if (p.name.empty()) p.name = io_text::valid_utf8(std::filesystem::path(path).stem().string());
  p.note = description_of(raw->info);
  throw_if_invalid(p.validate(), origin);
  return p;
}

namespace {

// /solution/status: one 32-bit integer a contact (0 separated, 1 stick, 2 slip: the JSON
// per_contact state, cpkit::friction_contacts), with that key in its attribute "states". An extra
// dataset of /solution: libfclib's fclib_read_solution and Siconos read only v, u, r, l there.
void write_contact_states(const std::string& path, const FrictionContactProblem& problem,
                          const Eigen::VectorXd& r) {
  std::vector<std::int32_t> states;
  for (const ContactReport& c : friction_contacts(problem, r))
    states.push_back(static_cast<std::int32_t>(c.state));
  static_assert(static_cast<int>(ContactState::kSeparated) == 0 &&
                static_cast<int>(ContactState::kStick) == 1 &&
                static_cast<int>(ContactState::kSlip) == 2);
  const std::string key = "0 separated, 1 stick, 2 slip";
  bool ok = false;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file >= 0) {
    const hsize_t dims[1] = {static_cast<hsize_t>(states.size())};
    const hid_t space = H5Screate_simple(1, dims, nullptr);
    const hid_t set = H5Dcreate2(file, "/solution/status", H5T_STD_I32LE, space, H5P_DEFAULT,
                                 H5P_DEFAULT, H5P_DEFAULT);
    const hid_t text = H5Tcopy(H5T_C_S1);
    H5Tset_size(text, key.size() + 1);
    const hid_t scalar = H5Screate(H5S_SCALAR);
    const hid_t attr = set >= 0 ? H5Acreate2(set, "states", text, scalar, H5P_DEFAULT, H5P_DEFAULT)
                                : H5I_INVALID_HID;
    ok = set >= 0 && attr >= 0 &&
         H5Dwrite(set, H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, states.data()) >= 0 &&
         H5Awrite(attr, text, key.c_str()) >= 0;
    if (attr >= 0) H5Aclose(attr);
    H5Sclose(scalar);
    H5Tclose(text);
    if (set >= 0) H5Dclose(set);
    H5Sclose(space);
    ok = H5Fclose(file) >= 0 && ok;
  }
  if (!ok)
    throw InputError(io_text::valid_utf8(path) +
                     ": cannot write the contact states into the FCLIB file");
}

}  // namespace

void write_local_with_solution(const std::string& path, const FrictionContactProblem& problem,
                               const Eigen::VectorXd& r, const Eigen::VectorXd& u) {
  throw_if_invalid(problem.validate(), "write_friction_solution");
  const Eigen::Index n = problem.W.rows();
  if (r.size() != n || u.size() != n)
    throw InputError("write_friction_solution: r has " + std::to_string(r.size()) + " and u " +
                     std::to_string(u.size()) + " entries, expected " + std::to_string(n));
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> W = problem.W;
  W.makeCompressed();
  fclib_matrix mat{};
  mat.nzmax = static_cast<int>(W.nonZeros());
  mat.m = mat.n = static_cast<int>(n);
  mat.p = W.outerIndexPtr();
  mat.i = W.innerIndexPtr();
  mat.x = W.valuePtr();
  mat.nz = -1;
  mat.info = nullptr;
  Eigen::VectorXd q = problem.q, mu = problem.mu, rr = r, uu = u;
  std::string title = problem.name, description = problem.note, math = "";
  fclib_info info{};
  info.title = title.data();
  info.description = description.data();
  info.math_info = math.data();
  fclib_local local{};
  local.W = &mat;
  local.q = q.data();
  local.mu = mu.data();
  local.spacedim = 3;
  local.info = &info;
  std::error_code ec;
  std::filesystem::remove(path, ec);  // libfclib refuses to overwrite an existing problem
  QuietHdf5 quiet;
  if (!fclib_write_local(&local, path.c_str()))
    throw InputError(io_text::valid_utf8(path) + ": cannot write the FCLIB file");
  fclib_solution sol{};
  sol.r = rr.data();
  sol.u = uu.data();
  if (!fclib_write_solution(&sol, path.c_str()))
    throw InputError(io_text::valid_utf8(path) + ": cannot write the solution into the FCLIB file");
  write_contact_states(path, problem, r);
}

}  // namespace cpkit::fclib_io
