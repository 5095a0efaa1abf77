// The checkpoint of a map run (map_run.hpp): chunk bytes, the folder PREFIX.parts/ with its
// manifest, and the rules for reading it back (regular files of bounded size, of this map).
#include "map_checkpoint.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/json_read.hpp"

namespace cpkit::rate {

namespace fs = std::filesystem;

namespace {
// Version 2 adds the map identity (map_id) after the magic: a chunk names the map it belongs to.
constexpr char kMagic[8] = {'c', 'p', 'k', 'c', 'h', 'n', 'k', '2'};
constexpr std::size_t kHeaderBytes = 8 + 8 + 4 * 8;  // magic, map_id, index, rows, rank

void put_u64(std::string& s, uint64_t v) {
  char b[8];
  std::memcpy(b, &v, 8);
  s.append(b, 8);
}
uint64_t get_u64(const std::string& s, std::size_t& at) {
  if (at + 8 > s.size()) throw InputError("truncated map chunk");
  uint64_t v = 0;
  std::memcpy(&v, s.data() + at, 8);
  at += 8;
  return v;
}

}  // namespace

uint64_t fnv1a(const std::string& bytes) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}


std::string chunk_path(const std::string& folder, int k) {
  return (fs::path(folder) / ("chunk_" + std::to_string(k) + ".bin")).string();
}

namespace {

/// The bytes of a checkpoint file (its first `head` bytes), which must have at most
/// `max_bytes`. Only a regular file is read: a device (/dev/zero), a
/// FIFO or a symbolic link put in a checkpoint folder is refused without reading or blocking
/// (opened with O_NONBLOCK | O_NOFOLLOW, then checked with fstat).
std::string read_checkpoint_file(const std::string& path, uint64_t max_bytes,
                                 uint64_t head = UINT64_MAX) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0)
    throw InputError("cannot read the checkpoint file '" + path + "': " + std::strerror(errno) +
                     (errno == ELOOP ? " (a symbolic link: a checkpoint holds only the files "
                                       "cpkit wrote)" : ""));
  struct Close {
    int fd;
    ~Close() { ::close(fd); }
  } close_fd{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))
    throw InputError("the checkpoint file '" + path + "' is not a regular file (a device, FIFO "
                     "or folder): a checkpoint holds only the files cpkit wrote; remove it or "
                     "run without --resume");
  const uint64_t size = static_cast<uint64_t>(st.st_size);
  if (size > max_bytes)
    throw InputError("the checkpoint file '" + path + "' has " + std::to_string(size) +
                     " bytes, more than the " + std::to_string(max_bytes) +
                     " a file of this map can have: it is not one cpkit wrote; remove it or "
                     "run without --resume");
  const uint64_t want = std::min(size, head);
  std::string bytes(static_cast<std::size_t>(want), '\0');
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  if (got != bytes.size())
    throw InputError("the checkpoint file '" + path + "' changed while read (" +
                     std::to_string(got) + " of " + std::to_string(want) + " bytes)");
  return bytes;
}

}  // namespace

nlohmann::json parse_checkpoint_json(const std::string& text, const std::string& what) {
  // The one bounded JSON parser of every cpkit input (core/json_read.hpp: nesting, numbers,
  // duplicate keys): a hostile checkpoint file cannot crash the program.
  try {
    return parse_json_bounded(text, what);
  } catch (const InputError& e) {
    throw InputError(what + " is not a checkpoint file cpkit wrote: " + e.what());
  }
}

namespace {

/// Largest file chunk k of a map can be: its arrays (at most 16 bytes a cell; the kinds write
/// 2 to 6) and its summary (critical directions and values: bounded per row).
uint64_t max_chunk_bytes(const ChunkPlan& p, int k) {
  const uint64_t rows = static_cast<uint64_t>(p.end(k) - p.begin(k));
  return (uint64_t{1} << 20) + rows * (uint64_t{1} << 16) +
         rows * static_cast<uint64_t>(p.columns) * 16;
}

constexpr uint64_t kMaxManifestBytes = uint64_t{1} << 20;

}  // namespace

