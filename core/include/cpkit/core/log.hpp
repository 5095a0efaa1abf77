#pragma once
/// \file log.hpp
/// Library code never prints: it writes to a LogSink the caller provides (or to nothing).
#include <mutex>
#include <ostream>
#include <string_view>

namespace cpkit {

enum class LogLevel { kError = 0, kWarning = 1, kInfo = 2, kDebug = 3 };
std::string_view to_string(LogLevel level) noexcept;

/// Receives log lines. Implementations must be safe to call from several threads.
class LogSink {
 public:
  virtual ~LogSink() = default;
  virtual void write(LogLevel level, std::string_view message) = 0;
};

/// Writes "[level] message" lines to a stream (e.g. std::cerr), serialized by a mutex.
class StreamLogSink final : public LogSink {
 public:
  explicit StreamLogSink(std::ostream& out) : out_(out) {}
  void write(LogLevel level, std::string_view message) override;

 private:
  std::ostream& out_;
  std::mutex mutex_;
};

/// Sends a message to `sink` when it exists and `verbosity` admits `level`
/// (verbosity 0: errors only; 1: + warnings; 2: + info; 3: + debug).
void log(LogSink* sink, int verbosity, LogLevel level, std::string_view message);

}  // namespace cpkit
