// The friction problem readers (core/friction_io.hpp) on hostile files (issue 34: F4-05, F4-07,
// F4-10, F4-11, external storage, user blocks, damaged global files). The files of
// tests/data/fclib/hostile were written with h5py by the hostile round (their README gives the
// expected answers); the others are written here with HDF5's C API. Independent sources: the
// READMEs' stated contents (W = I, q = (-1, 0, 0), mu = 0.5 per contact; the titles), the
// datasets read straight with HDF5's C API, and the same file read from a regular path.
#include <catch2/catch.hpp>
#include <fcntl.h>
#include <signal.h>
#include <hdf5.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"
#include "scratch_files.hpp"

namespace {

namespace fs = std::filesystem;
using cpkit::InputError;
using Eigen::MatrixXd;
using Eigen::VectorXd;

fs::path data(const std::string& rel) { return fs::path(CPKIT_TEST_DATA_DIR) / "fclib" / rel; }
fs::path hostile(const std::string& name) { return data("hostile/" + name); }

fs::path scratch() {
  static const fs::path dir = cpkit::test::scratch_dir("cpkit_test_friction_io_hostile_");
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// The InputError message of `f` (fails the test when there is none).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("no InputError");
  return {};
}

/// A string dataset read with HDF5's C API as h5py stores a str (variable length) or bytes.
std::string raw_string(hid_t file, const char* path) {
  const hid_t d = H5Dopen2(file, path, H5P_DEFAULT);
  REQUIRE(d >= 0);
  const hid_t t = H5Dget_type(d);
  std::string out;
  if (H5Tis_variable_str(t) > 0) {
    char* s = nullptr;
    REQUIRE(H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, &s) >= 0);
    out = s;
    H5free_memory(s);
  } else {
    std::vector<char> b(H5Tget_size(t) + 1, '\0');
    REQUIRE(H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, b.data()) >= 0);
    out = b.data();
  }
  H5Tclose(t);
  H5Dclose(d);
  return out;
}

// ---- small FCLIB files written here with HDF5's C API -----------------------------------------

/// One dataset of `n` entries of native type `type` at `path`, with creation properties `dcpl`
/// (H5P_DEFAULT: contiguous).
void put(hid_t file, const std::string& path, hid_t type, const void* data, hsize_t n,
         hid_t dcpl = H5P_DEFAULT) {
  const hid_t space = H5Screate_simple(1, &n, nullptr);
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  const hid_t d = H5Dcreate2(file, path.c_str(), type, space, lcpl, dcpl, H5P_DEFAULT);
  REQUIRE(d >= 0);
  if (data && n > 0) REQUIRE(H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0);
  H5Dclose(d);
  H5Pclose(lcpl);
  H5Sclose(space);
}
void put_int(hid_t file, const std::string& path, int v) { put(file, path, H5T_NATIVE_INT, &v, 1); }

/// A local FCLIB problem of `contacts` contacts, W = 2 I (compressed columns), q = (-1, 0, 0),
/// mu = 0.3 per contact; `q_dcpl` stores q (H5P_DEFAULT: contiguous); `write_q` false leaves
/// q's data unwritten; `userblock` reserves that many bytes before the HDF5 data; `identity`
/// false writes W = 0 as a triplet matrix without entries; `mu_dcpl` stores mu.
fs::path write_local(const std::string& name, int contacts, hid_t q_dcpl = H5P_DEFAULT,
                     bool write_q = true, hsize_t userblock = 0, bool identity = true,
                     hid_t mu_dcpl = H5P_DEFAULT) {
  const fs::path path = scratch() / name;
  const hid_t fcpl = H5Pcreate(H5P_FILE_CREATE);
  if (userblock) H5Pset_userblock(fcpl, userblock);
  const hid_t f = H5Fcreate(path.string().c_str(), H5F_ACC_TRUNC, fcpl, H5P_DEFAULT);
  REQUIRE(f >= 0);
  const int n = 3 * contacts;
  std::vector<int> p(n + 1), i(n);
  std::vector<double> x(n, 2.0), q(n, 0.0), mu(contacts, 0.3);
  for (int k = 0; k <= n; ++k) p[k] = k;
  for (int k = 0; k < n; ++k) i[k] = k;
  for (int c = 0; c < contacts; ++c) q[3 * c] = -1;
  put_int(f, "/fclib_local/spacedim", 3);
  for (const char* s : {"/fclib_local/W/m", "/fclib_local/W/n"}) put_int(f, s, n);
  if (identity) {
    put_int(f, "/fclib_local/W/nzmax", n);
    put_int(f, "/fclib_local/W/nz", -1);
    put(f, "/fclib_local/W/p", H5T_NATIVE_INT, p.data(), n + 1);
    put(f, "/fclib_local/W/i", H5T_NATIVE_INT, i.data(), n);
    put(f, "/fclib_local/W/x", H5T_NATIVE_DOUBLE, x.data(), n);
  } else {
    put_int(f, "/fclib_local/W/nzmax", 0);
    put_int(f, "/fclib_local/W/nz", 0);
    put(f, "/fclib_local/W/p", H5T_NATIVE_INT, nullptr, 0);
    put(f, "/fclib_local/W/i", H5T_NATIVE_INT, nullptr, 0);
    put(f, "/fclib_local/W/x", H5T_NATIVE_DOUBLE, nullptr, 0);
  }
  put(f, "/fclib_local/vectors/q", H5T_NATIVE_DOUBLE, write_q ? q.data() : nullptr, n, q_dcpl);
  put(f, "/fclib_local/vectors/mu", H5T_NATIVE_DOUBLE, mu.data(), contacts, mu_dcpl);
  H5Fclose(f);
  H5Pclose(fcpl);
  return path;
}