/// The chunk of file `path`, checked against the map: a regular file of bounded size, chunk k
/// with the plan's rows, written for this map (map_id).
MapChunk read_chunk(const ChunkRun& run, const std::string& path, int k) {
  MapChunk c;
  try {
    c = parse_chunk(read_checkpoint_file(path, max_chunk_bytes(run.plan, k)));
  } catch (const InputError& e) {
    throw InputError("checkpoint chunk '" + path + "': " + e.what());
  }
  if (c.map_id != run.map_id)
    throw InputError("checkpoint chunk '" + path + "' was written by another map (another "
                     "run on the same --out with other input or options); remove the "
                     "checkpoint folder or run without --resume");
  if (c.index != k || c.row_begin != run.plan.begin(k) || c.row_end != run.plan.end(k))
    throw InputError("checkpoint chunk '" + path + "' is corrupt (it holds chunk " +
                     std::to_string(c.index) + ", rows " + std::to_string(c.row_begin) + ".." +
                     std::to_string(c.row_end) + ")");
  return c;
}

/// Written under a temporary name and renamed: a chunk file is complete or absent.
void write_file_atomic(const std::string& path, const std::string& bytes) {
  const std::string tmp = path + ".partial";
  {
    std::ofstream f(tmp, std::ios::binary);
    f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    f.close();
    if (!f) throw InputError("cannot write '" + tmp + "' (disk full?)");
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw InputError("cannot write '" + path + "': " + ec.message());
}

/// The chunks already finished in the checkpoint (rank 0): with --resume and the same manifest;
/// otherwise the folder is started afresh.
std::vector<char> open_checkpoint(const ChunkRun& run, ChunkRunStats& stats) {
  std::vector<char> have(static_cast<std::size_t>(run.plan.chunks), 0);
  if (run.checkpoint.empty()) {
    if (run.resume) throw InputError("--resume needs --out PREFIX (the checkpoint is PREFIX.parts)");
    return have;
  }
  const fs::path dir(run.checkpoint);
  const fs::path manifest = dir / "manifest.json";
  std::error_code ec;
  if (run.resume) {
    if (!fs::exists(manifest))
      throw InputError("--resume: no checkpoint in '" + dir.string() + "' (nothing to resume: run "
                       "without --resume)");
    const nlohmann::json old = parse_checkpoint_json(
        read_checkpoint_file(manifest.string(), kMaxManifestBytes),
        "--resume: '" + manifest.string() + "'");
    if (!old.is_object())
      throw InputError("--resume: '" + manifest.string() + "' is not a checkpoint manifest");
    // What the checkpoint belongs to: version, inputs (the system's data hash), options, grid.
    auto shown = [](const nlohmann::json& v) {
      std::string t = v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
      return t.size() > 200 ? t.substr(0, 200) + "..." : t;
    };
    // The innermost field that differs ("input.from"), so that the message names it.
    auto first_difference = [](const nlohmann::json& there, const nlohmann::json& now,
                               std::string& path, const nlohmann::json*& a,
                               const nlohmann::json*& b) {
      a = &there;
      b = &now;
      while (a->is_object() && b->is_object()) {
        const nlohmann::json *na = nullptr, *nb = nullptr;
        std::string key;
        for (const auto& [k, v] : b->items())
          if (!a->contains(k) || a->at(k) != v) {
            key = k;
            na = a->contains(k) ? &a->at(k) : nullptr;
            nb = &v;
            break;
          }
        if (!nb) break;
        if (!na) {
          path += "." + key;
          a = nullptr;
          b = nb;
          return;
        }
        path += "." + key;
        a = na;
        b = nb;
      }
    };
    for (const auto& [key, value] : run.manifest.items())
      if (!old.contains(key) || old[key] != value) {
        std::string path = key;
        const nlohmann::json *there = nullptr, *now = &value;
        if (old.contains(key)) first_difference(old[key], value, path, there, now);
        throw InputError("--resume: the checkpoint in '" + dir.string() + "' was made for a "
                         "different map (" + path + " differs: " +
                         (there ? shown(*there) : std::string("absent")) + " there, " +
                         shown(*now) + " now); remove it or run without --resume");
      }
    for (const auto& [key, value] : old.items())
      if (!run.manifest.contains(key))
        throw InputError("--resume: the checkpoint in '" + dir.string() + "' was made for a "
                         "different map (it has " + key + ", this map has none); remove it or "
                         "run without --resume");
    for (int k = 0; k < run.plan.chunks; ++k) {
      const std::string path = chunk_path(run.checkpoint, k);
      std::error_code sec;
      if (fs::symlink_status(path, sec).type() == fs::file_type::not_found) continue;
      // Every present chunk is checked before any work (the whole of it when consumed): a
      // regular file of bounded size, of this map.
      const std::string head = read_checkpoint_file(path, max_chunk_bytes(run.plan, k), kHeaderBytes);
      if (head.size() < kHeaderBytes || std::memcmp(head.data(), kMagic, 8) != 0)
        throw InputError("--resume: '" + path + "' is not a chunk of this cpkit version's "
                         "checkpoints; remove the checkpoint folder or run without --resume");
      std::size_t at = 8;
      if (get_u64(head, at) != run.map_id)
        throw InputError("--resume: '" + path + "' was written by another map (another run on "
                         "the same --out with other input or options); remove the checkpoint "
                         "folder '" + dir.string() + "' or run without --resume");
      if (get_u64(head, at) != static_cast<uint64_t>(k))
        throw InputError("--resume: '" + path + "' is corrupt (it holds another chunk)");
      have[static_cast<std::size_t>(k)] = 1;
      ++stats.resumed_chunks;
      stats.resumed_cells += static_cast<int64_t>(run.plan.end(k) - run.plan.begin(k)) * run.plan.columns;
    }
    return have;
  }
  fs::remove_all(dir, ec);
  fs::create_directories(dir, ec);
  if (ec) throw InputError("cannot create the checkpoint folder '" + dir.string() + "'");
  write_file_atomic(manifest.string(),
                    run.manifest.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  return have;
}


std::string serialize_chunk(const MapChunk& c) {
  std::string s(kMagic, 8);
  put_u64(s, c.map_id);
  put_u64(s, static_cast<uint64_t>(c.index));
  put_u64(s, static_cast<uint64_t>(c.row_begin));
  put_u64(s, static_cast<uint64_t>(c.row_end));
  put_u64(s, static_cast<uint64_t>(c.rank));
  const std::string j = c.summary.dump();
  put_u64(s, j.size());
  s += j;
  put_u64(s, c.arrays.size());
  for (const auto& a : c.arrays) {
    put_u64(s, a.size());
    s += a;
  }
  return s;
}

MapChunk parse_chunk(const std::string& b) {
  if (b.size() < 8 || std::memcmp(b.data(), kMagic, 8) != 0) throw InputError("not a cpkit map chunk");
  std::size_t at = 8;
  MapChunk c;
  c.map_id = get_u64(b, at);
  c.index = static_cast<int>(get_u64(b, at));
  c.row_begin = static_cast<int>(get_u64(b, at));
  c.row_end = static_cast<int>(get_u64(b, at));
  c.rank = static_cast<int>(get_u64(b, at));
  const uint64_t jn = get_u64(b, at);
  if (jn > b.size() - at) throw InputError("truncated map chunk");
  c.summary = parse_checkpoint_json(b.substr(at, jn), "the map chunk's summary");
  at += jn;
  const uint64_t na = get_u64(b, at);
  if (na > 64) throw InputError("corrupt map chunk");
  for (uint64_t i = 0; i < na; ++i) {
    const uint64_t n = get_u64(b, at);
    if (n > b.size() - at) throw InputError("truncated map chunk");
    c.arrays.push_back(b.substr(at, n));
    at += n;
  }
  if (at != b.size()) throw InputError("corrupt map chunk (trailing bytes)");
  return c;
}

void remove_checkpoint(const std::string& folder) {
  if (folder.empty()) return;
  std::error_code ec;
  fs::remove_all(folder, ec);
}


}  // namespace cpkit::rate
