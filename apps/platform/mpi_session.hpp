#pragma once
// MPI for `cpkit map` (docs/cluster.md). MPI is used only when cpkit was built with
// CPKIT_WITH_MPI and started by mpirun (its environment says so): otherwise cpkit is one
// process, rank 0 of 1, and never touches MPI (no start-up cost, no MPI library needed).
#include <string>
#include <vector>

namespace cpkit::rate {
class MapTransport;
}

namespace cpkit::cli::mpi {

/// True when this cpkit was built with MPI (CMake option CPKIT_WITH_MPI).
bool built_with_mpi() noexcept;
/// The number of processes mpirun (or srun) started, read from the environment; 1 otherwise.
int launched_size() noexcept;

/// Initialises MPI when built with it and launched_size() > 1 (or mpirun -np 1). Throws
/// InputError when started by mpirun with several ranks but built without MPI (every rank
/// would run the whole map).
void init(int* argc, char*** argv);
/// Finalises MPI if init() started it.
void finalize() noexcept;
bool active() noexcept;
int rank() noexcept;
int size() noexcept;
/// Ends every rank of the job (after a message on stderr): MPI_Abort, or exit without MPI.
[[noreturn]] void abort(int exit_code) noexcept;

/// Point-to-point messages (active() only). Tags are small non-negative integers.
void send_bytes(const std::string& bytes, int dest, int tag);
/// Waits for a message with `tag` from any rank; returns its bytes and sets *from.
std::string recv_bytes(int tag, int* from);
/// True (and *from set) when a message with `tag` is waiting; with wait = true, blocks until one.
bool probe(int tag, int* from, bool wait);
void send_int(long long value, int dest, int tag);
long long recv_int(int source, int tag);
/// Every rank's value, on every rank.
std::vector<long long> all_gather(long long value);

/// The transport a map run uses (cpkit/rate_problem/maps/map_run.hpp) when MPI is active; null
/// otherwise (one process).
rate::MapTransport* map_transport();

}  // namespace cpkit::cli::mpi
