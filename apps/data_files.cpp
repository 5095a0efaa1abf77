#include "data_files.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace cpkit::cli {
namespace fs = std::filesystem;

std::string find_data_file(const std::string& name, std::string* searched) {
  std::error_code ec;
  // /proc/self/exe: the executable itself, wherever it was installed or copied with its tree.
  const fs::path exe = fs::canonical("/proc/self/exe", ec);
  std::string tried;
  if (!ec) {
    const fs::path p = exe.parent_path() / CPKIT_BIN_TO_DATA_DIR / name;
    if (fs::is_regular_file(p, ec)) return p.lexically_normal().string();
    tried += p.lexically_normal().string();
  }
  const fs::path src = fs::path(CPKIT_SOURCE_SCRIPT_DIR) / name;
  if (fs::is_regular_file(src, ec)) return src.string();
  tried += (tried.empty() ? "" : ", ") + src.string();
  if (searched) *searched = tried;
  return {};
}

std::string plot_python() {
  if (const char* p = std::getenv("CPKIT_PYTHON"); p && *p) return p;
  std::error_code ec;
  return fs::exists("/usr/bin/python3", ec) ? "/usr/bin/python3" : "python3";
}

}  // namespace cpkit::cli
