#pragma once
// The transport of a distributed map run (map_run.hpp), injected by the program: cpkit's is MPI
// (apps/platform/mpi_session.hpp). Free of other headers so that the MPI unit includes it
// without the library's include path.
#include <string>

namespace cpkit::rate {

/// How the processes of a job talk (point-to-point messages of bytes and integers; tags are
/// small non-negative integers). Used only when size() > 1.
class MapTransport {
 public:
  virtual ~MapTransport() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  virtual void send_bytes(const std::string& bytes, int dest, int tag) = 0;
  /// Waits for a message with `tag` from any rank; returns its bytes and sets *from.
  virtual std::string recv_bytes(int tag, int* from) = 0;
  /// True (and *from set) when a message with `tag` is waiting; with wait = true, blocks.
  virtual bool probe(int tag, int* from, bool wait) = 0;
  virtual void send_int(long long value, int dest, int tag) = 0;
  virtual long long recv_int(int source, int tag) = 0;
  /// Ends every process of the job after `message` on stderr (an error during the distributed
  /// phase: no rank waits for a dead one).
  [[noreturn]] virtual void abort(const std::string& message, int exit_code) = 0;
};

}  // namespace cpkit::rate
