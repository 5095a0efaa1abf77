// Ipopt backend of the MPCC subproblems: a TNLP adapter over NlpEvaluator (dense derivatives).
// Ipopt's console journal is never created: its output goes to the caller's LogSink (at debug
// level, only when verbosity >= 3) or nowhere, so it can never reach stdout. The options file
// "ipopt.opt" is never read (Initialize from an empty stream). Ipopt and MUMPS are not assumed
// thread-safe: all calls are serialized by ipopt_mutex().
#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>
#include <mutex>
#include <sstream>
#include <string>

#include "cpkit/core/log.hpp"
#include "mpcc_nlp.hpp"

namespace cpkit::lcp::detail {
namespace {

std::mutex& ipopt_mutex() {
  static std::mutex mutex;
  return mutex;
}

constexpr double kIpoptInf = 2e19;  // Ipopt's default nlp_upper_bound_inf

double to_ipopt(double v) {
  if (v == std::numeric_limits<double>::infinity()) return kIpoptInf;
  if (v == -std::numeric_limits<double>::infinity()) return -kIpoptInf;
  return v;
}

/// Forwards Ipopt's journal to a LogSink line by line (debug level).
class SinkJournal : public Ipopt::Journal {
 public:
  SinkJournal(LogSink* sink, Ipopt::EJournalLevel level)
      : Ipopt::Journal("cpkit-sink", level), sink_(sink) {}
  ~SinkJournal() override { FlushBufferImpl(); }

 protected:
  void PrintImpl(Ipopt::EJournalCategory, Ipopt::EJournalLevel, const char* str) override {
    buffer_ += str;
    emit_lines();
  }
  void PrintfImpl(Ipopt::EJournalCategory, Ipopt::EJournalLevel, const char* fmt,
                  va_list ap) override {
    char local[2048];
    va_list copy;
    va_copy(copy, ap);
    const int len = std::vsnprintf(local, sizeof local, fmt, copy);
    va_end(copy);
    if (len < 0) return;
    if (static_cast<std::size_t>(len) < sizeof local) {
      buffer_ += local;
    } else {
      std::string big(static_cast<std::size_t>(len) + 1, '\0');
      std::vsnprintf(big.data(), big.size(), fmt, ap);
      big.resize(static_cast<std::size_t>(len));
      buffer_ += big;
    }
    emit_lines();
  }
  void FlushBufferImpl() override {
    if (!buffer_.empty() && sink_) sink_->write(LogLevel::kDebug, "ipopt: " + buffer_);
    buffer_.clear();
  }

 private:
  void emit_lines() {
    std::size_t pos;
    while ((pos = buffer_.find('\n')) != std::string::npos) {
      if (pos > 0 && sink_) sink_->write(LogLevel::kDebug, "ipopt: " + buffer_.substr(0, pos));
      buffer_.erase(0, pos + 1);
    }
  }
  LogSink* sink_;
  std::string buffer_;
};

class MpccTnlp : public Ipopt::TNLP {
 public:
  MpccTnlp(const NlpEvaluator& nlp, const Vec& x0, NlpOutcome& out)
      : nlp_(nlp), x0_(x0), out_(out) {}

  bool get_nlp_info(Ipopt::Index& n, Ipopt::Index& m, Ipopt::Index& nnz_jac_g,
                    Ipopt::Index& nnz_h_lag, IndexStyleEnum& index_style) override {
    n = static_cast<Ipopt::Index>(nlp_.n());
    m = static_cast<Ipopt::Index>(nlp_.rows());
    nnz_jac_g = n * m;
    nnz_h_lag = n * (n + 1) / 2;
    index_style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Ipopt::Index n, Ipopt::Number* x_l, Ipopt::Number* x_u, Ipopt::Index m,
                       Ipopt::Number* g_l, Ipopt::Number* g_u) override {
    for (Ipopt::Index i = 0; i < n; ++i) {
      x_l[i] = to_ipopt(nlp_.x_lower()(i));
      x_u[i] = to_ipopt(nlp_.x_upper()(i));
    }
    for (Ipopt::Index j = 0; j < m; ++j) {
      g_l[j] = to_ipopt(nlp_.g_lower()(j));
      g_u[j] = to_ipopt(nlp_.g_upper()(j));
    }
    return true;
  }

