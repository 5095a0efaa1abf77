// The friction problem readers (core/friction_io.hpp) on the real files of tests/data/fclib and
// on broken copies of them. Independent sources: the smallest .dat file's numbers stated by hand
// from its text; FCLIB files read a second way, dataset by dataset with HDF5's C API and the
// matrices decoded by hand here; solutions written by cpkit (through libfclib) read back by
// libfclib's fclib_read_solution. Hostile files: test_friction_io_hostile.cpp. Siconos' reader on every .dat file: test_friction_io_siconos_peer.cpp.
#include <catch2/catch.hpp>
extern "C" {  // fclib.h has no C++ guards
#include <fclib.h>
}
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
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

fs::path scratch() {
  static const fs::path dir = cpkit::test::scratch_dir("cpkit_test_friction_io_");
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

fs::path write_bytes(const std::string& name, const std::string& bytes) {
  const fs::path p = scratch() / name;
  std::ofstream(p, std::ios::binary) << bytes;
  return p;
}

// ---- a second route into FCLIB files: HDF5's C API, dataset by dataset ----------------------

template <class T>
std::vector<T> read_dataset(hid_t file, const std::string& path, hid_t type) {
  const hid_t d = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  REQUIRE(d >= 0);
  const hid_t s = H5Dget_space(d);
  const hssize_t n = H5Sget_simple_extent_npoints(s);
  std::vector<T> v(static_cast<std::size_t>(n));
  REQUIRE(H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
  H5Sclose(s);
  H5Dclose(d);
  return v;
}
std::vector<int> ints(hid_t f, const std::string& p) { return read_dataset<int>(f, p, H5T_NATIVE_INT); }
VectorXd doubles(hid_t f, const std::string& p) {
  const auto v = read_dataset<double>(f, p, H5T_NATIVE_DOUBLE);
  return Eigen::Map<const VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

/// The matrix group `g` as a dense matrix, decoded by hand: nz >= 0 triplet (CSparse: i rows,
/// p columns), -1 compressed columns, -2 compressed rows.
MatrixXd raw_matrix(hid_t f, const std::string& g) {
  const int m = ints(f, g + "/m")[0], n = ints(f, g + "/n")[0], nz = ints(f, g + "/nz")[0];
  const auto p = ints(f, g + "/p"), i = ints(f, g + "/i");
  const VectorXd x = doubles(f, g + "/x");
  MatrixXd a = MatrixXd::Zero(m, n);
  if (nz >= 0) {
    for (int k = 0; k < nz; ++k) a(i[k], p[k]) += x[k];
  } else {
    const int outer = nz == -1 ? n : m;
    for (int k = 0; k < outer; ++k)
      for (int e = p[k]; e < p[k + 1]; ++e) (nz == -1 ? a(i[e], k) : a(k, i[e])) += x[e];
  }
  return a;
}

struct H5File {
  hid_t id;
  explicit H5File(const fs::path& p, unsigned flags = H5F_ACC_RDONLY)
      : id(H5Fopen(p.string().c_str(), flags, H5P_DEFAULT)) {
    REQUIRE(id >= 0);
  }
  ~H5File() { H5Fclose(id); }
};

/// InputError whose message names the file (or part of it) and contains `what`.
template <class F>
void require_input_error(F&& f, const std::string& file, const std::string& what = "") {
  try {
    f();
    FAIL("no InputError for " << file);
  } catch (const InputError& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).find(file) != std::string::npos);
    if (!what.empty()) CHECK(std::string(e.what()).find(what) != std::string::npos);
  }
}

}  // namespace

TEST_CASE("FrictionContact3D_1c.dat holds the numbers its text shows", "[friction][io]") {
  // The file: d 3, nc 1, dense 3 x 3 W column by column, q, mu (read by eye).
  const auto p = cpkit::read_friction_problem(data("local/FrictionContact3D_1c.dat").string());
  REQUIRE(p.contacts() == 1);
  MatrixXd W(3, 3);
  W << 15, -1, -2, -1, 14, 1, -2, 1, 16;
  CHECK(MatrixXd(p.W) == W);
  CHECK(p.q == Eigen::Vector3d(-1, 2, 3));
  CHECK(p.mu[0] == 0.1);
  CHECK(p.name == "FrictionContact3D_1c");
}

