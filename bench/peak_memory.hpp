#pragma once
// Resident memory of this process from /proc/self/status (Linux): VmRSS now and VmHWM, its
// peak. reset_peak_memory() sets the peak back to the current size (writing 5 to
// /proc/self/clear_refs, Linux >= 4.0), so that peak - current measures what comes next.
#include <cstdio>
#include <cstring>

namespace cpkit::bench {

/// The "Name:   N kB" field of /proc/self/status in kB; -1 when unreadable.
inline long proc_status_kb(const char* name) {
  std::FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return -1;
  char line[256];
  long kb = -1;
  const size_t len = std::strlen(name);
  while (std::fgets(line, sizeof line, f))
    if (std::strncmp(line, name, len) == 0 && line[len] == ':') {
      std::sscanf(line + len + 1, "%ld", &kb);
      break;
    }
  std::fclose(f);
  return kb;
}

inline long resident_kb() { return proc_status_kb("VmRSS"); }
inline long peak_resident_kb() { return proc_status_kb("VmHWM"); }

/// True when the peak was reset to the current resident size.
inline bool reset_peak_memory() {
  std::FILE* f = std::fopen("/proc/self/clear_refs", "w");
  if (!f) return false;
  const bool ok = std::fputs("5", f) >= 0;
  return std::fclose(f) == 0 && ok;
}

}  // namespace cpkit::bench
