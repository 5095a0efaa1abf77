// The friction problem readers' entry points: the format is chosen by content (HDF5's 8-byte
// signature at the start of the file; FCLIB files have no user block), not by the file name.
#include <cstring>
#include <fstream>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"
#include "friction_io_fclib.hpp"
#include "io_text.hpp"

namespace cpkit {
namespace {

bool is_hdf5(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(io_text::valid_utf8(path) + ": cannot open the file");
  char head[8] = {};
  in.read(head, 8);
  return in.gcount() == 8 && std::memcmp(head, "\x89HDF\r\n\x1a\n", 8) == 0;
}

}  // namespace

FrictionContactProblem read_friction_problem(const std::string& path) {
  if (is_hdf5(path)) return fclib_io::read_local(path);
  return parse_friction_dat(io_text::read_text(path), path);
}

GlobalFrictionContactProblem read_global_friction_problem(const std::string& path) {
  if (is_hdf5(path)) return fclib_io::read_global(path);
  return parse_global_friction_dat(io_text::read_text(path), path);
}

void write_friction_solution(const std::string& path, const FrictionContactProblem& problem,
                             const Eigen::VectorXd& r, const Eigen::VectorXd& u) {
  fclib_io::write_local_with_solution(path, problem, r, u);
}

}  // namespace cpkit