TEST_CASE("every local and global file of tests/data/fclib reads", "[friction][io]") {
  int local = 0, global = 0;
  for (const auto& e : fs::directory_iterator(data("local"))) {
    INFO(e.path());
    const auto p = cpkit::read_friction_problem(e.path().string());
    CHECK(p.contacts() >= 1);
    CHECK(p.validate().empty());
    // W is a Delassus operator: nearly symmetric (these files: to 1e-3 of its largest entry).
    const MatrixXd W = p.W;
    CHECK((W - W.transpose()).cwiseAbs().maxCoeff() <= 1e-2 * W.cwiseAbs().maxCoeff());
    ++local;
  }
  for (const auto& e : fs::directory_iterator(data("global"))) {
    INFO(e.path());
    const auto p = cpkit::read_global_friction_problem(e.path().string());
    CHECK(p.contacts() >= 1);
    CHECK(p.validate().empty());
    ++global;
  }
  CHECK(local == 12);
  CHECK(global == 3);
}

TEST_CASE("FCLIB files read as their HDF5 datasets say", "[friction][io][fclib]") {
  for (const char* name : {"local/Capsules-i125-1213.hdf5", "local/fclib_local_problem_test.hdf5"}) {
    INFO(name);
    const auto p = cpkit::read_friction_problem(data(name).string());
    H5File f(data(name));
    const MatrixXd W = raw_matrix(f.id, "/fclib_local/W");
    const VectorXd q = doubles(f.id, "/fclib_local/vectors/q");
    const VectorXd mu = doubles(f.id, "/fclib_local/vectors/mu");
    REQUIRE(p.contacts() == mu.size());
    CHECK(p.W.nonZeros() == (W.array() != 0).count());
    CHECK(MatrixXd(p.W) == W);
    CHECK(p.q == q);
    CHECK(p.mu == mu);
  }
  const auto name = "global/Box_Stacks-i0122-82-5.hdf5";
  const auto p = cpkit::read_global_friction_problem(data(name).string());
  H5File f(data(name));
  CHECK(MatrixXd(p.M) == raw_matrix(f.id, "/fclib_global/M"));
  CHECK(MatrixXd(p.H) == raw_matrix(f.id, "/fclib_global/H"));
  CHECK(p.f == doubles(f.id, "/fclib_global/vectors/f"));
  CHECK(p.w == doubles(f.id, "/fclib_global/vectors/w"));
  CHECK(p.mu == doubles(f.id, "/fclib_global/vectors/mu"));
  // A global file is not a local one, and the other way round: said, not crashed.
  require_input_error([&] { cpkit::read_friction_problem(data(name).string()); }, name, "global");
  require_input_error(
      [&] { cpkit::read_global_friction_problem(data("local/Capsules-i125-1213.hdf5").string()); },
      "Capsules-i125-1213.hdf5", "local");
}

TEST_CASE("a solution written by cpkit reads back through libfclib", "[friction][io][fclib]") {
  const auto p = cpkit::read_friction_problem(data("local/Rover4396.dat").string());
  VectorXd r(p.W.rows());
  for (Eigen::Index i = 0; i < r.size(); ++i) r[i] = 0.25 * static_cast<double>(i) - 1.0 / 3.0;
  const VectorXd u = p.W * r + p.q;
  const fs::path out = scratch() / "solution.hdf5";
  cpkit::write_friction_solution(out.string(), p, r, u);
  cpkit::write_friction_solution(out.string(), p, r, u);  // an existing file is replaced
  const auto back = cpkit::read_friction_problem(out.string());
  CHECK(MatrixXd(back.W) == MatrixXd(p.W));
  CHECK(back.q == p.q);
  CHECK(back.mu == p.mu);
  fclib_solution* s = fclib_read_solution(out.string().c_str());  // the file has /solution
  REQUIRE(s != nullptr);
  CHECK(Eigen::Map<const VectorXd>(s->r, r.size()) == r);
  CHECK(Eigen::Map<const VectorXd>(s->u, u.size()) == u);
  fclib_delete_solutions(s, 1);
  require_input_error([&] { cpkit::write_friction_solution(out.string(), p, r.head(3), u); },
                      "write_friction_solution", "entries");
}

