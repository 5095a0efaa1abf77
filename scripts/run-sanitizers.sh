#!/usr/bin/env bash
# The whole test suite built with AddressSanitizer + UndefinedBehaviorSanitizer (CI runs it after
# scripts/run-tests.sh), and the Python module's hostile-input tests against the module built so.
# Any sanitizer report fails the run: UBSan does not recover, ASan aborts.
# LeakSanitizer is off: Ipopt and MUMPS keep static allocations alive until exit.
# Build dir: ${CPKIT_SANITIZER_BUILD_DIR:-build-sanitize}.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup-deps.sh" --tests
build="${CPKIT_SANITIZER_BUILD_DIR:-$root/build-sanitize}"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# UBSan's alignment, null and pointer-overflow checks are off: they cost 38 % of the compile
# time of a test program (measured on test_system_step.cpp: 49 s of CPU with them, 30 s without;
# ASan alone 27 s), and what they look for is found otherwise here: ASan's SEGV handler reports a
# null dereference with its stack, and x86-64 has no alignment faults for the scalar and Eigen
# types this code reads (no packed structs, no type punning). Every other UBSan check stays on.
flags="-fsanitize=address,undefined -fno-sanitize=alignment,null,pointer-overflow -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
# -O1 -g1 (line tables), and no -DNDEBUG: assert() and Eigen's own checks (aliasing as in
# A = A + A.transpose(), sizes, indices) run here, where the release build compiles them out.
# -O1 -g1 compiles in half the time of RelWithDebInfo's -O2 -g (measured on system_step.cpp:
# 56 s against 113 s, objects of 19 MB against 73 MB) and keeps file:line in every report.
# With CPKIT_SANITIZE_PYTHON=1 the Python module is built instrumented too, and its hostile-input
# tests run here (the FCLIB reader and the sparse-matrix conversions under Python:
# python/CMakeLists.txt). Off by default, in CI too: its 21 pybind11 files cost minutes of
# the CI's 60 for two tests whose C++ paths (readers, sparse checks) the instrumented C++ suite
# runs anyway, and the Release suite runs the same Python tests for crashes. The uninstrumented
# /usr/bin/python3 loads it only with the sanitizer runtimes preloaded (they must come first);
# the tests' child interpreters inherit LD_PRELOAD and ASAN_OPTIONS, so a report there kills the
# child and fails its test. The module is linked with the runtimes too, so that loading it
# without them fails with ASan's own message rather than an undefined symbol.
preload=""
for lib in libasan.so libubsan.so; do
  path=$("${CXX:-c++}" -print-file-name="$lib")
  [[ -f "$path" ]] || { echo "run-sanitizers.sh: ${CXX:-c++} does not find $lib (install libasan/libubsan)" >&2; exit 1; }
  preload+="${preload:+ }$path"
done
python=(-DCPKIT_BUILD_PYTHON=OFF)
if [[ "${CPKIT_SANITIZE_PYTHON:-0}" == 1 ]]; then
  python=(-DCPKIT_BUILD_PYTHON=ON "-DCPKIT_PYTHON_PRELOAD=$preload")
fi
# CI has 60 minutes on 2 cores for both builds and both suites, and code runs 15-20x slower
# here than in Release. So CI's instrumented run leaves out the test programs below, each for a
# reason; all of them run in the Release suite, and CPKIT_SANITIZE_ALL=1 runs them here too:
#  - apps.test_docs_check runs every documented command (minutes here); the command-line paths it
#    walks are walked instrumented by the apps.test_cli_* programs;
#  - apps.test_cli_map_resume interrupts and resumes maps (minutes here); the checkpoint reader and
#    the chunked run are instrumented in rate_problem.test_map_run / test_map_streaming and in
#    the fuzz harness of the map chunks;
#  - apps.test_cli_map_mpi needs an MPI build, which this one is not.
#  - apps.test_cli_map_time_limit times small maps against the map's time estimate (within 2x) and
#    stops runs by the clock: a judgement of timings, which instrumented code under a parallel
#    suite makes marginal (its estimate case failed 3 of 7 instrumented runs at load 5). The
#    estimate's code runs instrumented in apps.test_cli_map and apps.test_cli_hostile (the
#    refused 10^11-cell maps); the test runs in Release.
# The seeded random families run a shorter prefix of the same seeds here (tests/test_budget.hpp).
left_out="apps.test_docs_check;apps.test_cli_map_resume;apps.test_cli_map_mpi;apps.test_cli_map_time_limit"
[[ "${CPKIT_SANITIZE_ALL:-0}" == 1 ]] && left_out="apps.test_cli_map_mpi"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCPKIT_BUILD_BENCH=OFF \
  "${python[@]}" "-DCPKIT_TESTS_LEFT_OUT=$left_out" \
  "-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1" \
  "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined" \
  "-DCMAKE_MODULE_LINKER_FLAGS=-fsanitize=address,undefined" \
  "${launcher[@]}" "$@" >/dev/null
t0=$SECONDS
cmake --build "$build" -j "$(nproc)"
echo "run-sanitizers.sh: the instrumented build took $((SECONDS - t0)) s"
cd "$build"
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# docs/simulation.md's flat-punch fretting run (55 s of CPU in Release, 4^7 active sets per step)
# would take a quarter of an hour here; its code runs under the sanitizers in
# rate_problem.test_system_simulation, and the Release suite runs the example itself.
export CPKIT_DOCS_CHECK_SKIP="flat_punch_fretting.json"
# The consumer test installs and rebuilds the package without sanitizers: run in the main suite.
t0=$SECONDS
# The documentation's C++ snippets are compiled (docs.snippets_build: minutes of instrumented
# compiling) and run in the Release suite; the library calls they make run instrumented in the
# unit tests. Without the module here, python.* is the Release suite's.
exclude='^install\.|^docs\.snippet'
[[ "${CPKIT_SANITIZE_ALL:-0}" == 1 ]] && exclude='^install\.'
[[ "${CPKIT_SANITIZE_PYTHON:-0}" == 1 ]] || exclude+='|^python\.'
ctest --output-on-failure -j "$(nproc)" --timeout 1200 -E "$exclude"
echo "run-sanitizers.sh: the instrumented suite took $((SECONDS - t0)) s"
