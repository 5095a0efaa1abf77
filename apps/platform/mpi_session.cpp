// MPI for `cpkit map` (mpi_session.hpp): the few calls cpkit needs, or their one-process stand-ins.
#include "mpi_session.hpp"

#include <cstdlib>
#include <iostream>
#include <stdexcept>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/map_transport.hpp"

#ifdef CPKIT_WITH_MPI
#include <mpi.h>
// Every call goes through the profiling names PMPI_*: Ipopt's sequential MUMPS (libdmumps_seq)
// exports stub MPI_Init, MPI_Comm_rank, MPI_Finalize that would otherwise shadow Open MPI's
// (every rank would be rank 0). Open MPI defines PMPI_* for every MPI_* function.
#endif

namespace cpkit::cli::mpi {

namespace {
bool g_active = false;
int g_rank = 0, g_size = 1;

int env_int(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : 0;
}

/// Started by an MPI launcher (the variables every launcher sets for its processes).
bool launched() noexcept {
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_RANK") || std::getenv("PMIX_RANK");
}
}  // namespace

bool built_with_mpi() noexcept {
#ifdef CPKIT_WITH_MPI
  return true;
#else
  return false;
#endif
}

int launched_size() noexcept {
  // Open MPI's mpirun, MPICH's mpiexec (PMI), Slurm's srun with PMIx (the task count).
  if (const int n = env_int("OMPI_COMM_WORLD_SIZE"); n >= 1) return n;
  if (const int n = env_int("PMI_SIZE"); n >= 1) return n;
  if (std::getenv("PMIX_RANK"))
    if (const int n = env_int("SLURM_NTASKS"); n >= 1) return n;
  return 1;
}

void init(int* argc, char*** argv) {
  (void)argc;
  (void)argv;
  if (!launched()) return;
#ifdef CPKIT_WITH_MPI
  int provided = 0;
  // Only the main thread calls MPI; worker threads compute cells.
  PMPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  PMPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  PMPI_Comm_size(MPI_COMM_WORLD, &g_size);
  g_active = true;
#else
  if (launched_size() > 1)
    throw InputError("cpkit was started by mpirun with " + std::to_string(launched_size()) +
                     " processes but built without MPI (CMake option CPKIT_WITH_MPI=OFF): every "
                     "process would compute the whole map. Rebuild with -DCPKIT_WITH_MPI=ON "
                     "(Debian: libopenmpi-dev) or run without mpirun");
#endif
}

void finalize() noexcept {
#ifdef CPKIT_WITH_MPI
  if (g_active) PMPI_Finalize();
#endif
  g_active = false;
}

bool active() noexcept { return g_active; }
int rank() noexcept { return g_rank; }
int size() noexcept { return g_size; }

void abort(int exit_code) noexcept {
  std::cerr.flush();
#ifdef CPKIT_WITH_MPI
  if (g_active) PMPI_Abort(MPI_COMM_WORLD, exit_code);
#endif
  std::_Exit(exit_code);
}

#ifdef CPKIT_WITH_MPI
void send_bytes(const std::string& bytes, int dest, int tag) {
  PMPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, dest, tag, MPI_COMM_WORLD);
}

std::string recv_bytes(int tag, int* from) {
  MPI_Status st;
  PMPI_Probe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &st);
  int n = 0;
  PMPI_Get_count(&st, MPI_BYTE, &n);
  std::string bytes(static_cast<std::size_t>(n), '\0');
  PMPI_Recv(bytes.data(), n, MPI_BYTE, st.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  if (from) *from = st.MPI_SOURCE;
  return bytes;
}

bool probe(int tag, int* from, bool wait) {
  MPI_Status st;
  int flag = 1;
  if (wait)
    PMPI_Probe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &st);
  else
    PMPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &flag, &st);
  if (flag && from) *from = st.MPI_SOURCE;
  return flag != 0;
}

void send_int(long long value, int dest, int tag) {
  PMPI_Send(&value, 1, MPI_LONG_LONG, dest, tag, MPI_COMM_WORLD);
}

long long recv_int(int source, int tag) {
  long long v = 0;
  PMPI_Recv(&v, 1, MPI_LONG_LONG, source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return v;
}

std::vector<long long> all_gather(long long value) {
  std::vector<long long> all(static_cast<std::size_t>(g_size));
  PMPI_Allgather(&value, 1, MPI_LONG_LONG, all.data(), 1, MPI_LONG_LONG, MPI_COMM_WORLD);
  return all;
}
#else
// Without MPI there is one process and nobody to talk to: reaching these is a bug.
void send_bytes(const std::string&, int, int) { throw std::logic_error("mpi::send_bytes without MPI"); }
std::string recv_bytes(int, int*) { throw std::logic_error("mpi::recv_bytes without MPI"); }
bool probe(int, int*, bool) { return false; }
void send_int(long long, int, int) { throw std::logic_error("mpi::send_int without MPI"); }
long long recv_int(int, int) { throw std::logic_error("mpi::recv_int without MPI"); }
std::vector<long long> all_gather(long long value) { return {value}; }
#endif

namespace {
/// The map run's transport (map_transport.hpp) over the calls above.
class MpiMapTransport final : public rate::MapTransport {
 public:
  int rank() const override { return mpi::rank(); }
  int size() const override { return mpi::size(); }
  void send_bytes(const std::string& b, int dest, int tag) override { mpi::send_bytes(b, dest, tag); }
  std::string recv_bytes(int tag, int* from) override { return mpi::recv_bytes(tag, from); }
  bool probe(int tag, int* from, bool wait) override { return mpi::probe(tag, from, wait); }
  void send_int(long long v, int dest, int tag) override { mpi::send_int(v, dest, tag); }
  long long recv_int(int source, int tag) override { return mpi::recv_int(source, tag); }
  [[noreturn]] void abort(const std::string& message, int exit_code) override {
    std::cerr.clear();  // ranks other than 0 are silenced (main.cpp): this message must show
    std::cerr << message << "\n";
    mpi::abort(exit_code);
  }
};
}  // namespace

rate::MapTransport* map_transport() {
  static MpiMapTransport transport;
  return active() ? &transport : nullptr;
}

}  // namespace cpkit::cli::mpi
