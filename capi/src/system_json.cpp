// cpkit_system_rate and cpkit_system_step: a contact system's rate problem and incremental step
// from the text of a system file, through the library's requests (rate_request.hpp,
// step_request.hpp) as `cpkit rate --system FILE --json` and `cpkit step --system FILE --all
// --json` run them; the answer is the JSON those commands print.
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "c_boundary.hpp"
#include "finite_check.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/requests/rate_request.hpp"
#include "cpkit/rate_problem/report/json.hpp"
#include "cpkit/rate_problem/requests/step_request.hpp"
#include "cpkit/rate_problem/system/system_file.hpp"

namespace cpkit::capi {
namespace {

rate::SystemFile system_file(const char* system_json) {
  require(system_json, "system_json");
  return rate::parse_system_file(system_json, "system_json");
}

std::vector<double> load(int n_dF, const double* dF) {
  if (n_dF < 0) throw InputError("n_dF must be >= 0, got " + std::to_string(n_dF));
  if (n_dF > 0) {
    require(dF, "dF");
    check_finite(dF, n_dF, "dF");
  }
  return n_dF > 0 ? std::vector<double>(dF, dF + n_dF) : std::vector<double>{};
}

/// `json` dumped into memory the caller releases with cpkit_free.
char* c_text(const nlohmann::json& json) {
  const std::string text = json.dump(1);
  char* out = static_cast<char*>(std::malloc(text.size() + 1));
  if (out == nullptr) throw std::bad_alloc();
  std::memcpy(out, text.c_str(), text.size() + 1);
  return out;
}

/// The lines a command prints on stderr after its answer, as the message.
void notes_message(cpkit_info& info, const std::vector<std::string>& notes) {
  std::string text;
  for (const auto& n : notes) text += (text.empty() ? "cpkit: " : "; ") + n;
  set_message(info, text);
}

}  // namespace
}  // namespace cpkit::capi

using namespace cpkit;
using namespace cpkit::capi;

extern "C" int cpkit_system_rate(const char* system_json, int n_dF, const double* dF,
                                 const char* method, int facets, char** solution_json,
                                 cpkit_info* info) {
  if (solution_json != nullptr) *solution_json = nullptr;
  return guarded(info, [&](cpkit_info& out) {
    require(solution_json, "solution_json");
    rate::RateRequest request;
    request.system = "system_json";
    request.file = system_file(system_json);
    request.dF = load(n_dF, dF);
    if (method != nullptr) request.method = method;
    request.facets = facets;
    const rate::RateOutcome outcome = rate::run_rate_request(request);
    notes_message(out, outcome.notes);
    *solution_json = c_text(rate::rate_outcome_json(outcome, CPKIT_VERSION));
    return static_cast<int>(outcome.exit_code);
  });
}

extern "C" int cpkit_system_step(const char* system_json, int n_dF, const double* dF,
                                 char** solution_json, cpkit_info* info) {
  if (solution_json != nullptr) *solution_json = nullptr;
  return guarded(info, [&](cpkit_info& out) {
    require(solution_json, "solution_json");
    rate::StepRequest request;
    request.system = "system_json";
    request.file = system_file(system_json);
    request.DF = load(n_dF, dF);
    // Every solution where a complete enumeration exists (2-D systems, one 3-D point); N coupled
    // 3-D points have none: their default chain (fb-soc) answers.
    const nlohmann::json& points = request.file->document.value("points", nlohmann::json());
    request.all = request.file->dim == 2 || (points.is_array() && points.size() == 1);
    const rate::StepOutcome outcome = rate::run_step_request(request);
    notes_message(out, outcome.errors);
    *solution_json = c_text(rate::step_outcome_json(outcome, CPKIT_VERSION));
    return static_cast<int>(outcome.exit_code);
  });
}