  bool get_starting_point(Ipopt::Index n, bool init_x, Ipopt::Number* x, bool init_z,
                          Ipopt::Number*, Ipopt::Number*, Ipopt::Index, bool init_lambda,
                          Ipopt::Number*) override {
    if (!init_x || init_z || init_lambda) return false;
    for (Ipopt::Index i = 0; i < n; ++i) x[i] = x0_(i);
    return true;
  }

  bool eval_f(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Number& obj) override {
    return note(nlp_.objective(map(n, x), obj));
  }

  bool eval_grad_f(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Number* grad) override {
    Vec g;
    if (!note(nlp_.gradient(map(n, x), g))) return false;
    Eigen::Map<Vec>(grad, n) = g;
    return true;
  }

  bool eval_g(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Index m,
              Ipopt::Number* g) override {
    Vec v;
    if (!note(nlp_.constraints(map(n, x), v))) return false;
    Eigen::Map<Vec>(g, m) = v;
    return true;
  }

  bool eval_jac_g(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Index m, Ipopt::Index,
                  Ipopt::Index* iRow, Ipopt::Index* jCol, Ipopt::Number* values) override {
    if (values == nullptr) {
      Ipopt::Index k = 0;
      for (Ipopt::Index r = 0; r < m; ++r)
        for (Ipopt::Index c = 0; c < n; ++c, ++k) {
          iRow[k] = r;
          jCol[k] = c;
        }
      return true;
    }
    Mat J;
    if (!note(nlp_.jacobian(map(n, x), J))) return false;
    Ipopt::Index k = 0;
    for (Ipopt::Index r = 0; r < m; ++r)
      for (Ipopt::Index c = 0; c < n; ++c) values[k++] = J(r, c);
    return true;
  }

  bool eval_h(Ipopt::Index n, const Ipopt::Number* x, bool, Ipopt::Number obj_factor,
              Ipopt::Index m, const Ipopt::Number* lambda, bool, Ipopt::Index,
              Ipopt::Index* iRow, Ipopt::Index* jCol, Ipopt::Number* values) override {
    if (values == nullptr) {
      Ipopt::Index k = 0;
      for (Ipopt::Index r = 0; r < n; ++r)
        for (Ipopt::Index c = 0; c <= r; ++c, ++k) {
          iRow[k] = r;
          jCol[k] = c;
        }
      return true;
    }
    Mat Hs;
    const Vec lam = Eigen::Map<const Vec>(lambda, m);
    if (!note(nlp_.hessian(map(n, x), obj_factor, lam, Hs))) return false;
    Ipopt::Index k = 0;
    for (Ipopt::Index r = 0; r < n; ++r)
      for (Ipopt::Index c = 0; c <= r; ++c) values[k++] = Hs(r, c);
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn, Ipopt::Index n, const Ipopt::Number* x,
                         const Ipopt::Number*, const Ipopt::Number*, Ipopt::Index,
                         const Ipopt::Number*, const Ipopt::Number*, Ipopt::Number,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    if (x != nullptr) {
      Vec xv = Eigen::Map<const Vec>(x, n);
      if (xv.allFinite()) out_.x = xv;
    }
  }

  bool intermediate_callback(Ipopt::AlgorithmMode, Ipopt::Index iter, Ipopt::Number,
                             Ipopt::Number, Ipopt::Number, Ipopt::Number, Ipopt::Number,
                             Ipopt::Number, Ipopt::Number, Ipopt::Number, Ipopt::Index,
                             const Ipopt::IpoptData*,
                             Ipopt::IpoptCalculatedQuantities*) override {
    out_.iterations = static_cast<int>(iter);
    return true;
  }

