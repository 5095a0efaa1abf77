#pragma once
// What this machine can hold: memory available now (/proc/meminfo MemAvailable, else
// sysconf physical pages) and free disk space at a path (statvfs). Used to refuse, up front, a
// job that cannot fit (exit 2 with the option that makes it fit).
#include <sys/statvfs.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

namespace cpkit::cli {

/// Bytes of memory available to a new job; -1 when unknown.
inline double available_memory_bytes() {
  if (std::FILE* f = std::fopen("/proc/meminfo", "r")) {
    char line[256];
    while (std::fgets(line, sizeof line, f)) {
      unsigned long long kib = 0;
      if (std::sscanf(line, "MemAvailable: %llu kB", &kib) == 1) {
        std::fclose(f);
        return 1024.0 * static_cast<double>(kib);
      }
    }
    std::fclose(f);
  }
  const long pages = sysconf(_SC_AVPHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page > 0) return static_cast<double>(pages) * static_cast<double>(page);
  return -1;
}

/// Bytes free for an unprivileged writer in the file system holding `dir`; -1 when unknown.
inline double free_disk_bytes(const std::string& dir) {
  struct statvfs s;
  std::memset(&s, 0, sizeof s);
  if (statvfs(dir.empty() ? "." : dir.c_str(), &s) != 0) return -1;
  return static_cast<double>(s.f_bavail) * static_cast<double>(s.f_frsize);
}

}  // namespace cpkit::cli
