// FCLIB files (HDF5). Reading is done here with HDF5's C API, not with libfclib's
// fclib_read_local/global: libfclib trusts its input (it mallocs from declared sizes, reads a
// string dataset of any shape into a buffer sized for one string, and calls exit(1) on any HDF5
// error: a filter HDF5 lacks, a damaged chunk, a missing external file). Here every dataset is
// checked before anything is allocated for it (exists, class, one dimension, the extent the
// header declares, its bytes really in the file: no external storage, no unwritten chunks, a
// filter HDF5 can decode, a plausible total for the file's length), then read into cpkit's own
// buffers; an HDF5 read error is an InputError naming the dataset. libfclib writes the files
// (write_local_with_solution): what it writes is what this reader reads.
extern "C" {  // fclib.h has no C++ guards
#include <fclib.h>
}
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
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

/// An HDF5 identifier closed by its own close function when the object goes.
class Id {
 public:
  Id(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Id() {
    if (id_ >= 0) close_(id_);
  }
  Id(const Id&) = delete;
  Id& operator=(const Id&) = delete;
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

/// The innermost description on HDF5's error stack (e.g. "inflate() failed"), for messages.
std::string hdf5_reason() {
  std::string reason;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_DOWNWARD,
      [](unsigned, const H5E_error2_t* e, void* out) -> herr_t {
        if (e->desc && *e->desc) *static_cast<std::string*>(out) = e->desc;
        return 0;
      },
      &reason);
  return reason.empty() ? "HDF5 reports an error" : io_text::valid_utf8(reason);
}

// What a file of `file_bytes` can plausibly decode to: its own size 64 times over (compressed
// numbers rarely shrink 10 times; deflate's limit, reached only by runs of zeros, is ~1000)
// plus 16 MiB. Bounds the memory a small file can make the reader take.
constexpr std::uint64_t kDecodedRatio = 64;
constexpr std::uint64_t kDecodedAllowance = std::uint64_t{16} << 20;
// Largest index or size read: Eigen's sparse matrices index with int.
constexpr std::int64_t kMaxSize = std::numeric_limits<int>::max() - 1;

/// An open FCLIB file, read dataset by dataset. Every failure is an InputError naming the file
/// and the dataset.
class Reader {
 public:
  Reader(hid_t file, std::string origin, std::uint64_t file_bytes)
      : file_(file), origin_(std::move(origin)), file_bytes_(file_bytes) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(origin_ + ": " + message);
  }

  /// True when every link of `path` exists; an external link (into another file) is refused.
  bool exists(const std::string& path) const {
    // H5Lexists on "/a/b" needs "/a" to exist: check each prefix.
    std::size_t pos = 1;
    while (true) {
      const std::size_t next = path.find('/', pos);
      const std::string prefix = path.substr(0, next);
      if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
      H5L_info_t link{};
      if (H5Lget_info(file_, prefix.c_str(), &link, H5P_DEFAULT) >= 0 &&
          link.type == H5L_TYPE_EXTERNAL)
        fail(prefix + " is an external link into another file, which cpkit does not follow");
      if (next == std::string::npos) return true;
      pos = next + 1;
    }
  }

  /// Integers of a dataset of `expected` entries (at most that many when `at_most`, any number
  /// when expected < 0).
  std::vector<std::int64_t> integers(const std::string& path, std::int64_t expected,
                                     bool at_most = false) {
    std::vector<std::int64_t> v;
    read(path, H5T_INTEGER, expected, at_most, H5T_NATIVE_INT64, v);
    return v;
  }
  std::vector<double> reals(const std::string& path, std::int64_t expected, bool at_most = false) {
    std::vector<double> v;
    read(path, H5T_FLOAT, expected, at_most, H5T_NATIVE_DOUBLE, v);
    return v;
  }
  /// A one-entry integer dataset (libfclib writes sizes as datasets of shape (1,)), in
  /// [lo, hi].
  std::int64_t integer(const std::string& path, std::int64_t lo = -kMaxSize,
                       std::int64_t hi = kMaxSize) {
    const std::int64_t v = integers(path, 1)[0];
    if (v < lo || v > hi)
      fail(path + " is " + std::to_string(v) + ", outside [" + std::to_string(lo) + ", " +
           std::to_string(hi) + "]");
    return v;
  }

