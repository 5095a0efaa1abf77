#pragma once
// The C boundary (include/cpkit/cpkit.h): every entry point runs its body through guarded(),
// which catches everything, so that no C++ exception crosses into C or Fortran, and fills the
// caller's cpkit_info (or a local one when the caller passed NULL). Nothing here prints.
#include <cstring>
#include <optional>
#include <string>
#include <string_view>

#include "cpkit/core/options.hpp"
#include "cpkit/core/registry.hpp"
#include "cpkit/core/status.hpp"
#include "cpkit/cpkit.h"
#include "call_clock.hpp"

namespace cpkit::capi {

/// Copies `text` into info.message (truncated to 511 characters, always NUL-terminated).
void set_message(cpkit_info& info, std::string_view text) noexcept;

/// The C API's code of a solve's status (the command line's): LCP solve, 0 a verified solution,
/// else 1 (as `cpkit lcp solve`); friction, 0 a verified solution, 1 proved none, else 5 (as
/// `cpkit fc solve`).
int lcp_code(Status s) noexcept;
int fc_code(Status s) noexcept;

/// CommonOptions from the C options (NULL: defaults); InputError naming a bad field.
CommonOptions common_options(const cpkit_options* options);

/// The registered solver `name` (NULL: "auto") that accepts `kind`, looked up once per thread
/// and name (the name is compared, not parsed, on later calls); InputError when unknown, the
/// message listing the valid names.
const SolverEntry& solver_entry(const char* name, ProblemKind kind);

/// Throws InputError(what) when `pointer` is NULL.
void require(const void* pointer, const char* what);

/// Runs body(info) -> int code with every exception caught: InputError and any other exception
/// give status 2 with "cpkit: bad input: ..." or "cpkit: error: ..."; fills status and seconds
/// (the wall time of the call, measured only when the caller passed an info).
template <class Body>
int guarded(cpkit_info* caller_info, Body&& body) noexcept {
  cpkit_info local;
  cpkit_info& info = caller_info != nullptr ? *caller_info : local;
  // The clock is read only when the caller wants info (call_clock.hpp: a cheap read).
  const bool timed = caller_info != nullptr;
  std::optional<CallClock> clock;
  if (timed) clock.emplace();
  info.status = 0;
  info.iterations = 0;
  info.residual = 0;
  info.seconds = 0;
  info.message[0] = '\0';
  int code = 2;
  try {
    code = body(info);
  } catch (const std::invalid_argument& e) {  // InputError and the library's argument checks
    set_message(info, std::string("cpkit: bad input: ") + e.what());
  } catch (const std::bad_alloc&) {
    set_message(info, "cpkit: bad input: out of memory (the problem is too large)");
  } catch (const std::exception& e) {
    set_message(info, std::string("cpkit: error: ") + e.what());
  } catch (...) {
    set_message(info, "cpkit: error: unknown exception");
  }
  info.status = code;
  if (timed)
    info.seconds = clock->seconds();
  return code;
}

}  // namespace cpkit::capi