/// Checks that `p` is write_local's problem of `contacts` contacts.
void check_written_local(const cpkit::FrictionContactProblem& p, int contacts) {
  REQUIRE(p.contacts() == contacts);
  CHECK(MatrixXd(p.W) == 2 * MatrixXd::Identity(3 * contacts, 3 * contacts));
  for (int c = 0; c < contacts; ++c) {
    CHECK(p.q.segment<3>(3 * c) == Eigen::Vector3d(-1, 0, 0));
    CHECK(p.mu[c] == 0.3);
  }
}

/// Peak resident memory of this process (kB).
long peak_kb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

}  // namespace

TEST_CASE("F4-05: FCLIB strings are one string each, read without overrunning a buffer",
          "[friction][io][hostile]") {
  // title_array.hdf5 holds 1000 strings of 10 bytes at info/title, description_vlen_array.hdf5
  // 300 variable-length strings at info/description: FCLIB stores one string there. Refused,
  // the dataset named (libfclib wrote all of them into a buffer sized for one: heap overflow).
  CHECK_THAT(input_error([] { cpkit::read_friction_problem(hostile("title_array.hdf5").string()); }),
             Catch::Contains("/fclib_local/info/title") && Catch::Contains("1000 strings"));
  CHECK_THAT(input_error([] {
               cpkit::read_friction_problem(hostile("description_vlen_array.hdf5").string());
             }),
             Catch::Contains("/fclib_local/info/description") && Catch::Contains("300 strings"));
  // The README's titles: "a vlen title" (h5py's scalar variable-length str) and "hostile"
  // (np.bytes_: 7 bytes, NULLPAD, no NUL); read straight with HDF5's C API too.
  const auto vlen = cpkit::read_friction_problem(hostile("title_vlen.hdf5").string());
  CHECK(vlen.name == "a vlen title");
  const auto fixed = cpkit::read_friction_problem(hostile("title_fixed_h5py.hdf5").string());
  CHECK(fixed.name == "hostile");
  for (const char* f : {"title_vlen.hdf5", "title_fixed_h5py.hdf5"}) {
    const hid_t file = H5Fopen(hostile(f).string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(file >= 0);
    CHECK(raw_string(file, "/fclib_local/info/title") == (f[6] == 'v' ? vlen.name : fixed.name));
    H5Fclose(file);
  }
  // W's comment (an array of 2000 strings) belongs to W's optional info, which cpkit does not
  // use: the problem reads, 2 contacts, as its datasets say.
  const auto w = cpkit::read_friction_problem(hostile("W_comment_array.hdf5").string());
  CHECK(w.contacts() == 2);
  CHECK(w.validate().empty());
  CHECK(w.W.rows() == 6);
  CHECK(w.q.size() == 6);
  CHECK(w.q == fixed.q);  // the same base problem as the other files (the README: base_local())
  CHECK(MatrixXd(w.W) == MatrixXd(fixed.W));
  CHECK(w.mu == fixed.mu);
}

TEST_CASE("F4-07: data HDF5 cannot decode is an input error naming the dataset, never exit(1)",
          "[friction][io][hostile]") {
  // q_lzf.hdf5: q compressed with h5py's LZF (libhdf5 has no decoder); q_gzip_corrupt.hdf5: the
  // gzip chunk damaged. libfclib ended the process (exit 1, the Python interpreter killed).
  CHECK_THAT(input_error([] { cpkit::read_friction_problem(hostile("q_lzf.hdf5").string()); }),
             Catch::Contains("q_lzf.hdf5") && Catch::Contains("/fclib_local/vectors/q") &&
                 Catch::Contains("filter"));
  CHECK_THAT(
      input_error([] { cpkit::read_friction_problem(hostile("q_gzip_corrupt.hdf5").string()); }),
      Catch::Contains("q_gzip_corrupt.hdf5") && Catch::Contains("/fclib_local/vectors/q"));
  // The undamaged file: the README's problem, 100 contacts, W = I, q = (-1, 0, 0), mu = 0.5.
  const auto ok = cpkit::read_friction_problem(hostile("q_gzip_ok.hdf5").string());
  REQUIRE(ok.contacts() == 100);
  CHECK(MatrixXd(ok.W) == MatrixXd::Identity(300, 300));
  for (int c = 0; c < 100; ++c) {
    CHECK(ok.q.segment<3>(3 * c) == Eigen::Vector3d(-1, 0, 0));
    CHECK(ok.mu[c] == 0.5);
  }
}

TEST_CASE("external storage and external links are refused, whatever they point to",
          "[friction][io][hostile]") {
  // q's bytes in a raw file named by the dataset: /dev/zero (q read as zeros), a file of the
  // right length, a missing file. HDF5 would read each (or fail inside libfclib): refused.
  const std::vector<double> q = {-1, 0, 0, -1, 0, 0};
  const fs::path raw = scratch() / "q.raw";
  std::ofstream(raw, std::ios::binary).write(reinterpret_cast<const char*>(q.data()), 48);
  for (const std::string& target : {std::string("/dev/zero"), raw.string(),
                                   (scratch() / "missing.raw").string()}) {
    INFO(target);
    const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
    REQUIRE(H5Pset_external(dcpl, target.c_str(), 0, 48) >= 0);
    const fs::path p = write_local("external.hdf5", 2, dcpl, false);
    H5Pclose(dcpl);
    CHECK_THAT(input_error([&] { cpkit::read_friction_problem(p.string()); }),
               Catch::Contains("/fclib_local/vectors/q") && Catch::Contains("external"));
  }
  // mu as an external link into another FCLIB file.
  const fs::path other = write_local("other.hdf5", 2);
  const fs::path linked = write_local("linked.hdf5", 2);
  {
    const hid_t f = H5Fopen(linked.string().c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    REQUIRE(H5Ldelete(f, "/fclib_local/vectors/mu", H5P_DEFAULT) >= 0);
    REQUIRE(H5Lcreate_external(other.string().c_str(), "/fclib_local/vectors/mu", f,
                               "/fclib_local/vectors/mu", H5P_DEFAULT, H5P_DEFAULT) >= 0);
    H5Fclose(f);
  }
  CHECK_THAT(input_error([&] { cpkit::read_friction_problem(linked.string()); }),
             Catch::Contains("/fclib_local/vectors/mu") && Catch::Contains("external link"));
}

TEST_CASE("F4-11: declared sizes the file does not hold are refused before they are allocated",
          "[friction][io][hostile]") {
  // amp.hdf5: 64 KB declaring 9e6 rows, 1 chunk in 8 of q and mu written. The README's bound:
  // a refusal within 10 s and 256 MB (it took 1.6 GB and 9.9 s).
  const auto start = std::chrono::steady_clock::now();
  const std::string message =
      input_error([] { cpkit::read_friction_problem(hostile("amp.hdf5").string()); });
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK_THAT(message, Catch::Contains("amp.hdf5") && Catch::Contains("/fclib_local"));
  CHECK(seconds <= 10);
  CHECK(peak_kb() <= 256 * 1024);
  // q chunked, 4 chunks declared, never written: the data is not in the file.
  const hsize_t chunk = 3;
  hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(dcpl, 1, &chunk);
  const fs::path unwritten = write_local("unwritten.hdf5", 4, dcpl, false);
  CHECK_THAT(input_error([&] { cpkit::read_friction_problem(unwritten.string()); }),
             Catch::Contains("/fclib_local/vectors/q") && Catch::Contains("0 of its 4 chunks"));
  // Every chunk written, gzip, W = 0 (no entries): 1e6 contacts (q: 24 MB of zeros) in a file of
  // tens of kB is more than a file can plausibly hold (64 times its size + 16 MiB).
  const hsize_t big_chunk = 1 << 18;
  H5Pset_chunk(dcpl, 1, &big_chunk);
  H5Pset_deflate(dcpl, 9);
  const fs::path zipped = write_local("zipped.hdf5", 1000000, dcpl, true, 0, false, dcpl);
  H5Pclose(dcpl);
  REQUIRE(fs::file_size(zipped) < 100000);
  CHECK_THAT(input_error([&] { cpkit::read_friction_problem(zipped.string()); }),
             Catch::Contains("/fclib_local/vectors/q") && Catch::Contains("plausibly"));
  // The same layouts with every chunk written and a plausible size read, as written.
  dcpl = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(dcpl, 1, &chunk);
  H5Pset_deflate(dcpl, 6);
  check_written_local(cpkit::read_friction_problem(write_local("chunked.hdf5", 4, dcpl).string()), 4);
  H5Pclose(dcpl);
}

TEST_CASE("F4-10: a .dat file through a FIFO is read once; HDF5 through one is refused",
          "[friction][io][hostile]") {
  const fs::path regular = data("local/FC3D_Example1.dat");
  const auto expected = cpkit::read_friction_problem(regular.string());
  const fs::path global_regular = data("global/GFC3D_Example1.dat");
  const auto expected_global = cpkit::read_global_friction_problem(global_regular.string());
  // Writes `source` into a fresh FIFO from a thread; a reader that opened the FIFO a second
  // time would block forever: after 20 s a watchdog opens it once more and closes it (the
  // reader then sees an empty file and the test fails instead of hanging).
  auto through_fifo = [](const fs::path& source, auto read) {
    const fs::path fifo = scratch() / "p.dat";
    fs::remove(fifo);
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const std::string bytes = slurp(source);
    std::atomic<bool> finished{false};
    std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << bytes; });
    std::thread watchdog([&] {
      for (int k = 0; k < 200 && !finished; ++k)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      if (!finished) close(open(fifo.c_str(), O_WRONLY));
    });
    auto guard = [&] {
      finished = true;
      watchdog.join();
      // A reader that stopped early leaves the writer blocked: give it a reader (and ignore
      // the SIGPIPE of its unread bytes).
      signal(SIGPIPE, SIG_IGN);
      const int unblock = open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
      writer.join();
      if (unblock >= 0) close(unblock);
    };
    try {
      auto out = read(fifo.string());
      guard();
      return out;
    } catch (...) {
      guard();
      throw;
    }
  };
  const auto local = through_fifo(regular, [](const std::string& p) {
    return cpkit::read_friction_problem(p);
  });
  CHECK(MatrixXd(local.W) == MatrixXd(expected.W));
  CHECK(local.q == expected.q);
  CHECK(local.mu == expected.mu);
  // A global .dat file through a FIFO, its kind told from the one reading.
  const auto any = through_fifo(global_regular, [](const std::string& p) {
    return cpkit::read_friction_problem_file(p);
  });
  REQUIRE(any.is_global);
  CHECK(MatrixXd(any.global.M) == MatrixXd(expected_global.M));
  CHECK(MatrixXd(any.global.H) == MatrixXd(expected_global.H));
  CHECK(any.global.f == expected_global.f);
  CHECK(any.global.w == expected_global.w);
  // HDF5 needs to seek: an FCLIB file through a FIFO is refused, saying so.
  const std::string message = input_error([&] {
    through_fifo(data("local/Capsules-i125-1213.hdf5"),
                 [](const std::string& p) { return cpkit::read_friction_problem(p); });
  });
  CHECK_THAT(message, Catch::Contains("HDF5") && Catch::Contains("FIFO"));
}