  /// A string dataset holding one string, fixed-length (any padding, NUL or not) or
  /// variable-length (h5py's default for a Python str); empty when the dataset is absent.
  std::string text(const std::string& path) {
    if (!exists(path)) return {};
    const Id d(open(path, H5T_STRING), H5Dclose);
    const Id type(H5Dget_type(d.get()), H5Tclose);
    const Id space(H5Dget_space(d.get()), H5Sclose);
    const std::uint64_t count = entries(path, space.get());
    if (count != 1)
      fail(path + " holds " + std::to_string(count) +
           " strings; FCLIB stores one string there");
    const htri_t variable = H5Tis_variable_str(type.get());
    if (variable < 0) fail("cannot read the string type of " + path + " (" + hdf5_reason() + ")");
    if (variable > 0) {
      check_storage(d.get(), path, 0, 0);
      const Id mem(H5Tcopy(H5T_C_S1), H5Tclose);
      H5Tset_size(mem.get(), H5T_VARIABLE);
      H5Tset_cset(mem.get(), H5Tget_cset(type.get()));
      char* s = nullptr;
      if (H5Dread(d.get(), mem.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, &s) < 0)
        fail("cannot read " + path + " (" + hdf5_reason() + ")");
      std::string out = s ? std::string(s) : std::string();
      H5Dvlen_reclaim(mem.get(), space.get(), H5P_DEFAULT, &s);
      return io_text::valid_utf8(out);
    }
    // Fixed length: exactly `size` bytes, NUL-terminated, NUL-padded (h5py's np.bytes_: no
    // NUL at all when the text fills the size) or space-padded. Read into a buffer of that size
    // and cut at the first NUL: never past the buffer.
    const std::size_t size = H5Tget_size(type.get());
    check_storage(d.get(), path, 1, size);
    std::string buffer(size, '\0');
    if (size > 0 && H5Dread(d.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0)
      fail("cannot read " + path + " (" + hdf5_reason() + ")");
    buffer.resize(std::min(buffer.size(), buffer.find('\0')));
    if (H5Tget_strpad(type.get()) == H5T_STR_SPACEPAD)
      buffer.erase(buffer.find_last_not_of(' ') + 1);
    return io_text::valid_utf8(buffer);
  }

 private:
  /// Opens the dataset at `path`; fails unless it exists and has class `cls`.
  hid_t open(const std::string& path, H5T_class_t cls) const {
    if (!exists(path)) fail("the FCLIB dataset " + path + " is missing");
    const hid_t d = H5Dopen2(file_, path.c_str(), H5P_DEFAULT);
    if (d < 0) fail(path + " is not a dataset");
    const Id type(H5Dget_type(d), H5Tclose);
    if (!type.ok() || H5Tget_class(type.get()) != cls) {
      H5Dclose(d);
      fail(path + " has the wrong type (expected " +
           (cls == H5T_INTEGER ? "integers" : cls == H5T_FLOAT ? "floating-point numbers" : "a string") +
           ")");
    }
    return d;
  }

  /// The number of entries of a scalar or one-dimensional dataspace.
  std::uint64_t entries(const std::string& path, hid_t space) const {
    if (space >= 0 && H5Sget_simple_extent_type(space) == H5S_NULL) return 0;  // no data at all
    const int rank = space >= 0 ? H5Sget_simple_extent_ndims(space) : -1;
    if (rank != 0 && rank != 1) fail(path + " is not a vector (rank " + std::to_string(rank) + ")");
    hsize_t dims[1] = {1};
    if (rank == 1) H5Sget_simple_extent_dims(space, dims, nullptr);
    return dims[0];
  }

  /// Refuses data that is not in this file or that HDF5 cannot decode, before anything is
  /// allocated for `count` entries of `bytes_each` bytes in memory: external storage (a raw
  /// file named in the dataset, read whatever it holds), virtual datasets, filters this HDF5
  /// lacks (h5py's LZF), chunks never written (HDF5 would return the fill value), contiguous
  /// data shorter than its extent, and a total larger than the file can plausibly decode to.
  void check_storage(hid_t d, const std::string& path, std::uint64_t count,
                     std::uint64_t bytes_each) {
    const Id dcpl(H5Dget_create_plist(d), H5Pclose);
    if (!dcpl.ok()) fail("cannot read the storage of " + path + " (" + hdf5_reason() + ")");
    if (H5Pget_external_count(dcpl.get()) != 0)
      fail(path + " keeps its data in external files (HDF5 external storage), which cpkit "
                  "does not read: store it in the FCLIB file");
    const H5D_layout_t layout = H5Pget_layout(dcpl.get());
    if (layout == H5D_VIRTUAL || layout < 0)
      fail(path + " is a virtual dataset (its data is in other files), which cpkit does not read");
    const int filters = H5Pget_nfilters(dcpl.get());
    for (int k = 0; k < filters; ++k) {
      unsigned flags = 0, config = 0;
      std::size_t values = 0;
      char name[64] = {};
      const H5Z_filter_t id = H5Pget_filter2(dcpl.get(), static_cast<unsigned>(k), &flags,
                                             &values, nullptr, sizeof name, name, &config);
      if (id < 0 || H5Zfilter_avail(id) <= 0)
        fail(path + " is stored with the HDF5 filter " + std::to_string(id) + " ('" +
             io_text::valid_utf8(std::string(name, strnlen(name, sizeof name))) +
             "'), which this HDF5 library cannot decode (h5py's lzf is one): write it "
             "uncompressed or with gzip");
    }
    if (count == 0) return;
    const Id type(H5Dget_type(d), H5Tclose);
    const std::uint64_t stored = H5Dget_storage_size(d);
    const std::uint64_t file_size_each = type.ok() ? H5Tget_size(type.get()) : 0;
    if (layout == H5D_CONTIGUOUS && stored < count * file_size_each)
      fail(path + " declares " + std::to_string(count) + " entries but the file stores " +
           std::to_string(stored) + " bytes for it");
    if (layout == H5D_CHUNKED) {
      hsize_t chunk[1] = {0};
      hsize_t written = 0;
      const Id space(H5Dget_space(d), H5Sclose);
      if (H5Pget_chunk(dcpl.get(), 1, chunk) != 1 || chunk[0] == 0 || !space.ok() ||
          H5Dget_num_chunks(d, space.get(), &written) < 0)
        fail("cannot read the chunks of " + path + " (" + hdf5_reason() + ")");
      const std::uint64_t needed = (count + chunk[0] - 1) / chunk[0];
      if (written < needed)
        fail(path + " declares " + std::to_string(count) + " entries but only " +
             std::to_string(written) + " of its " + std::to_string(needed) +
             " chunks are in the file (the others were never written)");
    }
    if (stored > file_bytes_)
      fail(path + " claims " + std::to_string(stored) + " stored bytes, more than the file's " +
           std::to_string(file_bytes_));
    if (count > static_cast<std::uint64_t>(kMaxSize))
      fail(path + " declares " + std::to_string(count) + " entries, more than cpkit indexes");
    charge(path + " (" + std::to_string(count) + " entries)", count * bytes_each);
  }

 public:
  /// Counts `bytes` of memory about to be taken for `what` against what the file can
  /// plausibly decode to; fails beyond it.
  void charge(const std::string& what, std::uint64_t bytes) {
    decoded_ += bytes;
    if (decoded_ > kDecodedAllowance + kDecodedRatio * file_bytes_)
      fail(what + " brings the memory the file asks for to " + std::to_string(decoded_) +
           " bytes, more than a file of " + std::to_string(file_bytes_) +
           " bytes can plausibly hold (at most " + std::to_string(kDecodedRatio) +
           " times its size + 16 MiB): sizes the file does not hold");
  }

 private:

  template <class T>
  void read(const std::string& path, H5T_class_t cls, std::int64_t expected, bool at_most,
            hid_t memory_type, std::vector<T>& out) {
    const Id d(open(path, cls), H5Dclose);
    const Id space(H5Dget_space(d.get()), H5Sclose);
    const std::uint64_t count = entries(path, space.get());
    if (expected >= 0 && (at_most ? count > static_cast<std::uint64_t>(expected)
                                  : count != static_cast<std::uint64_t>(expected)))
      fail(path + " holds " + std::to_string(count) + " entries, the header declares " +
           (at_most ? "at most " : "") + std::to_string(expected));
    check_storage(d.get(), path, count, sizeof(T));
    out.resize(static_cast<std::size_t>(count));
    if (count > 0 && H5Dread(d.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
      fail("cannot read " + path + " (" + hdf5_reason() +
           "): a damaged file, or data HDF5 cannot decode");
  }

  hid_t file_;
  std::string origin_;
  std::uint64_t file_bytes_;
  std::uint64_t decoded_ = 0;  // bytes of the datasets read so far, as held in memory
};

/// An FCLIB matrix group (CSparse's layout: nz >= 0 triplets, i rows and p columns; nz = -1
/// compressed columns, -2 compressed rows) as an Eigen matrix, every size and index checked.
Eigen::SparseMatrix<double> matrix(Reader& f, const std::string& g) {
  const std::int64_t nzmax = f.integer(g + "/nzmax", 0);
  const std::int64_t m = f.integer(g + "/m", 0);
  const std::int64_t n = f.integer(g + "/n", 0);
  const std::int64_t nz = f.integer(g + "/nz");
  std::vector<std::int64_t> p, i;
  if (nz >= 0) {
    if (nz > nzmax) f.fail(g + ": nz " + std::to_string(nz) + " exceeds nzmax " + std::to_string(nzmax));
    p = f.integers(g + "/p", nz);
    i = f.integers(g + "/i", nz);
  } else if (nz == -1 || nz == -2) {
    p = f.integers(g + "/p", (nz == -1 ? n : m) + 1);
    i = f.integers(g + "/i", nzmax, true);
  } else {
    f.fail(g + ": nz = " + std::to_string(nz) +
           " is no FCLIB storage (>= 0 triplet, -1 compressed columns, -2 compressed rows)");
  }
  const std::vector<double> x = f.reals(g + "/x", nzmax, true);
  const std::uint64_t stored = std::min(i.size(), x.size());
  if (nz >= 0 && stored < static_cast<std::uint64_t>(nz))
    f.fail(g + "/x holds " + std::to_string(x.size()) + " entries, nz declares " + std::to_string(nz));
  // libfclib, which wrote the file, allocates nzmax entries: far more than stored is no file it
  // wrote.
  if (static_cast<std::uint64_t>(nzmax) > 4 * stored + 1024)
    f.fail(g + ": nzmax " + std::to_string(nzmax) + " is far larger than the " +
           std::to_string(stored) + " entries stored");
  auto fail = [&](const std::string& what) { f.fail(g + ": " + what); };
  std::vector<Eigen::Triplet<double>> t;
  auto add = [&](std::int64_t row, std::int64_t col, double v) {
    if (row < 0 || row >= m || col < 0 || col >= n)
      fail("entry (" + std::to_string(row) + ", " + std::to_string(col) + ") outside its " +
           std::to_string(m) + " x " + std::to_string(n) + " size");
    if (!std::isfinite(v))
      fail("entry (" + std::to_string(row) + ", " + std::to_string(col) + ") is not finite");
    t.emplace_back(static_cast<int>(row), static_cast<int>(col), v);
  };
  if (nz >= 0) {
    t.reserve(static_cast<std::size_t>(nz));
    for (std::int64_t k = 0; k < nz; ++k) add(i[k], p[k], x[k]);
  } else {
    const std::int64_t outer = nz == -1 ? n : m;
    if (p[0] != 0) fail("the first pointer is " + std::to_string(p[0]) + ", not 0");
    for (std::int64_t k = 0; k < outer; ++k)
      if (p[k + 1] < p[k] || static_cast<std::uint64_t>(p[k + 1]) > stored)
        fail("pointer " + std::to_string(k + 1) + " = " + std::to_string(p[k + 1]) +
             " decreases or exceeds the " + std::to_string(stored) + " entries stored");
    t.reserve(static_cast<std::size_t>(p[outer]));
    for (std::int64_t k = 0; k < outer; ++k)
      for (std::int64_t e = p[k]; e < p[k + 1]; ++e)
        if (nz == -1)
          add(i[e], k, x[e]);
        else
          add(k, i[e], x[e]);
  }
  // The compressed matrix holds n + 1 column pointers whatever the entries: a declared size
  // costs memory too.
  f.charge(g + " (" + std::to_string(m) + " x " + std::to_string(n) + ")",
           4 * (static_cast<std::uint64_t>(n) + 1));
  Eigen::SparseMatrix<double> out(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(n));
  out.setFromTriplets(t.begin(), t.end());  // duplicates are summed, as CSparse does
  out.makeCompressed();
  return out;
}

Eigen::VectorXd vector(Reader& f, const std::string& path, Eigen::Index n) {
  const std::vector<double> v = f.reals(path, n);
  return Eigen::Map<const Eigen::VectorXd>(v.data(), n);
}

/// Opens `path` and runs `read` on it; InputError when it is no readable HDF5 file.
template <class Read>
auto with_file(const std::string& path, const std::string& origin, Read read) {
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(origin + ": cannot read the file (" + ec.message() + ")");
  QuietHdf5 quiet;
  const Id file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.ok()) throw InputError(origin + ": not a readable HDF5 file (truncated or corrupted?)");
  Reader f(file.get(), origin, bytes);
  return read(f);
}

std::string name_of(Reader& f, const std::string& info, const std::string& path) {
  const std::string title = f.text(info + "/title");
  return title.empty() ? io_text::valid_utf8(std::filesystem::path(path).stem().string()) : title;
}

}  // namespace

FrictionContactProblem read_local(const std::string& path) {
  const std::string origin = io_text::valid_utf8(path);
  return with_file(path, origin, [&](Reader& f) {
    if (!f.exists("/fclib_local")) {
      if (f.exists("/fclib_global"))
        f.fail("holds an FCLIB global problem (/fclib_global), not a local one: read it with "
               "read_global_friction_problem");
      f.fail("is an HDF5 file without an FCLIB problem (/fclib_local)");
    }
    const std::int64_t dim = f.integer("/fclib_local/spacedim");
    if (dim != 3) f.fail("spacedim is " + std::to_string(dim) + "; cpkit reads 3-D problems");
    if (f.exists("/fclib_local/V") || f.exists("/fclib_local/R"))
      f.fail("has the optional V, R, s constraints of FCLIB's mixed problem, which cpkit does not read");
    FrictionContactProblem p;
    p.W = matrix(f, "/fclib_local/W");
    const Eigen::Index m = p.W.rows();
    if (m != p.W.cols() || m % 3 != 0 || m == 0)
      f.fail("W is " + std::to_string(m) + " x " + std::to_string(p.W.cols()) +
             ", expected square with 3 rows per contact");
    p.q = vector(f, "/fclib_local/vectors/q", m);
    p.mu = vector(f, "/fclib_local/vectors/mu", m / 3);
    p.name = name_of(f, "/fclib_local/info", path);
    p.note = f.text("/fclib_local/info/description");
    throw_if_invalid(p.validate(), origin);
    return p;
  });
}

bool holds_global(const std::string& path) {
  return with_file(path, io_text::valid_utf8(path), [](Reader& f) {
    return f.exists("/fclib_global") && !f.exists("/fclib_local");
  });
}

GlobalFrictionContactProblem read_global(const std::string& path) {
  const std::string origin = io_text::valid_utf8(path);
  return with_file(path, origin, [&](Reader& f) {
    if (!f.exists("/fclib_global")) {
      if (f.exists("/fclib_local"))
        f.fail("holds an FCLIB local problem (/fclib_local), not a global one: read it with "
               "read_friction_problem");
      f.fail("is an HDF5 file without an FCLIB problem (/fclib_global)");
    }
    const std::int64_t dim = f.integer("/fclib_global/spacedim");
    if (dim != 3) f.fail("spacedim is " + std::to_string(dim) + "; cpkit reads 3-D problems");
    if (f.exists("/fclib_global/G"))
      f.fail("has FCLIB's optional equality constraints G, b, which cpkit does not read");
    GlobalFrictionContactProblem p;
    p.M = matrix(f, "/fclib_global/M");
    const Eigen::Index dofs = p.M.rows();
    if (dofs != p.M.cols() || dofs == 0)
      f.fail("M is " + std::to_string(dofs) + " x " + std::to_string(p.M.cols()) +
             ", expected square");
    p.H = matrix(f, "/fclib_global/H");
    const Eigen::Index cols = p.H.cols();
    if (p.H.rows() != dofs || cols % 3 != 0 || cols == 0)
      f.fail("H is " + std::to_string(p.H.rows()) + " x " + std::to_string(cols) + ", expected " +
             std::to_string(dofs) + " x 3 n_c");
    p.f = vector(f, "/fclib_global/vectors/f", dofs);
    p.w = vector(f, "/fclib_global/vectors/w", cols);
    p.mu = vector(f, "/fclib_global/vectors/mu", cols / 3);
    p.name = name_of(f, "/fclib_global/info", path);
    p.note = f.text("/fclib_global/info/description");
    throw_if_invalid(p.validate(), origin);
    return p;
  });
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
