#pragma once
// Test helper (not a test): a per-process scratch folder under the system temp directory and
// a writer of small text files in it.
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace cpkit::test {

/// A folder named <prefix><random number>, created once per process and prefix.
inline std::filesystem::path scratch_dir(const std::string& prefix) {
  std::random_device rd;
  auto d = std::filesystem::temp_directory_path() / (prefix + std::to_string(rd()));
  std::filesystem::create_directories(d);
  return d;
}

/// Writes `text` to dir/name and returns the path.
inline std::string write_file(const std::filesystem::path& dir, const std::string& name,
                              const std::string& text) {
  const auto path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

}  // namespace cpkit::test
