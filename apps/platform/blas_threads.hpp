#pragma once
// The BLAS thread pool of the `cpkit` process. Debian's OpenBLAS (the LAPACK of fb-newton's
// dense LU, and the BLAS of Ipopt's MUMPS) starts one thread per core, and its idle threads
// spin (sched_yield) waiting for work: on the 2-core machines shared by several jobs this made
// `cpkit lcp solve --solver fb-newton` at n = 400 two to five times slower (docs/benchmarks.md).
// cpkit's dense systems are small enough for one thread, so the program asks for one, unless
// the user chose a number with OPENBLAS_NUM_THREADS. The library itself leaves the pool alone.
#include <dlfcn.h>

#include <cstdlib>

namespace cpkit::cli {

inline void use_one_blas_thread() {
  if (std::getenv("OPENBLAS_NUM_THREADS") != nullptr) return;
  using SetThreads = void (*)(int);
  // present only when the BLAS in use is OpenBLAS
  if (auto* set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
    set(1);
}

}  // namespace cpkit::cli
