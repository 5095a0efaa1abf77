// Outputs that must not destroy data: output/input identity and the prefix lock
// (output_guard.hpp).
#include "output_guard.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include "cpkit/core/errors.hpp"

namespace cpkit::cli {

namespace fs = std::filesystem;

namespace {

/// Absolute, with "." and ".." and the symbolic links of its existing part resolved.
fs::path normalised(const std::string& p) {
  std::error_code ec;
  fs::path n = fs::weakly_canonical(fs::absolute(p, ec), ec);
  if (ec) n = fs::absolute(p, ec).lexically_normal();
  return n;
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return false;
  struct stat sa {}, sb {};
  // stat, not open: an input that is a FIFO or a device is compared without being read.
  const bool ea = ::stat(a.c_str(), &sa) == 0, eb = ::stat(b.c_str(), &sb) == 0;
  if (ea && eb) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  return normalised(a) == normalised(b);
}

bool inside_folder(const std::string& path, const std::string& folder) {
  if (path.empty() || folder.empty()) return false;
  const fs::path p = normalised(path), f = normalised(folder);
  auto pi = p.begin();
  for (auto fi = f.begin(); fi != f.end(); ++fi, ++pi)
    if (pi == p.end() || *pi != *fi) return false;
  return true;
}

void refuse_outputs_over_inputs(const std::string& command, const std::vector<NamedPath>& outputs,
                                const std::vector<NamedPath>& inputs) {
  for (const auto& o : outputs) {
    if (o.path.empty()) continue;
    for (const auto& i : inputs)
      if (same_file(o.path, i.path))
        throw InputError(command + ": the output '" + o.path + "' (" + o.what +
                         ") is the input file '" + i.path + "' (" + i.what +
                         "): writing it would destroy the input; choose another output path");
  }
  for (std::size_t k = 0; k < outputs.size(); ++k)
    for (std::size_t l = k + 1; l < outputs.size(); ++l)
      if (same_file(outputs[k].path, outputs[l].path))
        throw InputError(command + ": two outputs are the same file '" + outputs[k].path +
                         "' (" + outputs[k].what + " and " + outputs[l].what +
                         "): one would overwrite the other; give them different paths");
}

void refuse_special_outputs(const std::string& command, const std::vector<NamedPath>& outputs) {
  for (const auto& o : outputs) {
    struct stat st {};
    if (o.path.empty() || ::stat(o.path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) continue;
    throw InputError(command + ": the output '" + o.path + "' (" + o.what +
                     ") exists and is not a regular file (a device, a pipe, a folder or a link "
                     "to one): it cannot hold the output; remove it or choose another path");
  }
}

std::vector<NamedPath> prefix_output_files(const std::string& prefix,
                                           const std::vector<std::string>& suffixes) {
  std::vector<NamedPath> out;
  if (prefix.empty()) return out;
  const std::string head = "--out " + prefix + ": ";
  for (const auto& n : suffixes) {
    out.push_back({head + "PREFIX" + n, prefix + n});
    out.push_back({head + "PREFIX" + n + ".partial", prefix + n + ".partial"});
  }
  return out;
}

std::vector<NamedPath> map_output_files(const std::string& prefix) {
  std::vector<std::string> names = {".json", ".csv", ".png", ".svg", ".lock", "_critical.csv"};
  for (const char* key : {"count", "types", "disagree", "x", "y", "theta", "class", "min_count",
                          "max_count", "pattern", "complete"})
    names.push_back(std::string("_") + key + ".npy");
  return prefix_output_files(prefix, names);
}

PrefixLock::PrefixLock(const std::string& prefix) : path_(prefix + ".lock") {
  // The holder removes the file when it ends; a run that opened the old file just before must
  // not lock that unlinked inode and think it owns the prefix: it checks that the path still
  // names the file it locked, and otherwise tries again.
  for (int attempt = 0; attempt < 16; ++attempt) {
    const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0)
      throw InputError("cannot create the lock file '" + path_ + "': " + std::strerror(errno));
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
      ::close(fd);
      throw InputError("the lock file '" + path_ + "' is not a regular file: remove it");
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      char buf[32] = {};
      const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
      ::close(fd);
      std::string holder = n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string();
      while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
      if (err == EWOULDBLOCK)
        throw InputError("the output prefix '" + prefix + "' is in use: '" + path_ +
                         "' is locked" + (holder.empty() ? "" : " by process " + holder) +
                         " (another cpkit run writing the same --out); wait for it to end or "
                         "choose another --out");
      throw InputError("cannot lock '" + path_ + "': " + std::strerror(err));
    }
    struct stat now {};
    if (::stat(path_.c_str(), &now) == 0 && now.st_dev == st.st_dev && now.st_ino == st.st_ino) {
      const std::string pid = std::to_string(::getpid()) + "\n";
      if (::ftruncate(fd, 0) == 0) (void)!::pwrite(fd, pid.data(), pid.size(), 0);
      fd_ = fd;
      return;
    }
    ::close(fd);  // removed by its previous holder meanwhile: lock the new one
  }
  throw InputError("cannot lock '" + path_ + "': it keeps being replaced (another run?)");
}

PrefixLock::~PrefixLock() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // while still locked: a waiting run then re-checks the path
  ::close(fd_);
}

}  // namespace cpkit::cli
