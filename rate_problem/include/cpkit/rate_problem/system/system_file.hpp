#pragma once
/// \file system_file.hpp
/// A system file (docs/file_formats.md, "System file") read once, whatever the dimension of its
/// points: the commands read the file (a regular file, or a pipe such as `--system <(cat F)`,
/// which can be read only once), look at its "dim", and hand the parsed document to the 2-D
/// reader (contact_system.hpp) or the 3-D one (both in system/contact_system.hpp).
#include <string>

#include <nlohmann/json.hpp>

namespace cpkit::rate {

struct SystemFile {
  std::string source;       ///< the path (or another name) for messages
  nlohmann::json document;  ///< a JSON object, parsed with the limits of core/json_read.hpp
  int dim = 2;              ///< its "dim": 2 (also when absent) or 3
};

/// `text` as a system file. InputError "source:line: ..." when it is not JSON within the limits
/// of parse_json_bounded (nesting, number range, duplicate keys), and "source: ..." when it is
/// not an object or its "dim" is not 2 or 3.
SystemFile parse_system_file(const std::string& text, const std::string& source = "system");

/// Reads `path` once (a regular file or a FIFO, at most 2 GiB; not a directory or a device) and
/// parses it as parse_system_file does. InputError naming the path for anything wrong.
SystemFile read_system_file(const std::string& path);

}  // namespace cpkit::rate
