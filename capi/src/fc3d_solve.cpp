// cpkit_fc3d_solve and cpkit_fc3d_solve_batch: one contact ("auto", "nsgs") first on the
// allocation-free path (small_contact.hpp: the local solve from r = 0, or the closed form of a
// unique solution) when the verdict accepts its answer; otherwise the problem mapped into the library's FrictionContactProblem and solved
// by the registered friction solver (or, for one contact, by the closed form when the contact
// has exactly one solution). Every answer is decided by the friction verdict (finalize,
// core/friction_verdict.hpp; the fast path computes the same number and accepts only what
// finalize() would call solved).
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "c_boundary.hpp"
#include "finite_check.hpp"
#include "friction_input.hpp"
#include "small_contact.hpp"
#include "cpkit/core/errors.hpp"

namespace cpkit::capi {
namespace {

/// A thread's problem and result, reused from call to call; larger problems are not kept.
constexpr int kKeptContacts = 16;
struct FrictionWorkspace {
  FrictionContactProblem problem;
  SolveResult result;
};

FrictionWorkspace& workspace(int contacts, std::optional<FrictionWorkspace>& large) {
  thread_local FrictionWorkspace kept;
  return contacts <= kKeptContacts ? kept : large.emplace();
}

/// What a caller of a solve reports: the code, and for cpkit_info the iterations and the
/// unit-free verdict.
struct Outcome {
  int code = 0;
  int iterations = 0;
  double residual = 0;
};

/// The allocation-free path of one contact (small_contact.hpp) into r, u; false when the
/// general route must decide.
bool solve_fast(const OneContact& c, const double* q, double mu, const CommonOptions& o,
                double* r, double* u, Outcome& out) {
  Vec3 rc, uc;
  if (!solve_one_contact_fast(c, Eigen::Map<const Vec3>(q), mu, o.tol, rc, uc, out.residual))
    return false;
  for (int i = 0; i < 3; ++i) {
    r[i] = rc[i];
    u[i] = uc[i];
  }
  return true;
}

/// Solves ws.problem into r, u (3 contacts each); ws.result holds the decision (its message
/// explains a code != 0).
Outcome solve_one(const SolverEntry& entry, const CommonOptions& o, double* r, double* u,
                  FrictionWorkspace& ws) {
  const FrictionContactProblem& p = ws.problem;
  SolveResult& res = ws.result;
  if (!solve_one_contact_unique(p, entry, o, res)) res = entry.solve_fc(p, o);
  const Eigen::Index m = p.q.size();
  const bool full = res.z.size() == m && res.w.size() == m;
  for (Eigen::Index i = 0; i < m; ++i) {
    r[i] = full ? res.z[i] : NAN;
    u[i] = full ? res.w[i] : NAN;
  }
  Outcome out;
  out.code = fc_code(res.status);
  out.iterations = res.iterations;
  out.residual = res.residuals.natural;
  return out;
}

std::string outcome_message(const SolveResult& r) {
  return "cpkit: " + std::string(to_string(r.status)) + (r.message.empty() ? "" : ": " + r.message);
}

}  // namespace
}  // namespace cpkit::capi

using namespace cpkit;
using namespace cpkit::capi;

extern "C" int cpkit_fc3d_solve(int contacts, int nnz, const int* col_ptr, const int* row_index,
                                const double* values, const double* q, const double* mu,
                                const char* solver, const cpkit_options* options, double* r,
                                double* u, cpkit_info* info) {
  return guarded(info, [&](cpkit_info& out) {
    require(r, "r");
    require(u, "u");
    const CommonOptions o = common_options(options);
    const SolverEntry& entry = solver_entry(solver, ProblemKind::kFrictionContact);
    if (one_contact_route(contacts, entry)) {
      check_friction_input(contacts, nnz, col_ptr, row_index, values, q, mu);
      OneContact c;
      read_one_contact(col_ptr, row_index, values, c);
      Outcome fast;
      if (solve_fast(c, q, mu[0], o, r, u, fast)) {
        out.residual = fast.residual;
        return 0;
      }
    }
    std::optional<FrictionWorkspace> large;
    FrictionWorkspace& ws = workspace(contacts, large);
    map_friction_problem(contacts, nnz, col_ptr, row_index, values, q, mu, ws.problem);
    const Outcome one = solve_one(entry, o, r, u, ws);
    out.iterations = one.iterations;
    out.residual = one.residual;
    if (one.code != 0) set_message(out, outcome_message(ws.result));
    return one.code;
  });
}

extern "C" int cpkit_fc3d_solve_batch(int count, int contacts, const double* W, const double* q,
                                      const double* mu, const char* solver,
                                      const cpkit_options* options, double* r, double* u,
                                      int* status, cpkit_info* info) {
  return guarded(info, [&](cpkit_info& out) {
    if (count < 0) throw InputError("count must be >= 0, got " + std::to_string(count));
    check_positive(contacts, "contacts");
    if (contacts > 1024)
      throw InputError("contacts must be at most 1024 for the batched call (dense W), got " +
                       std::to_string(contacts));
    if (count == 0) return 0;
    require(W, "W");
    require(q, "q");
    require(mu, "mu");
    require(r, "r");
    require(u, "u");
    const CommonOptions o = common_options(options);
    const SolverEntry& entry = solver_entry(solver, ProblemKind::kFrictionContact);
    const long long m = 3LL * contacts, mm = m * m;
    // Every problem checked first: a NaN in problem 900 must not leave 899 answers written.
    for (int k = 0; k < count; ++k) {
      const double* mu_k = mu + static_cast<long long>(k) * contacts;
      if (all_finite(W + k * mm, mm) && all_finite(q + k * m, m) && valid_mu(mu_k, contacts))
        continue;
      const std::string which = " of problem " + std::to_string(k);
      check_finite(W + k * mm, mm, "W" + which);
      check_finite(q + k * m, m, "q" + which);
      check_mu(mu_k, contacts, "mu" + which);
    }
    std::optional<FrictionWorkspace> large;
    FrictionWorkspace& ws = workspace(contacts, large);
    int first = 0;
    const bool one_contact = one_contact_route(contacts, entry);
    for (int k = 0; k < count; ++k) {
      const double* mu_k = mu + static_cast<long long>(k) * contacts;
      Outcome one;
      OneContact c;
      if (one_contact) read_one_contact_dense(W + k * mm, c);
      if (!one_contact || !solve_fast(c, q + k * m, mu_k[0], o, r + k * m, u + k * m, one)) {
        map_dense_friction_problem(contacts, W + k * mm, q + k * m, mu_k, ws.problem);
        one = solve_one(entry, o, r + k * m, u + k * m, ws);
      }
      if (status != nullptr) status[k] = one.code;
      out.iterations += one.iterations;
      out.residual = std::max(out.residual, one.residual);
      if (one.code != 0 && first == 0) {
        first = one.code;
        set_message(out, "problem " + std::to_string(k) + ": " + outcome_message(ws.result));
      }
    }
    return first;
  });
}
