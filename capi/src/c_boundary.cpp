// The shared parts of the C API: messages, codes, options, the solver lookup, and the small
// functions of cpkit.h (defaults, cpkit_free, the version).
#include "c_boundary.hpp"

#include <cmath>
#include <cstdlib>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/number_text.hpp"
#include "cpkit/lcp/friction/fc_request.hpp"
#include "cpkit/lcp/lcp_request.hpp"
#include "cpkit/lcp/solvers.hpp"

namespace cpkit::capi {

void set_message(cpkit_info& info, std::string_view text) noexcept {
  const std::size_t n = std::min(text.size(), sizeof info.message - 1);
  std::memcpy(info.message, text.data(), n);
  info.message[n] = '\0';
}

int lcp_code(Status s) noexcept { return is_solution(s) ? 0 : 1; }

int fc_code(Status s) noexcept {
  if (is_solution(s)) return 0;
  return s == Status::kInfeasible ? 1 : 5;
}

CommonOptions common_options(const cpkit_options* options) {
  CommonOptions o;
  if (options == nullptr) return o;
  // The checks and words of the command line's --tol, --max-iter, --time-limit.
  if (!(options->tol > 0 && options->tol <= 1e-3))
    throw InputError("options->tol must be in (0, 1e-3], got " + num_text(options->tol));
  if (options->max_iter < 0)
    throw InputError("options->max_iter must be >= 0 (0: the solver's default), got " +
                     std::to_string(options->max_iter));
  if (!(options->time_limit >= 0) || std::isinf(options->time_limit))
    throw InputError("options->time_limit must be a finite number of seconds >= 0 (0: none), got " +
                     num_text(options->time_limit));
  o.tol = options->tol;
  o.tol_acceptable = std::max(o.tol_acceptable, o.tol);
  o.max_iterations = options->max_iter;
  if (options->time_limit > 0) o.time_limit_s = options->time_limit;
  return o;
}

namespace {

/// One thread's last lookup: a later call with the same name skips the registry's search.
struct CachedEntry {
  char name[32] = {};
  ProblemKind kind = ProblemKind::kLcp;
  const SolverEntry* entry = nullptr;
};

}  // namespace

/// The registry's entry `name` when it accepts `kind`, else nullptr.
const SolverEntry* find_entry(const char* name, ProblemKind kind) {
  const SolverEntry* e = lcp::solvers().find(name);
  return e != nullptr && e->accepts(kind) ? e : nullptr;
}

/// The entries of the per-call paths ("auto" and "lemke" for LCPs, "auto" and "nsgs" for
/// friction), looked up once per process: the registry's entries never move, and a function's
/// static costs no thread-local access (a shared library's thread_local does).
const SolverEntry* usual_entry(const char* name, ProblemKind kind) {
  static const SolverEntry* const lcp_auto = find_entry("auto", ProblemKind::kLcp);
  static const SolverEntry* const lcp_lemke = find_entry("lemke", ProblemKind::kLcp);
  static const SolverEntry* const fc_auto = find_entry("auto", ProblemKind::kFrictionContact);
  static const SolverEntry* const fc_nsgs = find_entry("nsgs", ProblemKind::kFrictionContact);
  const bool lcp = kind == ProblemKind::kLcp;
  if (std::strcmp(name, "auto") == 0) return lcp ? lcp_auto : fc_auto;
  if (lcp && std::strcmp(name, "lemke") == 0) return lcp_lemke;
  if (kind == ProblemKind::kFrictionContact && std::strcmp(name, "nsgs") == 0) return fc_nsgs;
  return nullptr;
}

const SolverEntry& solver_entry(const char* name, ProblemKind kind) {
  if (name == nullptr) name = "auto";
  if (const SolverEntry* usual = usual_entry(name, kind)) return *usual;
  thread_local CachedEntry cache[2];  // one per kind asked here (LCP, friction)
  CachedEntry& c = cache[kind == ProblemKind::kLcp ? 0 : 1];
  if (c.entry != nullptr && c.kind == kind && std::strcmp(c.name, name) == 0) return *c.entry;
  const SolverEntry* e = find_entry(name, kind);
  if (e == nullptr) {
    const bool lcp = kind == ProblemKind::kLcp;
    throw InputError(std::string("unknown ") + (lcp ? "LCP" : "friction") + " solver '" + name +
                     "' (valid: " +
                     (lcp ? lcp::lcp_solver_list() : lcp::friction::fc_solver_list()) + ")");
  }
  if (std::strlen(name) < sizeof c.name) {
    std::strcpy(c.name, name);
    c.kind = kind;
    c.entry = e;
  }
  return *e;
}

void require(const void* pointer, const char* what) {
  if (pointer == nullptr) throw InputError(std::string(what) + " is NULL");
}

}  // namespace cpkit::capi

extern "C" {

void cpkit_default_options(cpkit_options* options) {
  if (options == nullptr) return;
  options->tol = cpkit::CommonOptions{}.tol;
  options->max_iter = 0;
  options->time_limit = 0;
}

void cpkit_free(void* p) { std::free(p); }

const char* cpkit_version(void) { return CPKIT_VERSION; }

}  // extern "C"
