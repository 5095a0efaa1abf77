#pragma once
// The memory bound of a run (simulate's load history and series, a map's cells): a run that
// would need more is refused up front (InputError; exit 2 in `cpkit`) with the size it would need.
#include <cstdint>
#include <cctype>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <string>

#include "cpkit/core/errors.hpp"

namespace cpkit {

constexpr std::int64_t kMemoryLimitBytes = std::int64_t{1} << 30;  // 1 GiB

/// "1.5 GiB", "300 MiB", "12 KiB" (for messages).
inline std::string byte_text(double bytes) {
  const char* unit[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int u = 0;
  while (bytes >= 1024 && u < 6) {
    bytes /= 1024;
    ++u;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g %s", bytes, unit[u]);
  return buf;
}

/// A size in bytes from an option value: a decimal number with an optional suffix K, M, G, T
/// (powers of 1024; "KB"/"KiB" etc. read the same), e.g. "500M", "10G", "1.5T", "4096".
/// Throws InputError naming `option` for anything else (empty, negative, non-finite, junk).
inline double parse_byte_size(const std::string& text, const std::string& option) {
  const std::string bad = option + " must be a size such as 500M, 10G or 4096 (bytes; K, M, G, "
                          "T are powers of 1024), got '" + text + "'";
  if (text.empty() || !(std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '.'))
    throw InputError(bad);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  std::string unit(end);
  for (auto& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  double scale = 1;
  const std::string prefixes = "KMGT";
  if (!unit.empty() && unit != "B") {
    const auto k = prefixes.find(unit[0]);
    const std::string rest = unit.substr(1);
    if (k == std::string::npos || !(rest.empty() || rest == "B" || rest == "IB"))
      throw InputError(bad);
    scale = std::pow(1024.0, static_cast<double>(k + 1));
  }
  if (!std::isfinite(v) || !(v > 0) || text.find_first_of("xX") != std::string::npos)
    throw InputError(bad);
  return v * scale;
}

}  // namespace cpkit
