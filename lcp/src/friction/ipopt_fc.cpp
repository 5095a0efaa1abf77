// Ipopt fallback for frictional contact through an MPCC on the true cone (ipopt_fc.hpp).
#include "cpkit/lcp/friction/ipopt_fc.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "cpkit/core/errors.hpp"
#include "cpkit/core/friction_verdict.hpp"
#include "cpkit/core/timer.hpp"
#include "cpkit/lcp/mpcc.hpp"
#include "friction_common.hpp"

namespace cpkit::lcp::friction {

std::string IpoptFcOptions::validate(Eigen::Index n) const {
  if (const std::string e = common.validate(); !e.empty()) return e;
  if (r0.size() != 0 && (r0.size() != n || !r0.allFinite()))
    return "r0 must have " + std::to_string(n) + " finite entries, got " +
           std::to_string(r0.size());
  return {};
}

SolveResult solve_ipopt_fc(const FrictionContactProblem& p, const IpoptFcOptions& o) {
  Stopwatch clock;
  detail::check_problem(p);
  const Eigen::Index nc = p.contacts(), n3 = 3 * nc, n = 4 * nc;
  throw_if_invalid(o.validate(n3), "ipopt friction options");
  SolveResult out;
  out.solver = "ipopt";
  if (nc > kIpoptFcMaxContacts) {
    out.status = Status::kUnsupported;
    out.message = "the Ipopt friction fallback takes at most " +
                  std::to_string(kIpoptFcMaxContacts) +
                  " contacts (dense derivatives of 4 n_c "
                  "unknowns); this problem has " +
                  std::to_string(nc) + ": use nsgs, fb-soc or prox";
    return out;
  }
  const FrictionUnits units = friction_units(p);
  if (!(units.q_inf > 0) || nc == 0) {  // q = 0: r = 0 solves it
    out.z = Eigen::VectorXd::Zero(n3);
    out.status = Status::kSolved;
    out.message = "q = 0: r = 0";
    return finalize(p, std::move(out), o.common);
  }
  const double w_max = units.w_max > 0 ? units.w_max : 1.0;
  const double U = units.q_inf, R = U / w_max;
  const Eigen::MatrixXd Wh = Eigen::MatrixXd(p.W) / w_max;
  const Eigen::VectorXd qh = p.q / U;
  const Eigen::VectorXd& mu = p.mu;

  MpccProblem m;
  m.n = n;
  m.name = p.name.empty() ? "friction MPCC" : p.name + " (friction MPCC)";
  m.lower = Eigen::VectorXd::Constant(n, -std::numeric_limits<double>::infinity());
  m.upper = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  for (Eigen::Index i = 0; i < nc; ++i) {
    m.lower[3 * i] = 0;
    m.lower[n3 + i] = 0;
  }
  m.x0 = Eigen::VectorXd::Zero(n);
  if (o.r0.size()) {
    m.x0.head(n3) = o.r0 / R;
    for (Eigen::Index i = 0; i < nc; ++i) m.x0[3 * i] = std::max(m.x0[3 * i], 0.0);
  } else {
    for (Eigen::Index i = 0; i < nc; ++i) m.x0[3 * i] = 1;
  }
  m.p = 2 * nc;
  m.G = [=](const Vec& x, Vec& g) {
    g.resize(2 * nc);
    for (Eigen::Index i = 0; i < nc; ++i) {
      g[i] = x[3 * i];
      g[nc + i] = x[n3 + i];
    }
    return true;
  };
  m.G_jacobian = [=](const Vec&, Mat& J) {
    J = Mat::Zero(2 * nc, n);
    for (Eigen::Index i = 0; i < nc; ++i) {
      J(i, 3 * i) = 1;
      J(nc + i, n3 + i) = 1;
    }
    return true;
  };
  m.H = [=, &Wh, &qh](const Vec& x, Vec& h) {
    const Eigen::VectorXd v = Wh * x.head(n3) + qh;
    h.resize(2 * nc);
    for (Eigen::Index i = 0; i < nc; ++i) {
      h[i] = v[3 * i];
      h[nc + i] = mu[i] * mu[i] * x[3 * i] * x[3 * i] - x[3 * i + 1] * x[3 * i + 1] -
                  x[3 * i + 2] * x[3 * i + 2];
    }
    return true;
  };
  m.H_jacobian = [=, &Wh](const Vec& x, Mat& J) {
    J = Mat::Zero(2 * nc, n);
    for (Eigen::Index i = 0; i < nc; ++i) {
      J.row(i).head(n3) = Wh.row(3 * i);
      J(nc + i, 3 * i) = 2 * mu[i] * mu[i] * x[3 * i];
      J(nc + i, 3 * i + 1) = -2 * x[3 * i + 1];
      J(nc + i, 3 * i + 2) = -2 * x[3 * i + 2];
    }
    return true;
  };
  m.m = 2 * nc;
  m.c_lower = Eigen::VectorXd::Zero(2 * nc);
  m.c_upper = Eigen::VectorXd::Zero(2 * nc);
  // c_{2i+a} = mu r_N v_{T,a} + s r_{T,a}
  m.constraints = [=, &Wh, &qh](const Vec& x, Vec& c) {
    const Eigen::VectorXd v = Wh * x.head(n3) + qh;
    c.resize(2 * nc);
    for (Eigen::Index i = 0; i < nc; ++i)
      for (int a = 1; a <= 2; ++a)
        c[2 * i + a - 1] = mu[i] * x[3 * i] * v[3 * i + a] + x[n3 + i] * x[3 * i + a];
    return true;
  };
  m.constraint_jacobian = [=, &Wh, &qh](const Vec& x, Mat& J) {
    const Eigen::VectorXd v = Wh * x.head(n3) + qh;
    J = Mat::Zero(2 * nc, n);
    for (Eigen::Index i = 0; i < nc; ++i)
      for (int a = 1; a <= 2; ++a) {
        const Eigen::Index row = 2 * i + a - 1;
        J.row(row).head(n3) = mu[i] * x[3 * i] * Wh.row(3 * i + a);
        J(row, 3 * i) += mu[i] * v[3 * i + a];
        J(row, 3 * i + a) += x[n3 + i];
        J(row, n3 + i) += x[3 * i + a];
      }
    return true;
  };
  m.hessian = [=, &Wh](const Vec&, double, const Vec& lc, const Vec&, const Vec& lH, Mat& Hs) {
    Hs = Mat::Zero(n, n);
    for (Eigen::Index i = 0; i < nc; ++i) {
      for (int a = 1; a <= 2; ++a) {
        const double l = lc[2 * i + a - 1];
        if (l == 0) continue;
        // d2/drho2 of mu r_N (W rho)_{T,a}: mu (e_N W_row^T + W_row e_N^T)
        Hs.row(3 * i).head(n3) += l * mu[i] * Wh.row(3 * i + a);
        Hs.col(3 * i).head(n3) += l * mu[i] * Wh.row(3 * i + a).transpose();
        Hs(n3 + i, 3 * i + a) += l;
        Hs(3 * i + a, n3 + i) += l;
      }
      const double l = lH[nc + i];
      Hs(3 * i, 3 * i) += l * 2 * mu[i] * mu[i];
      Hs(3 * i + 1, 3 * i + 1) -= l * 2;
      Hs(3 * i + 2, 3 * i + 2) -= l * 2;
    }
    return true;
  };
  MpccOptions mo;
  mo.common = o.common;
  mo.common.record_trace = false;
  mo.common.time_limit_s = o.common.time_limit_s;
  mo.backend = NlpBackend::kIpopt;
  mo.early_stop = [&](const Vec& x) {
    const Eigen::VectorXd r = R * x.head(n3);
    const Eigen::VectorXd u = p.W * r + p.q;
    return friction_residuals(p, units, r, u).natural <= o.common.tol;
  };
  const MpccResult mr = solve_mpcc(m, mo);
  out.z = mr.x.size() == n ? Eigen::VectorXd(R * mr.x.head(n3)) : Eigen::VectorXd();
  // The MPCC's own verdict is in its unit-free variables; only finalize() decides.
  out.status = Status::kNotRun;  // no claim: finalize() decides
  out.iterations = mr.iterations;
  out.message = "MPCC of the true cone by Ipopt (" + std::to_string(mr.subproblems.size()) +
                " NLPs, " + std::to_string(mr.iterations) + " iterations" +
                (mr.stopped_early ? ", stopped at the first verified iterate" : "") +
                "): " + std::string(to_string(mr.status)) +
                (mr.message.empty() ? "" : ", " + mr.message);
  SolveResult res = out.z.size() ? finalize(p, std::move(out), o.common) : out;
  if (res.status == Status::kNotRun)
    res.status = mr.status == Status::kTimeLimit ? Status::kTimeLimit : Status::kStalled;
  res.seconds = clock.seconds();
  return res;
}

SolverEntry with_ipopt_fc(SolverEntry e) {
  e.info.description += "; friction problems: an MPCC of the true cone (ipopt_fc.hpp)";
  e.solve_fc = detail::with_common_options<IpoptFcOptions>(
      [](const FrictionContactProblem& p, const IpoptFcOptions& o) { return solve_ipopt_fc(p, o); });
  return e;
}

}  // namespace cpkit::lcp::friction
