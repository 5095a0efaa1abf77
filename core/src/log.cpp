#include "cpkit/core/log.hpp"

namespace cpkit {

std::string_view to_string(LogLevel level) noexcept {
  switch (level) {
    case LogLevel::kError: return "error";
    case LogLevel::kWarning: return "warning";
    case LogLevel::kInfo: return "info";
    case LogLevel::kDebug: return "debug";
  }
  return "unknown";
}

void StreamLogSink::write(LogLevel level, std::string_view message) {
  std::lock_guard<std::mutex> lock(mutex_);
  out_ << '[' << to_string(level) << "] " << message << '\n';
}

void log(LogSink* sink, int verbosity, LogLevel level, std::string_view message) {
  if (sink != nullptr && static_cast<int>(level) <= verbosity) sink->write(level, message);
}

}  // namespace cpkit