TEST_CASE("a written solution holds each contact's state in /solution/status",
          "[friction][io][fclib]") {
  // W = I, mu = 1/2: each contact decoupled, solved by hand. q = (1, 0, 0): r = 0, u = q
  // (separated). q = (-1, 0.1, 0): r = (1, -0.1, 0), u = 0, |r_T| = 0.1 < mu r_N (stick).
  // q = (-1, 2, 0): r = (1, -0.5, 0), u = (0, 1.5, 0): r_T = -mu r_N u_T / |u_T|, and
  // u_hat = (0.75, 1.5, 0) is on the boundary of K*, r . u_hat = 0.75 - 0.75 = 0 (slip).
  cpkit::FrictionContactProblem p;
  p.W = MatrixXd::Identity(9, 9).sparseView();
  p.q = (VectorXd(9) << 1, 0, 0, -1, 0.1, 0, -1, 2, 0).finished();
  p.mu = VectorXd::Constant(3, 0.5);
  const VectorXd r = (VectorXd(9) << 0, 0, 0, 1, -0.1, 0, 1, -0.5, 0).finished();
  const VectorXd u = p.W * r + p.q;
  const fs::path out = scratch() / "states.hdf5";
  cpkit::write_friction_solution(out.string(), p, r, u);
  {
    H5File f(out);
    CHECK(ints(f.id, "/solution/status") == std::vector<int>{0, 1, 2});
    const hid_t d = H5Dopen2(f.id, "/solution/status", H5P_DEFAULT);
    REQUIRE(d >= 0);
    const hid_t a = H5Aopen(d, "states", H5P_DEFAULT);
    REQUIRE(a >= 0);
    const hid_t t = H5Aget_type(a);
    std::string key(H5Tget_size(t), '\0');
    REQUIRE(H5Aread(a, t, key.data()) >= 0);
    CHECK(key.c_str() == std::string("0 separated, 1 stick, 2 slip"));
    H5Tclose(t);
    H5Aclose(a);
    H5Dclose(d);
  }
  // The extra dataset does not disturb libfclib's readers.
  const auto back = cpkit::read_friction_problem(out.string());
  CHECK(back.q == p.q);
  fclib_solution* s = fclib_read_solution(out.string().c_str());
  REQUIRE(s != nullptr);
  CHECK(Eigen::Map<const VectorXd>(s->r, r.size()) == r);
  CHECK(Eigen::Map<const VectorXd>(s->u, u.size()) == u);
  fclib_delete_solutions(s, 1);
  fclib_local* l = fclib_read_local(out.string().c_str());
  REQUIRE(l != nullptr);
  CHECK(Eigen::Map<const VectorXd>(l->q, 9) == p.q);
  fclib_delete_local(l);
}

TEST_CASE("truncated .dat files are input errors at every cut", "[friction][io][bad]") {
  // Siconos' test files end with one token after mu (Siconos ignores it; so does cpkit): a cut
  // that keeps every token up to mu is a complete file, every shorter one an input error.
  const std::pair<const char*, int> files[] = {{"local/FrictionContact3D_1c.dat", 0},
                                               {"local/Rover4396.dat", 1},
                                               {"global/GFC3D_Example1.dat", 1},
                                               {"sparse/empty_column_csc.dat", 0},
                                               {"sparse/Rover4396_coo.dat", 0}};
  for (const auto& [name, trailing] : files) {
    const std::string text = slurp(data(name));
    const bool global = std::string(name).rfind("global", 0) == 0;
    auto tokens = [](const std::string& t) {
      std::istringstream in(t);
      std::string w;
      int n = 0;
      while (in >> w) ++n;
      return n;
    };
    const int needed = tokens(text) - trailing;
    int cuts = 0;
    for (std::size_t k = 0; k < text.size(); ++k) {
      if (!std::isspace(static_cast<unsigned char>(text[k]))) continue;
      const std::string cut = text.substr(0, k);
      if (tokens(cut) >= needed) break;
      INFO(name << " cut at byte " << k);
      if (global)
        CHECK_THROWS_AS(cpkit::parse_global_friction_dat(cut, name), InputError);
      else
        CHECK_THROWS_AS(cpkit::parse_friction_dat(cut, name), InputError);
      ++cuts;
    }
    CHECK(cuts >= needed - 1);
  }
}

