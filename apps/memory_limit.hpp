#pragma once
// The memory bound of the command line: a run (simulate's load history and series, a map's
// cells) that would need more is refused up front (exit 2) with the size it would need.
#include <cstdint>
#include <cstdio>
#include <string>

namespace cpkit::cli {

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

}  // namespace cpkit::cli