 private:
  static Vec map(Ipopt::Index n, const Ipopt::Number* x) { return Eigen::Map<const Vec>(x, n); }
  bool note(bool ok) {
    if (!ok) out_.eval_failed = true;
    return ok;
  }
  const NlpEvaluator& nlp_;
  Vec x0_;
  NlpOutcome& out_;
};

std::string status_name(Ipopt::ApplicationReturnStatus s) {
  switch (s) {
    case Ipopt::Solve_Succeeded: return "Solve_Succeeded";
    case Ipopt::Solved_To_Acceptable_Level: return "Solved_To_Acceptable_Level";
    case Ipopt::Infeasible_Problem_Detected: return "Infeasible_Problem_Detected";
    case Ipopt::Search_Direction_Becomes_Too_Small: return "Search_Direction_Becomes_Too_Small";
    case Ipopt::Diverging_Iterates: return "Diverging_Iterates";
    case Ipopt::User_Requested_Stop: return "User_Requested_Stop";
    case Ipopt::Feasible_Point_Found: return "Feasible_Point_Found";
    case Ipopt::Maximum_Iterations_Exceeded: return "Maximum_Iterations_Exceeded";
    case Ipopt::Restoration_Failed: return "Restoration_Failed";
    case Ipopt::Error_In_Step_Computation: return "Error_In_Step_Computation";
    case Ipopt::Maximum_CpuTime_Exceeded: return "Maximum_CpuTime_Exceeded";
    case Ipopt::Not_Enough_Degrees_Of_Freedom: return "Not_Enough_Degrees_Of_Freedom";
    case Ipopt::Invalid_Problem_Definition: return "Invalid_Problem_Definition";
    case Ipopt::Invalid_Option: return "Invalid_Option";
    case Ipopt::Invalid_Number_Detected: return "Invalid_Number_Detected";
    case Ipopt::Unrecoverable_Exception: return "Unrecoverable_Exception";
    case Ipopt::NonIpopt_Exception_Thrown: return "NonIpopt_Exception_Thrown";
    case Ipopt::Insufficient_Memory: return "Insufficient_Memory";
    case Ipopt::Internal_Error: return "Internal_Error";
  }
  return "ipopt status " + std::to_string(static_cast<int>(s));
}

}  // namespace

NlpOutcome solve_nlp_ipopt(const NlpEvaluator& nlp, const Vec& x0, const MpccOptions& options,
                           double time_limit_s, double bound_relax) {
  NlpOutcome out;
  out.x = x0;
  std::lock_guard<std::mutex> lock(ipopt_mutex());
  try {
    Ipopt::SmartPtr<Ipopt::IpoptApplication> app = new Ipopt::IpoptApplication(false, false);
    const bool chatty = options.common.log != nullptr && options.common.verbosity >= 3;
    if (chatty) {
      Ipopt::SmartPtr<Ipopt::Journal> journal =
          new SinkJournal(options.common.log, Ipopt::J_ITERSUMMARY);
      app->Jnlst()->AddJournal(journal);
    }
    std::istringstream no_options_file;
    if (app->Initialize(no_options_file) != Ipopt::Solve_Succeeded) {
      out.status = "Initialize_Failed";
      return out;
    }
    auto opts = app->Options();
    opts->SetIntegerValue("print_level", chatty ? 5 : 0);
    opts->SetNumericValue("tol", options.nlp_tol);
    opts->SetNumericValue("acceptable_tol", std::max(1e-6, options.nlp_tol));
    opts->SetIntegerValue("max_iter",
                          options.common.max_iterations > 0 ? options.common.max_iterations : 500);
    opts->SetNumericValue("bound_relax_factor", bound_relax);
    if (time_limit_s > 0 && std::isfinite(time_limit_s))
      opts->SetNumericValue("max_cpu_time", time_limit_s);
    if (!(options.exact_hessian && nlp.has_hessian()))
      opts->SetStringValue("hessian_approximation", "limited-memory");
    opts->SetStringValue("mu_strategy", "adaptive");

    Ipopt::SmartPtr<Ipopt::TNLP> tnlp = new MpccTnlp(nlp, x0, out);
    const Ipopt::ApplicationReturnStatus s = app->OptimizeTNLP(tnlp);
    out.status = status_name(s);
    out.converged = s == Ipopt::Solve_Succeeded || s == Ipopt::Solved_To_Acceptable_Level;
    out.time_limit = s == Ipopt::Maximum_CpuTime_Exceeded;
  } catch (const std::exception& e) {
    out.status = std::string("exception: ") + e.what();
    out.converged = false;
  } catch (...) {
    out.status = "unknown Ipopt exception";
    out.converged = false;
  }
  return out;
}

}  // namespace cpkit::lcp::detail
