// "auto" for frictional contact problems (auto.hpp).
#include "cpkit/lcp/friction/auto.hpp"

#include <algorithm>
#include <limits>

#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/friction/fb_soc.hpp"
#include "cpkit/lcp/friction/nsgs.hpp"
#include "cpkit/lcp/friction/prox.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "friction_common.hpp"

namespace cpkit::lcp::friction {

std::vector<std::string> auto_chain_names() {
  return {"fb-soc", "nsgs", "prox", "lemke-faceted", "lemke", "ipopt-fc", "ipopt"};
}

namespace {

constexpr int kPolishSweeps = 20;

// Ranks answers: kSolved, then kSolvedInaccurate, then the smallest finite residual.
bool better(const SolveResult& a, const SolveResult& b) {
  auto rank = [](const SolveResult& r) {
    return r.status == Status::kSolved ? 0 : r.status == Status::kSolvedInaccurate ? 1 : 2;
  };
  if (rank(a) != rank(b)) return rank(a) < rank(b);
  const double ra = a.z.size() ? a.residuals.natural : std::numeric_limits<double>::infinity();
  const double rb = b.z.size() ? b.residuals.natural : std::numeric_limits<double>::infinity();
  return ra < rb;
}

}  // namespace

SolveResult solve_auto(const FrictionContactProblem& p, const CommonOptions& o) {
  const Stopwatch clock;
  detail::check_input(p, o, Eigen::VectorXd());
  SolveResult best;
  best.solver = "auto";
  std::vector<Attempt> attempts;
  bool have = false;
  auto left = [&] { return o.time_limit_s - clock.seconds(); };
  auto record = [&](const std::string& name, SolveResult r) {
    attempts.push_back({name, r.status, r.residuals.natural, r.seconds, r.message});
    if (!have || better(r, best)) {
      best = std::move(r);
      best.solver = name;
      have = true;
    }
  };
  bool prox_ran = false;
  auto warm = [&]() { return have && best.z.size() == p.q.size() ? best.z : Eigen::VectorXd(); };
  auto common = [&]() {
    CommonOptions c = o;
    c.time_limit_s = left();
    return c;
  };
  for (const std::string& name : auto_chain_names()) {
    if (have && best.status == Status::kSolved) break;
    const SolverEntry* e = lcp::solvers().find(name);
    if (e == nullptr || !e->solve_fc) {
      // lemke / ipopt entries without solve_fc are expected when their friction versions are
      // registered under the other name: recorded all the same.
      attempts.push_back({name, Status::kNotRun, 0, 0,
                          e ? "skipped: does not accept friction problems"
                            : "skipped: not registered"});
      continue;
    }
    if (!(left() > 0)) {
      attempts.push_back({name, Status::kTimeLimit, 0, 0, "skipped: time limit reached"});
      continue;
    }
    if (name == "nsgs") {
      NsgsOptions no;
      no.common = common();
      no.r0 = warm();
      record(name, solve_nsgs(p, no));
      if (best.status != Status::kSolved && best.solver == "nsgs" && left() > 0) {
        FbSocOptions fo;  // Newton from the Gauss-Seidel iterate
        fo.common = common();
        fo.r0 = warm();
        record("fb-soc", solve_fb_soc(p, fo));
      }
      continue;
    }
    if (name == "prox" && prox_ran) continue;
    if (name == "fb-soc") {
      SolveResult first = e->solve_fc(p, common());
      // Stopped by itself (stagnation; kSolvedInaccurate when the stalled iterate passed only
      // tol_acceptable), not by an iteration or time limit.
      const bool stalled =
          first.status == Status::kStalled || first.status == Status::kSolvedInaccurate;
      record(name, std::move(first));
      // Newton stalls at the non-isolated solutions of a rank-deficient W; the proximal term
      // (W + alpha I) removes exactly that, so prox goes next, from fb-soc's best iterate
      // (Capsules-i125-1213: solved in 5 outer iterations; nsgs had not after 2000 sweeps).
      if (stalled && best.status != Status::kSolved && left() > 0) {
        ProxOptions po;
        po.common = common();
        po.r0 = warm();
        record("prox", solve_prox(p, po));
        prox_ran = true;
      }
      if (best.status != Status::kSolved && left() > 0) {
        FbSocOptions fo;  // the other line search (fb_soc.hpp), from r = 0 again
        fo.common = common();
        fo.nonmonotone_memory = 1;
        SolveResult r = solve_fb_soc(p, fo);
        r.message = "monotone line search" + (r.message.empty() ? "" : "; " + r.message);
        record(name, std::move(r));
      }
      continue;
    }
    record(name, e->solve_fc(p, common()));
  }
  // An answer accepted only just (above tol / 10): a few Gauss-Seidel sweeps from it, kept when
  // they do better. FrictionContact3D_RR_1c at tol 1e-8: fb-soc stops at 3.8e-9 (1.1e-7 by
  // Siconos' |q| measure); nsgs from there reaches rounding.
  if (have && best.status == Status::kSolved && best.residuals.natural > 0.1 * o.tol &&
      left() > 0) {
    NsgsOptions no;
    no.common = common();
    no.common.max_iterations = kPolishSweeps;
    no.common.tol = 1e-2 * o.tol;  // aims lower than the answer it starts from
    no.common.tol_acceptable = std::max(no.common.tol, o.tol_acceptable);
    no.r0 = best.z;
    SolveResult r = finalize(p, solve_nsgs(p, no), o);  // judged at the caller's tol
    r.message = "polish from " + best.solver + (r.message.empty() ? "" : "; " + r.message);
    if (r.status == Status::kSolved && r.residuals.natural < best.residuals.natural) {
      record("nsgs", std::move(r));
    } else {
      attempts.push_back({"nsgs", r.status, r.residuals.natural, r.seconds,
                          r.message + "; not better, not kept"});
    }
  }
  best.attempts = std::move(attempts);
  if (!have) {
    best.status = Status::kNotRun;
    best.message = "auto: no friction solver ran";
    best.seconds = clock.seconds();
    return best;
  }
  const std::string solver = best.solver;
  best = finalize(p, std::move(best), o);
  best.solver = solver;
  best.seconds = clock.seconds();
  return best;
}

}  // namespace cpkit::lcp::friction
