// Reading a local friction problem file (FCLIB HDF5 or Siconos .dat; core/friction_io.hpp) into
// the caller's arrays or into arrays cpkit allocates (released by cpkit_fc3d_problem_free).
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>

#include "c_boundary.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_io.hpp"

namespace cpkit::capi {
namespace {

/// The file's problem with W compressed by columns (int indices, 0-based).
FrictionContactProblem read(const char* path) {
  require(path, "path");
  FrictionContactProblem p = read_friction_problem(path);  // validates; names the file
  p.W.makeCompressed();
  return p;
}

/// Copies the problem into arrays of its sizes.
void copy_out(const FrictionContactProblem& p, int* col_ptr, int* row_index, double* values,
              double* q, double* mu) {
  const Eigen::Index m = p.W.cols(), nnz = p.W.nonZeros();
  std::copy(p.W.outerIndexPtr(), p.W.outerIndexPtr() + m + 1, col_ptr);
  std::copy(p.W.innerIndexPtr(), p.W.innerIndexPtr() + nnz, row_index);
  std::copy(p.W.valuePtr(), p.W.valuePtr() + nnz, values);
  std::copy(p.q.data(), p.q.data() + p.q.size(), q);
  std::copy(p.mu.data(), p.mu.data() + p.mu.size(), mu);
}

/// malloc of n > 0 elements (at least one, so that a NULL result always means failure).
template <class T>
T* allocate(Eigen::Index n) {
  void* p = std::malloc(sizeof(T) * static_cast<std::size_t>(std::max<Eigen::Index>(n, 1)));
  if (p == nullptr) throw std::bad_alloc();
  return static_cast<T*>(p);
}

}  // namespace
}  // namespace cpkit::capi

using namespace cpkit;
using namespace cpkit::capi;

extern "C" void cpkit_fc3d_problem_free(cpkit_fc3d_problem* problem) {
  if (problem == nullptr) return;
  std::free(problem->col_ptr);
  std::free(problem->row_index);
  std::free(problem->values);
  std::free(problem->q);
  std::free(problem->mu);
  std::memset(problem, 0, sizeof *problem);
}

extern "C" int cpkit_fc3d_read(const char* path, cpkit_fc3d_problem* problem, cpkit_info* info) {
  if (problem != nullptr) std::memset(problem, 0, sizeof *problem);
  return guarded(info, [&](cpkit_info&) {
    require(problem, "problem");
    const FrictionContactProblem p = read(path);
    cpkit_fc3d_problem out{};
    try {
      out.col_ptr = allocate<int>(p.W.cols() + 1);
      out.row_index = allocate<int>(p.W.nonZeros());
      out.values = allocate<double>(p.W.nonZeros());
      out.q = allocate<double>(p.q.size());
      out.mu = allocate<double>(p.mu.size());
    } catch (...) {
      cpkit_fc3d_problem_free(&out);
      throw;
    }
    out.contacts = static_cast<int>(p.contacts());
    out.nnz = static_cast<int>(p.W.nonZeros());
    copy_out(p, out.col_ptr, out.row_index, out.values, out.q, out.mu);
    *problem = out;
    return 0;
  });
}

extern "C" int cpkit_fc3d_read_sizes(const char* path, int* contacts, int* nnz, cpkit_info* info) {
  return guarded(info, [&](cpkit_info&) {
    require(contacts, "contacts");
    require(nnz, "nnz");
    const FrictionContactProblem p = read(path);
    *contacts = static_cast<int>(p.contacts());
    *nnz = static_cast<int>(p.W.nonZeros());
    return 0;
  });
}

extern "C" int cpkit_fc3d_read_into(const char* path, int contacts, int nnz, int* col_ptr,
                                    int* row_index, double* values, double* q, double* mu,
                                    cpkit_info* info) {
  return guarded(info, [&](cpkit_info&) {
    require(col_ptr, "col_ptr");
    require(q, "q");
    require(mu, "mu");
    const FrictionContactProblem p = read(path);
    if (p.contacts() != contacts || p.W.nonZeros() != nnz)
      throw InputError(std::string(path) + " has " + std::to_string(p.contacts()) +
                       (p.contacts() == 1 ? " contact and " : " contacts and ") +
                       std::to_string(p.W.nonZeros()) +
                       " stored entries of W, the arrays given are for " +
                       std::to_string(contacts) + " and " + std::to_string(nnz) +
                       " (cpkit_fc3d_read_sizes gives them)");
    if (nnz > 0) {
      require(row_index, "row_index");
      require(values, "values");
    }
    copy_out(p, col_ptr, row_index, values, q, mu);
    return 0;
  });
}
