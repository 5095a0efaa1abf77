#pragma once
// Internal: reading numbers from the JSON system files (2-D and 3-D) with messages that name
// the field.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/json_read.hpp"
#include "cpkit/rate_problem/model/interface_parameters.hpp"

namespace cpkit::rate::detail {

/// A JSON value as shown in a message (at most 40 characters, at a cost bounded by that).
inline std::string shown(const nlohmann::json& v) { return json_excerpt(v, 40); }

/// "point i" with i 1-based, as in the file.
inline std::string point_name(std::size_t i) { return "point " + std::to_string(i + 1); }

/// A finite number, or InputError naming `field`.
inline double get_num(const nlohmann::json& v, const std::string& field) {
  if (!v.is_number()) throw InputError(field + " must be a number, got " + shown(v));
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw InputError(field + " must be a finite number");
  return d;
}

/// The interface data that 2-D and 3-D points share (mu, C_T, k_a, P_s): reads key `k` into its
/// field and returns true, or returns false for another key.
inline bool read_interface_key(const std::string& k, const nlohmann::json& v, const std::string& f,
                               InterfaceParameters& p) {
  double* field = k == "mu"    ? &p.mu
                  : k == "C_T" ? &p.C_T
                  : k == "k_a" ? &p.k_a
                  : k == "P_s" ? &p.P_s
                               : nullptr;
  if (!field) return false;
  *field = get_num(v, f);
  return true;
}

/// Largest system file read (bytes): a bound on what a FIFO, which has no size, may send.
inline constexpr std::uintmax_t kMaxSystemFileBytes = std::uintmax_t{1} << 31;  // 2 GiB

/// The text of a system file, read once. As the problem-file readers (docs/file_formats.md):
/// regular files and FIFOs only (`--system <(cat F)`), at most 2 GiB, so that a directory or a
/// device (/dev/zero) cannot block or exhaust memory.
inline std::string read_system_text(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw InputError("cannot open system file " + path);
  if (!fs::is_regular_file(st) && !fs::is_fifo(st))
    throw InputError("system file " + path + " is not a regular file");
  if (fs::is_regular_file(st) && fs::file_size(path, ec) > kMaxSystemFileBytes)
    throw InputError("system file " + path + " is larger than 2 GiB");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open system file " + path);
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxSystemFileBytes)  // a FIFO has no size to check up front
      throw InputError("system file " + path + " is larger than 2 GiB");
  }
  if (in.bad()) throw InputError("error reading system file " + path);
  return text;
}

}  // namespace cpkit::rate::detail