TEST_CASE("corrupted .dat files name what is wrong", "[friction][io][bad]") {
  const std::string f = "bad.dat";
  auto bad = [&](const std::string& text, const std::string& what) {
    INFO(text);
    require_input_error([&] { cpkit::parse_friction_dat(text, f); }, f, what);
  };
  const std::string W = " 0 3 3 3 3  15 -1 -2 -1 14 1 -2 1 16 ";
  // The valid file these are made from (FrictionContact3D_1c.dat's numbers).
  CHECK(cpkit::parse_friction_dat("3 1" + W + "-1 2 3 0.1", f).contacts() == 1);
  bad("3 1" + W + "-1 nan 3 0.1", "q[1]");
  bad("3 1" + W + "-1 2 3 -0.1", "mu[0]");
  bad("3 1 0 3 3 3 3  15 -1 -2 -1 1e999 1 -2 1 16 -1 2 3 0.1", "W(1, 1)");
  bad("3 1 0 3 3 3 3  15 -1 -2 -1 14 1 -2 1 16 -1 2 3", "ends");  // no mu
  bad("2 1" + W + "-1 2 3 0.1", "dimension");                     // a 2-D problem
  bad("3 2" + W + "-1 2 3 0.1", "rows of W");                     // W is 3 x 3, not 6 x 6
  bad("3 999999999" + W + "-1 2 3 0.1", "contacts");              // huge nc: refused, not allocated
  bad("3 1 0 3 3 3 3 15", "ends too early");
  bad("3 1 2 3 3 3 3 15 1 2 3 4 5 6 7 8 9 10", "sparse origin 3 of W is not read");
  bad("3 1 7 3 3 3 3 15 1 2 3 4 5 6 7 8 9 10", "storage type 7");
  bad("3 1 1 3 3 2147483647 1 1 3 3 2 1 0 1 0 0 1 2 3 4 5 6 7 8 9 -1 2 3 0.1", "blocks");
  bad("3 1" + W + "-1 2 3 0.1 7 8", "more numbers follow mu");
  // A global file is not a local one (its M would pass for W): refused, not misread.
  require_input_error(
      [&] { cpkit::read_friction_problem(data("global/GFC3D_Example1.dat").string()); },
      "GFC3D_Example1.dat", "more numbers follow mu");
  bad("", "empty");
  bad("hello world", "contact dimension");
  require_input_error(
      [&] { cpkit::parse_global_friction_dat("3 1 0 1000000000 1000000000 1 2 3", f); }, f, "M");
}

