#pragma once
// Outputs that must not destroy data (issue 24, items 8 and 9): a command refuses an output path
// that is one of its inputs (or another of its outputs) before it writes anything, and a map
// holds an exclusive lock on its --out prefix for the whole run, so two runs never mix their
// files or checkpoints. `cpkit fc bench` guards and locks its PREFIX.csv and .png the same way
// (issue 34, F4-08 and F4-09).
#include <string>
#include <vector>

namespace cpkit::cli {

/// A path with what it is for messages ("--system", "--out PREFIX: PREFIX.json").
struct NamedPath {
  std::string what;
  std::string path;
};

/// True when a and b are the same file: the same device and inode when both exist (hard links,
/// symbolic links, "./x" and "x" alike), else the same normalised absolute path (an output that
/// does not exist yet but names an input).
bool same_file(const std::string& a, const std::string& b);

/// True when `path` is `folder` or lies inside it (normalised absolute paths).
bool inside_folder(const std::string& path, const std::string& folder);

/// Throws InputError (exit 2) naming both when an output is an input, or two outputs are the
/// same file. Empty paths are skipped. `command` heads the message ("cpkit map").
void refuse_outputs_over_inputs(const std::string& command, const std::vector<NamedPath>& outputs,
                                const std::vector<NamedPath>& inputs);

/// Throws InputError (exit 2) naming it when an output exists and is not a regular file: a
/// device such as /dev/full, a FIFO, a folder, or a symbolic link to one. Such outputs are
/// refused, not replaced: a table written as NAME.partial and renamed would replace the link,
/// and a device cannot hold the table (`cpkit fc bench`).
void refuse_special_outputs(const std::string& command, const std::vector<NamedPath>& outputs);

/// The files PREFIX<suffix> and their ".partial" names (written until complete), named for
/// messages ("--out PREFIX: PREFIX.csv"): what a command writes under its --out prefix.
std::vector<NamedPath> prefix_output_files(const std::string& prefix,
                                           const std::vector<std::string>& suffixes);

/// Every file a map may write under PREFIX (PREFIX.json, .csv, .png, .svg, .lock,
/// PREFIX_critical.csv, PREFIX_<array>.npy, and their ".partial" names while written), named
/// for messages.
std::vector<NamedPath> map_output_files(const std::string& prefix);

/// An exclusive advisory lock (flock) on PREFIX.lock, held while the object lives; the file is
/// removed when the lock is released. A second holder is refused at once (InputError naming
/// the lock file and the process holding it), never left waiting. A lock whose process has
/// ended (killed, crashed) is released by the system: the next run takes it.
class PrefixLock {
 public:
  explicit PrefixLock(const std::string& prefix);
  ~PrefixLock();
  PrefixLock(const PrefixLock&) = delete;
  PrefixLock& operator=(const PrefixLock&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace cpkit::cli
