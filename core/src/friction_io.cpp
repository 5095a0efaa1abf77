// The friction problem readers' entry points. The format is chosen by content: HDF5's 8-byte
// signature at offset 0, or at 512, 1024, 2048, ... after a user block (where HDF5 itself looks
// for it), not by the file name. A file is read once: a pipe or FIFO (`<(cat F.dat)`) cannot be
// opened a second time.
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"
#include "friction_io_dat.hpp"
#include "friction_io_fclib.hpp"
#include "io_text.hpp"

namespace cpkit {
namespace {

constexpr char kHdf5Signature[] = "\x89HDF\r\n\x1a\n";

bool has_signature_at(const std::string& bytes, std::size_t offset) {
  return bytes.size() >= offset + 8 && std::memcmp(bytes.data() + offset, kHdf5Signature, 8) == 0;
}

/// A problem file: HDF5 (then read by HDF5 from its path) or the text of a .dat file.
struct Input {
  bool hdf5 = false;
  std::string text;
};

/// A JSON text is named as such (most likely the LCP file of `cpkit lcp solve`), not read as
/// .dat numbers, where its '{' would meet "expected the contact dimension d".
void refuse_json(const std::string& text, const std::string& path) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos || (text[first] != '{' && text[first] != '[')) return;
  const bool lcp =
      text.find("\"M\"") != std::string::npos && text.find("\"q\"") != std::string::npos;
  throw InputError(io_text::valid_utf8(path) + ": " +
                   (lcp ? "an LCP file (JSON with M and q)" : "a JSON file") +
                   ", not a frictional contact problem (FCLIB HDF5 or Siconos FrictionContact / "
                   "GlobalFrictionContact .dat)" +
                   (lcp ? ": solve it with `cpkit lcp solve`"
                        : std::string()));
}

Input read_input(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const bool regular = fs::is_regular_file(fs::status(path, ec));
  if (regular) {
    // Every FCLIB file: the signature in the first 8 bytes, the file read by HDF5 itself.
    std::ifstream in(path, std::ios::binary);
    std::string head(8, '\0');
    if (in.read(head.data(), 8) && has_signature_at(head, 0)) return {true, {}};
  }
  // Read whole, once (FIFOs included; read_text refuses directories, devices, missing files).
  Input input{false, io_text::read_text(path)};
  for (std::size_t offset = 0; offset + 8 <= input.text.size(); offset = offset ? 2 * offset : 512) {
    if (!has_signature_at(input.text, offset)) continue;
    if (!regular)
      throw InputError(io_text::valid_utf8(path) +
                       ": an HDF5 (FCLIB) file cannot be read from a pipe or FIFO (HDF5 seeks "
                       "in the file): give it as a regular file");
    return {true, {}};  // after a user block of `offset` bytes: HDF5 finds it there too
  }
  refuse_json(input.text, path);
  return input;
}

}  // namespace

FrictionContactProblem read_friction_problem(const std::string& path) {
  const Input input = read_input(path);
  if (input.hdf5) return fclib_io::read_local(path);
  return parse_friction_dat(input.text, path);
}

GlobalFrictionContactProblem read_global_friction_problem(const std::string& path) {
  const Input input = read_input(path);
  if (input.hdf5) return fclib_io::read_global(path);
  return parse_global_friction_dat(input.text, path);
}

FrictionProblemFile read_friction_problem_file(const std::string& path) {
  const Input input = read_input(path);
  FrictionProblemFile out;
  if (input.hdf5) {
    out.is_global = fclib_io::holds_global(path);
    if (out.is_global)
      out.global = fclib_io::read_global(path);
    else
      out.local = fclib_io::read_local(path);
    return out;
  }
  // A .dat file says nothing of its kind but its numbers: a local reading first (the common
  // kind), then a global one; when neither reads, the message of the one that read further.
  std::size_t local_reached = 0, global_reached = 0;
  try {
    out.local = friction_dat::parse_local(input.text, path, local_reached);
    return out;
  } catch (const InputError& local_error) {
    try {
      out.global = friction_dat::parse_global(input.text, path, global_reached);
    } catch (const InputError&) {
      if (global_reached > local_reached) throw;
      throw local_error;
    }
  }
  out.is_global = true;
  return out;
}

void write_friction_solution(const std::string& path, const FrictionContactProblem& problem,
                             const Eigen::VectorXd& r, const Eigen::VectorXd& u) {
  fclib_io::write_local_with_solution(path, problem, r, u);
}

}  // namespace cpkit