TEST_CASE("files in neither format, and broken FCLIB files, are input errors", "[friction][io][bad]") {
  const std::string binary("\x01\x02\xff\xfe\x00garbage", 12);
  const auto junk = write_bytes("junk.bin", binary);
  require_input_error([&] { cpkit::read_friction_problem(junk.string()); }, "junk.bin");
  require_input_error([&] { cpkit::read_friction_problem((scratch() / "missing.dat").string()); },
                      "missing.dat");
  // Truncated HDF5: the signature is there, the rest is not.
  const std::string h5 = slurp(data("local/Capsules-i125-1213.hdf5"));
  for (std::size_t cut : {std::size_t{8}, std::size_t{100}, h5.size() / 2, h5.size() - 1}) {
    const auto p = write_bytes("cut.hdf5", h5.substr(0, cut));
    INFO("cut at " << cut);
    require_input_error([&] { cpkit::read_friction_problem(p.string()); }, "cut.hdf5");
  }
  // Valid HDF5, broken FCLIB content: edited with HDF5's API in a copy of a written file.
  const auto p = cpkit::read_friction_problem(data("local/FrictionContact3D_1c.dat").string());
  const VectorXd r = VectorXd::Ones(3), u = p.W * r + p.q;
  auto edited = [&](const std::string& name, auto edit) {
    const fs::path path = scratch() / name;
    cpkit::write_friction_solution(path.string(), p, r, u);
    {
      H5File f(path, H5F_ACC_RDWR);
      edit(f.id);
    }
    return path.string();
  };
  // H5S_ALL writes the whole dataset: the buffer must hold as many elements as it has (libfclib
  // stores a scalar as a dataset of a few elements; one int on the stack overflowed under ASan).
  auto elements = [](hid_t d) {
    const hid_t space = H5Dget_space(d);
    const hssize_t n = H5Sget_simple_extent_npoints(space);
    H5Sclose(space);
    return n;
  };
  auto set_int = [&](hid_t f, const char* path, int v) {
    const hid_t d = H5Dopen2(f, path, H5P_DEFAULT);
    const hssize_t n = elements(d);
    REQUIRE(n >= 1);
    const std::vector<int> all(static_cast<std::size_t>(n), v);
    REQUIRE(H5Dwrite(d, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, all.data()) >= 0);
    H5Dclose(d);
  };
  auto set_doubles = [&](hid_t f, const char* path, std::vector<double> v) {
    const hid_t d = H5Dopen2(f, path, H5P_DEFAULT);
    REQUIRE(elements(d) == static_cast<hssize_t>(v.size()));
    REQUIRE(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
    H5Dclose(d);
  };
  require_input_error([&] { cpkit::read_friction_problem(edited("huge.hdf5", [&](hid_t f) {
                        set_int(f, "/fclib_local/W/nzmax", 2000000000);
                      })); }, "huge.hdf5", "nzmax");
  require_input_error([&] { cpkit::read_friction_problem(edited("nz.hdf5", [&](hid_t f) {
                        set_int(f, "/fclib_local/W/nz", -3);
                      })); }, "nz.hdf5", "nz = -3");
  require_input_error([&] { cpkit::read_friction_problem(edited("rows.hdf5", [&](hid_t f) {
                        set_int(f, "/fclib_local/W/m", 6);
                      })); }, "rows.hdf5", "W");
  require_input_error([&] { cpkit::read_friction_problem(edited("noq.hdf5", [&](hid_t f) {
                        REQUIRE(H5Ldelete(f, "/fclib_local/vectors/q", H5P_DEFAULT) >= 0);
                      })); }, "noq.hdf5", "vectors/q");
  require_input_error([&] { cpkit::read_friction_problem(edited("mu.hdf5", [&](hid_t f) {
                        set_doubles(f, "/fclib_local/vectors/mu", {-0.5});
                      })); }, "mu.hdf5", "mu[0]");
  require_input_error([&] { cpkit::read_friction_problem(edited("nan.hdf5", [&](hid_t f) {
                        set_doubles(f, "/fclib_local/W/x", std::vector<double>(9, NAN));
                      })); }, "nan.hdf5", "not finite");
  require_input_error([&] { cpkit::read_friction_problem(edited("index.hdf5", [&](hid_t f) {
                        set_int(f, "/fclib_local/W/i", 0);  // row indices: first one ok, still valid
                        set_int(f, "/fclib_local/spacedim", 2);
                      })); }, "index.hdf5", "spacedim");
}

namespace {

// One contact, W = [[2, 0, 0.5], [0, 1.25, 0], [0.5, 0, 3]], q = (-1, 0.25, 0.125), mu = 0.3,
// with W in storage 2 as Siconos 4.4's writer prints it (a csc, then a triplet; the line
// breaks matter: the banner and the header are lines).
const char* const kCsc =
    "3\n1\n2\n3\n3\n2\n"
    "CSparse Version 3.2.0, Sept 12, 2017.  Copyright (c) Timothy A. Davis, 2006-2016\n"
    "3-by-3, nzmax: 5 nnz: 5, 1-norm: 3.5\n"
    "    col 0 : locations 0 to 1\n      0 : 2\n      2 : 0.5\n"
    "    col 1 : locations 2 to 2\n      1 : 1.25\n"
    "    col 2 : locations 3 to 4\n      0 : 0.5\n      2 : 3\n"
    " -1 0.25 0.125\n 0.3\n";
const char* const kTriplet =
    "3\n1\n2\n3\n3\n1\n"
    "CSparse Version 3.2.0, Sept 12, 2017.  Copyright (c) Timothy A. Davis, 2006-2016\n"
    "triplet: 3-by-3, nzmax: 5 nnz: 5\n"
    "    0 0 : 2\n    2 0 : 0.5\n    1 1 : 1.25\n    0 2 : 0.5\n    2 2 : 3\n"
    " -1 0.25 0.125\n 0.3\n";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST_CASE("storage 2 (sparse W) holds the numbers its text shows", "[friction][io][sparse]") {
  MatrixXd W(3, 3);
  W << 2, 0, 0.5, 0, 1.25, 0, 0.5, 0, 3;
  for (const char* text : {kCsc, kTriplet}) {
    const auto p = cpkit::parse_friction_dat(text, "sparse.dat");
    CHECK(MatrixXd(p.W) == W);
    CHECK(p.W.nonZeros() == 5);
    CHECK(p.q == Eigen::Vector3d(-1, 0.25, 0.125));
    CHECK(p.mu[0] == 0.3);
  }
  // The empty column (generate.py's matrix): "col 2 : locations 5 to 4" holds nothing.
  const auto e = cpkit::read_friction_problem(data("sparse/empty_column_csc.dat").string());
  MatrixXd E(6, 6);
  E << 2, 0.25, 0, 0.5, 0, 0, 0.25, 1.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0.5, 0, 0, 3, 0.125, 0,
      0, 0, 0, 0.125, 1, 0, 0, 0, 0, 0, 0, 1;
  CHECK(MatrixXd(e.W) == E);
  // A triplet and a csc of the same problem (Siconos' writer) read the same.
  CHECK(MatrixXd(cpkit::read_friction_problem(data("sparse/FC3D_Example1_coo.dat").string()).W) ==
        MatrixXd(cpkit::read_friction_problem(data("sparse/FC3D_Example1_csc.dat").string()).W));
}

TEST_CASE("malformed storage 2 files name what is wrong", "[friction][io][sparse][bad]") {
  const std::string f = "bad.dat";
  auto bad = [&](const std::string& text, const std::string& what) {
    INFO(text);
    require_input_error([&] { cpkit::parse_friction_dat(text, f); }, f, what);
  };
  const std::string csc = kCsc, triplet = kTriplet;
  // Counts inconsistent with the entries.
  bad(replaced(csc, "nzmax: 5 nnz: 5,", "nzmax: 6 nnz: 6,"), "ends too early");
  bad(replaced(csc, "nnz: 5,", "nnz: 4,"), "the last location of W's col 2 is 4");
  bad(replaced(csc, "locations 2 to 2", "locations 3 to 3"), "the first location of W's col 1");
  bad(replaced(csc, "col 1 :", "col 2 :"), "the index of W's col 1");
  bad(replaced(csc, "nzmax: 5", "nzmax: 4"), "exceeds its nzmax");
  bad(replaced(triplet, "nzmax: 5 nnz: 5", "nzmax: 6 nnz: 6"), "ends too early");
  // Out-of-range indices.
  bad(replaced(csc, "      2 : 3", "      3 : 3"), "the row of entry 4 of W is 3");
  bad(replaced(triplet, "    0 2 : 0.5", "    0 -1 : 0.5"), "the column of entry 3 of W");
  bad(replaced(triplet, "    2 2 : 3", "    2 3 : 3"), "the column of entry 4 of W is 3");
  // Huge sizes: refused before anything is allocated for them.
  bad(replaced(csc, "nzmax: 5 nnz: 5,", "nzmax: 999999999999999 nnz: 999999999999999,"),
      "more entries than the file holds");
  bad(replaced(triplet, "nzmax: 5 nnz: 5", "nzmax: 99999999999 nnz: 99999999999"),
      "more entries than the file holds");
  // A header that does not describe this matrix or this storage.
  bad(replaced(csc, "3-by-3,", "4-by-3,"), "the sparse W is 4-by-3");
  bad(replaced(csc, "3-by-3,", "3x3,"), "expected the size 'R-by-C,'");
  bad(replaced(csc, "CSparse Version", "Sparse Version"), "expected 'CSparse'");
  bad(replaced(triplet, "triplet: ", ""), "announces a 'triplet:' header");
  bad(replaced(csc, "\n2\nCSparse", "\n1\nCSparse"), "announces a 'triplet:' header");
  bad(replaced(csc, "\n2\nCSparse", "\n4\nCSparse"), "sparse origin 4 of W is not read");
  bad(replaced(csc, "\n2\nCSparse", "\n0\nCSparse"), "sparse origin 0");
  bad(replaced(csc, "      1 : 1.25", "      1 : nan"), "entry 2 of W");
  bad(replaced(csc, "locations 0 to 1", "locations 0 - 1"), "expected 'to'");
  bad(replaced(triplet, "    1 1 : 1.25", "    1 1 = 1.25"), "expected ':'");
}
