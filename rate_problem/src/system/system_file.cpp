// Reading a system file once and telling its dimension (system_file.hpp).
#include "cpkit/rate_problem/system/system_file.hpp"

#include "cpkit/core/errors.hpp"
#include "cpkit/core/json_read.hpp"
#include "json_fields.hpp"

namespace cpkit::rate {

SystemFile parse_system_file(const std::string& text, const std::string& source) {
  SystemFile f;
  f.source = source;
  f.document = parse_json_bounded(text, source, "a system file needs 3: {\"A\": [[...]]}");
  if (!f.document.is_object())
    throw InputError(source + ": the system file must be a JSON object, got " +
                     detail::shown(f.document));
  const auto dim = f.document.find("dim");
  if (dim != f.document.end()) {
    const bool number = dim->is_number();
    const double d = number ? dim->get<double>() : 0.0;
    if (!number || (d != 2 && d != 3))
      throw InputError(source + ": dim must be 2 (2-D points) or 3 (3-D points), got " +
                       detail::shown(*dim));
    f.dim = static_cast<int>(d);
  }
  return f;
}

SystemFile read_system_file(const std::string& path) {
  return parse_system_file(detail::read_system_text(path), path);
}

}  // namespace cpkit::rate
