// "auto" for frictional contact problems (auto.hpp).
#include "cpkit/lcp/friction/auto.hpp"

#include <algorithm>
#include <cmath>
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
  return {"nsgs", "prox", "fb-soc", "lemke-faceted", "lemke", "ipopt-fc", "ipopt"};
}

namespace {

constexpr int kPolishSweeps = 20;
constexpr int kFirstSweeps = 50;

// nsgs in runs of 50, 50, 100, 200, ... sweeps, each from the last one's answer, for as long as
// the rate of the last run (its residual decrease per sweep) predicts tol within nsgs' sweep
// budget (options.max_iterations, else nsgs' 2000). A stalling nsgs is so stopped after a few
// hundred sweeps, however long it would run (Capsules-i100-889: it stalls near 1e-4 after ~200
// sweeps), while one that converges slowly but steadily goes on (KaplasTower: 1,100 sweeps).
SolveResult nsgs_stage(const FrictionContactProblem& p, const CommonOptions& o,
                       const Stopwatch& clock) {
  const int budget = o.max_iterations > 0 ? o.max_iterations : 2000;
  const double start = clock.seconds();
  SolveResult out;
  Eigen::VectorXd r0;
  int done = 0, runs = 0, chunk = std::min(kFirstSweeps, budget);
  double e_last = 0, predicted_last = HUGE_VAL;
  int s_last = 0;
  std::string why;
  for (;;) {
    // The time left, taken once (read twice it could pass 0 in between, and a solver refuses a
    // time limit <= 0 as bad input).
    const double left = o.time_limit_s - clock.seconds();
    if (!(left > 0)) {
      if (runs == 0) out.status = Status::kTimeLimit;
      break;
    }
    NsgsOptions no;
    no.common = o;
    no.common.max_iterations = chunk;
    no.common.time_limit_s = left;
    no.r0 = r0;
    out = solve_nsgs(p, no);  // its z is never worse than its start r0
    done += out.iterations;
    ++runs;
    if (out.z.size() == p.q.size()) r0 = out.z;
    const double e = out.residuals.natural;
    if (out.status == Status::kSolved || out.status == Status::kTimeLimit || done >= budget ||
        !(o.time_limit_s - clock.seconds() > 0))
      break;
    if (runs >= 2) {
      const double rate = e < e_last ? std::log(e_last / e) / (done - s_last) : 0;
      const double predicted = rate > 0 ? done + std::log(e / o.tol) / rate : HUGE_VAL;
      if (!(predicted <= budget)) {
        why = "; stopped: its rate predicts tol after " +
              (std::isfinite(predicted) ? std::to_string(static_cast<long>(predicted)) : "no") +
              " sweeps (budget " + std::to_string(budget) + ")";
        break;
      }
      // A prediction that more than doubles from one run to the next is a stall beginning
      // (BoxesStack1: 620 then 1,676 sweeps, stopped by the budget only after 800 sweeps, as
      // long as prox's whole solve); converging runs predict steadily (KaplasTower at tol 1e-10:
      // 626, 963, 1346, 1550).
      if (predicted > 2 * predicted_last) {
        why = "; stopped: its predicted sweeps more than doubled (" +
              std::to_string(static_cast<long>(predicted_last)) + " then " +
              std::to_string(static_cast<long>(predicted)) + ")";
        break;
      }
      predicted_last = predicted;
    }
    e_last = e;
    s_last = done;
    chunk = std::min(runs >= 2 ? 2 * chunk : chunk, budget - done);
  }
  out.iterations = done;
  out.seconds = clock.seconds() - start;
  if (out.status != Status::kSolved)
    out.message = "nsgs: " + std::to_string(done) + " sweeps in " + std::to_string(runs) +
                  " runs" + why;
  return out;
}

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
  auto warm = [&]() { return have && best.z.size() == p.q.size() ? best.z : Eigen::VectorXd(); };
  // The caller's options with the time left, taken once: a solver is called only when that
  // number is > 0 (read again after a check it could have passed 0, which solvers refuse).
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
    const CommonOptions c = common();
    if (!(c.time_limit_s > 0)) {
      attempts.push_back({name, Status::kTimeLimit, 0, 0, "skipped: time limit reached"});
      continue;
    }
    if (name == "nsgs") {
      record(name, nsgs_stage(p, o, clock));
      continue;
    }
    if (name == "prox") {
      // W + alpha I: what a rank-deficient W, where nsgs stalls, needs. From r = 0, not from
      // nsgs' iterate: its alpha rule then starts large (Capsules-i125-1213: 5 outer
      // iterations from 0, 10 from nsgs' iterate; Capsules-i101-404: 8 and 15).
      ProxOptions po;
      po.common = c;
      record(name, solve_prox(p, po));
      continue;
    }
    if (name == "fb-soc") {
      FbSocOptions fo;  // Newton from the best iterate so far
      fo.common = c;
      fo.r0 = warm();
      record(name, solve_fb_soc(p, fo));
      const CommonOptions c2 = common();
      if (best.status != Status::kSolved && c2.time_limit_s > 0) {
        FbSocOptions mo;  // the other line search (fb_soc.hpp), from r = 0
        mo.common = c2;
        mo.nonmonotone_memory = 1;
        SolveResult r = solve_fb_soc(p, mo);
        r.message = "monotone line search" + (r.message.empty() ? "" : "; " + r.message);
        record(name, std::move(r));
      }
      continue;
    }
    record(name, e->solve_fc(p, c));
  }
  // An answer accepted only just (above tol / 10): a few Gauss-Seidel sweeps from it, kept when
  // they do better. FrictionContact3D_RR_1c at tol 1e-8: fb-soc stops at 3.8e-9 (1.1e-7 by
  // Siconos' |q| measure); nsgs from there reaches rounding.
  // (Not after nsgs itself: the polish would only continue its sweeps, doubling the time of a
  // small problem.)
  const CommonOptions polish = common();
  if (have && best.status == Status::kSolved && best.solver != "nsgs" &&
      best.residuals.natural > 0.1 * o.tol && polish.time_limit_s > 0) {
    NsgsOptions no;
    no.common = polish;
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
    // A time limit spent before the first solver (a limit of microseconds) is a time limit.
    const bool timed_out = !(left() > 0);
    best.status = timed_out ? Status::kTimeLimit : Status::kNotRun;
    best.message = timed_out ? "auto: time limit reached before any friction solver ran"
                             : "auto: no friction solver ran";
    best.seconds = clock.seconds();
    return best;
  }
  // Every stage ran at the caller's tol and tol_acceptable and returned through finalize(),
  // which stored its errors: judging that answer again would decide the same (a small solve
  // spent a sixth of its time there). An answer finalize() did not judge is judged here.
  if (!best.friction_errors) {
    const std::string solver = best.solver;
    best = finalize(p, std::move(best), o);
    best.solver = solver;
  }
  // A chain the clock cut short (a solver stopped by it, or one never started) has not shown
  // that its solvers fail: the best unverified answer's own status (e.g. nsgs' iteration_limit)
  // would say so. Its status is the time limit; the message keeps the answer's own.
  const bool clock_cut = std::any_of(best.attempts.begin(), best.attempts.end(),
                                     [](const Attempt& a) { return a.status == Status::kTimeLimit; });
  if (clock_cut && !is_solution(best.status)) {
    best.message = "auto: time limit reached; best answer by " + best.solver + " (" +
                   std::string(to_string(best.status)) + ")" +
                   (best.message.empty() ? "" : ": " + best.message);
    best.status = Status::kTimeLimit;
  }
  best.seconds = clock.seconds();
  return best;
}

}  // namespace cpkit::lcp::friction