TEST_CASE("an HDF5 file after a user block is read as HDF5, not as text",
          "[friction][io][hostile]") {
  // HDF5 finds its signature at 0, 512, 1024, 2048, ...: a file whose first 512 bytes are text
  // (here a valid .dat problem of 1 contact) is the FCLIB problem after them.
  for (hsize_t block : {hsize_t{512}, hsize_t{2048}}) {
    INFO(block);
    const fs::path p = write_local("userblock.hdf5", 2, H5P_DEFAULT, true, block);
    {
      std::fstream f(p, std::ios::binary | std::ios::in | std::ios::out);
      f << "3 1 0 3 3 3 3 15 -1 -2 -1 14 1 -2 1 16 -1 2 3 0.1\n";
    }
    check_written_local(cpkit::read_friction_problem(p.string()), 2);
  }
}

TEST_CASE("a damaged global file is reported as a global one", "[friction][io][hostile]") {
  // A GlobalFrictionContact .dat file written here (1 contact, m = 6 degrees of freedom, dense
  // storage, its sizes repeated): d nc | 0 6 6 6 6 M (36) | 0 6 3 6 3 H (18) | q (6) | b (3) |
  // mu (1). One number of M, H, q (cpkit's f), b (cpkit's w) or mu made "x": the message is the
  // global reader's, naming that part (it was the local reader's, about W's size).
  std::vector<std::string> tokens = {"3", "1", "0", "6", "6", "6", "6"};
  for (int k = 0; k < 36; ++k) tokens.push_back(k % 7 == 0 ? "2" : "0");  // M = 2 I
  for (const char* t : {"0", "6", "3", "6", "3"}) tokens.push_back(t);
  for (int k = 0; k < 18; ++k) tokens.push_back(k % 7 == 0 ? "1" : "0");
  for (const char* t : {"0", "0", "0", "0", "0", "0", "-1", "0", "0", "0.5"}) tokens.push_back(t);
  REQUIRE(tokens.size() == 76);
  auto text_of = [](const std::vector<std::string>& t) {
    std::string out;
    for (const auto& w : t) out += w + "\n";
    return out;
  };
  const fs::path p = scratch() / "global.dat";
  std::ofstream(p) << text_of(tokens);
  const auto good = cpkit::read_friction_problem_file(p.string());
  REQUIRE(good.is_global);
  CHECK(MatrixXd(good.global.M) == 2 * MatrixXd::Identity(6, 6));
  const std::pair<std::size_t, const char*> damage[] = {
      {8, "M("}, {49, "H("}, {67, "q (cpkit's f)"}, {73, "b (cpkit's w)"}, {75, "mu"}};
  for (const auto& [at, part] : damage) {
    std::vector<std::string> bad = tokens;
    bad[at] = "x";
    std::ofstream(p) << text_of(bad);
    INFO(part);
    const std::string message = input_error([&] { cpkit::read_friction_problem_file(p.string()); });
    CHECK_THAT(message, Catch::Contains(part) && Catch::Contains("'x'"));
    CHECK_THAT(message, !Catch::Contains("W"));
  }
  // A local file damaged the same way is still reported by the local reader.
  const std::string local = "3 1 0 3 3 3 3 15 -1 -2 -1 14 1 -2 1 16 -1 x 3 0.1";
  std::ofstream(p) << local;
  CHECK_THAT(input_error([&] { cpkit::read_friction_problem_file(p.string()); }),
             Catch::Contains("q[1]"));
  // An FCLIB global file with a non-finite entry of H: the global reader's message.
  const fs::path copy = scratch() / "damaged_global.hdf5";
  fs::copy_file(data("global/Box_Stacks-i0122-82-5.hdf5"), copy,
                fs::copy_options::overwrite_existing);
  fs::permissions(copy, fs::perms::owner_write, fs::perm_options::add);
  {
    const hid_t f = H5Fopen(copy.string().c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    REQUIRE(f >= 0);
    const hid_t d = H5Dopen2(f, "/fclib_global/H/x", H5P_DEFAULT);
    const hid_t s = H5Dget_space(d);
    std::vector<double> x(static_cast<std::size_t>(H5Sget_simple_extent_npoints(s)));
    REQUIRE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, x.data()) >= 0);
    x[0] = NAN;
    REQUIRE(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, x.data()) >= 0);
    H5Sclose(s);
    H5Dclose(d);
    H5Fclose(f);
  }
  CHECK_THAT(input_error([&] { cpkit::read_friction_problem_file(copy.string()); }),
             Catch::Contains("/fclib_global/H") && Catch::Contains("not finite"));
}
