// Robustness benchmark: every registered LCP solver (and "auto"), plus Siconos numerics'
// solvers as extra columns when CPKIT_HAVE_SICONOS, on the public LCP files and on random
// families whose solvability is known by construction:
//   pmatrix    M = B B^T / n + S + I/2 (S skew): positive definite, so a P-matrix; q ~ N(0, 1)
//   psd        M = A A^T / n (A n x n/2, rank-deficient) + S (skew); q planted (see below)
//   copositive M >= 0 entrywise with diagonal in [1, 2] (strictly copositive); q ~ N(0, 1)
//   general    M ~ N(0, 1) (indefinite, no structure); q planted
//   infeasible M ~ N(0, 1) with row k <= 0 and q_k < 0 (w_k < 0 for every z >= 0)
// "Planted": z* >= 0 and w* >= 0 complementary with random supports, q = w* - M z*, so z*
// solves the LCP. Every answer is judged by cpkit: finalize() on the returned z (Siconos' own
// "info" is ignored) plus a divergence guard (||z||_inf > 1e10 ||q||_inf / ||M||_max is a failure).
//
// Output (directory argument, default ./robustness-out): results.csv (one row per solve),
// profile.csv (Dolan-More performance profile over the solvable problems: the fraction of
// problems each solver solves within a factor tau of the best time; failures never count),
// machine.txt. Draw the profile with scripts/plot_profiles.py.
//
// Usage: bench_robustness [OUTDIR] [--quick]
//        mpirun -np K bench_robustness [OUTDIR] [--quick]   (a build with CPKIT_WITH_MPI)
// Under mpirun the problems are handed out one at a time by rank 0 to whichever rank is free
// (rate_problem/maps/map_run.hpp, as for the distributed maps); every rank runs all solvers on its
// problems, rank 0 writes the same files in the same order. Times are then those of a rank
// sharing the machine with the others.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cpkit/core/finalize.hpp"
#include "cpkit/core/io.hpp"
#include "cpkit/lcp/solvers.hpp"
#include "cpkit/rate_problem/maps/map_run.hpp"
#include "platform/mpi_session.hpp"

#include "siconos_lcp.hpp"

namespace {

using cpkit::LcpProblem;
using cpkit::Mat;
using cpkit::Vec;
namespace fs = std::filesystem;

struct Item {
  std::string name, family;
  LcpProblem problem;
  bool solvable = true;  ///< known: solvable by construction / file; false: proven infeasible
};

double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
double normal(std::mt19937_64& rng) {  // Box-Muller on portable uniforms
  const double u1 = 1 - uniform01(rng), u2 = uniform01(rng);
  return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
}
Mat gaussian(Eigen::Index r, Eigen::Index c, std::mt19937_64& rng) {
  Mat A(r, c);
  for (Eigen::Index j = 0; j < c; ++j)
    for (Eigen::Index i = 0; i < r; ++i) A(i, j) = normal(rng);
  return A;
}
Vec planted_q(const Mat& M, std::mt19937_64& rng) {
  const Eigen::Index n = M.rows();
  Vec z = Vec::Zero(n), w = Vec::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (uniform01(rng) < 0.5) z(i) = 0.1 + uniform01(rng);
    else w(i) = 0.1 + uniform01(rng);
  }
  return w - M * z;
}
Mat skew(Eigen::Index n, std::mt19937_64& rng) {
  const Mat A = gaussian(n, n, rng);
  return (A - A.transpose()) / std::sqrt(static_cast<double>(n));
}

std::vector<Item> make_items(bool quick) {
  std::vector<Item> items;
  const fs::path dir = fs::path(__FILE__).parent_path() / ".." / "tests" / "data" / "lcp";
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    Item it;
    it.problem = cpkit::read_lcp_file(f.string());
    it.name = f.stem().string();
    it.family = "file";
    std::ifstream in(f);
    std::stringstream text;
    text << in.rdbuf();
    it.solvable = text.str().find("\"status\": \"infeasible\"") == std::string::npos &&
                  text.str().find("\"status\":\"infeasible\"") == std::string::npos;
    items.push_back(std::move(it));
  }
  const std::vector<Eigen::Index> sizes =
      quick ? std::vector<Eigen::Index>{10, 20} : std::vector<Eigen::Index>{10, 25, 50, 100};
  const int per = quick ? 1 : 3;
  std::mt19937_64 rng(20261122);
  for (Eigen::Index n : sizes)
    for (int k = 0; k < per; ++k) {
      const std::string tag = "_n" + std::to_string(n) + "_" + std::to_string(k);
      {
        const Mat B = gaussian(n, n, rng);
        Mat M = B * B.transpose() / static_cast<double>(n) + skew(n, rng) +
                0.5 * Mat::Identity(n, n);
        Vec q(n);
        for (Eigen::Index i = 0; i < n; ++i) q(i) = normal(rng);
        items.push_back({"pmatrix" + tag, "pmatrix", LcpProblem(M, q), true});
      }
      {
        const Mat A = gaussian(n, n / 2, rng);
        Mat M = A * A.transpose() / static_cast<double>(n) + skew(n, rng);
        items.push_back({"psd" + tag, "psd", LcpProblem(M, planted_q(M, rng)), true});
      }
      {
        Mat M(n, n);
        for (Eigen::Index j = 0; j < n; ++j)
          for (Eigen::Index i = 0; i < n; ++i) M(i, j) = i == j ? 1 + uniform01(rng) : uniform01(rng);
        Vec q(n);
        for (Eigen::Index i = 0; i < n; ++i) q(i) = normal(rng);
        items.push_back({"copositive" + tag, "copositive", LcpProblem(M, q), true});
      }
      {
        Mat M = gaussian(n, n, rng);
        items.push_back({"general" + tag, "general", LcpProblem(M, planted_q(M, rng)), true});
      }
      if (k == 0) {
        Mat M = gaussian(n, n, rng);
        Vec q(n);
        for (Eigen::Index i = 0; i < n; ++i) q(i) = normal(rng);
        const Eigen::Index r = static_cast<Eigen::Index>(rng() % static_cast<std::uint64_t>(n));
        M.row(r) = -M.row(r).cwiseAbs();
        q(r) = -0.5 - uniform01(rng);
        items.push_back({"infeasible" + tag, "infeasible", LcpProblem(M, q), false});
      }
    }
  return items;
}

struct Outcome {
  std::string status;
  bool solved = false;
  double residual = 0, seconds = 0;
  std::string answered_by;
};

bool diverged(const LcpProblem& p, const Vec& z) {
  if (z.size() == 0 || !z.allFinite()) return true;
  const double qn = p.q.lpNorm<Eigen::Infinity>(), mn = p.dense_M().cwiseAbs().maxCoeff();
  return qn > 0 && mn > 0 && z.lpNorm<Eigen::Infinity>() / 1e10 > qn / mn;  // unit-free
}

Outcome run_cpkit(const cpkit::SolverEntry& e, const LcpProblem& p) {
  cpkit::CommonOptions o;
  o.time_limit_s = 60;
  const auto t0 = std::chrono::steady_clock::now();
  cpkit::SolveResult r;
  try {
    r = e.solve_lcp(p, o);
  } catch (const std::exception& ex) {
    r.status = cpkit::Status::kNumericalFailure;
  }
  Outcome out;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.status = std::string(cpkit::to_string(r.status));
  out.solved = cpkit::is_solution(r.status) && !diverged(p, r.z);
  out.residual = r.residuals.natural;
  out.answered_by = r.solver;
  return out;
}

#ifdef CPKIT_HAVE_SICONOS
Outcome run_siconos(int solver_id, const LcpProblem& p) {
  const int n = static_cast<int>(p.size());
  SiconosLcp sl(p.M, p.q);
  LinearComplementarityProblem& lcp = sl.lcp;
  SolverOptions* opt = solver_options_create(solver_id);
  opt->dparam[SICONOS_DPARAM_TOL] = 1e-12;
  if (solver_id != SICONOS_LCP_ENUM) opt->iparam[SICONOS_IPARAM_MAX_ITER] = 10000;
  Vec z = Vec::Zero(n), w = Vec::Zero(n);
  const auto t0 = std::chrono::steady_clock::now();
  const int info = linearComplementarity_driver(&lcp, z.data(), w.data(), opt);
  Outcome out;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  solver_options_delete(opt);
  // Judged by cpkit: finalize() on the returned z, claimed as a solution.
  cpkit::SolveResult claim;
  claim.status = cpkit::Status::kSolved;
  claim.z = z;
  const auto r = cpkit::finalize(p, claim, cpkit::CommonOptions{});
  out.solved = cpkit::is_solution(r.status) && !diverged(p, z);
  out.residual = r.residuals.natural;
  out.status = out.solved ? "verified" : "info=" + std::to_string(info) + ";refuted";
  if (!out.solved && info != 0) out.status = "info=" + std::to_string(info);
  return out;
}
#endif

std::string machine() {
  std::ostringstream s;
  std::ifstream cpu("/proc/cpuinfo");
  std::string line;
  int cores = 0;
  std::string model;
  while (std::getline(cpu, line)) {
    if (line.rfind("model name", 0) == 0 && model.empty()) model = line.substr(line.find(':') + 2);
    if (line.rfind("processor", 0) == 0) ++cores;
  }
  s << "cpu: " << model << "\nlogical cores: " << cores << "\n";
  std::ifstream ver("/proc/version");
  if (std::getline(ver, line)) s << "kernel: " << line << "\n";
  std::ifstream load("/proc/loadavg");
  if (std::getline(load, line)) s << "load average at start: " << line << "\n";
  s << "note: shared machine (other builds running); times are single runs, wall clock\n";
  return s.str();
}

}  // namespace

int main(int argc, char** argv) {
  cpkit::cli::mpi::init(&argc, &argv);
  fs::path out_dir = "robustness-out";
  bool quick = false;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--quick") quick = true;
    else out_dir = arg;
  }
  fs::create_directories(out_dir);
  const auto items = make_items(quick);
  std::vector<std::string> columns;
  for (const auto& e : cpkit::lcp::solvers().entries())
    if (e.solve_lcp) columns.push_back(e.info.name);
#ifdef CPKIT_HAVE_SICONOS
  const std::vector<std::pair<std::string, int>> siconos = {
      {"siconos-lexicolemke", SICONOS_LCP_LEMKE},
      {"siconos-newton_FB", SICONOS_LCP_NEWTON_FB_FBLSA},
      {"siconos-pgs", SICONOS_LCP_PGS},
      {"siconos-enum", SICONOS_LCP_ENUM}};
  for (const auto& s : siconos) columns.push_back(s.first);
#endif
  // Every (problem, solver) run: problem k is chunk k, computed on whichever rank takes it.
  std::vector<std::vector<Outcome>> results(items.size());
  auto solve_item = [&](const Item& it) {
    std::vector<Outcome> outs;
    for (const auto& col : columns) {
      Outcome o;
      if (const auto* e = cpkit::lcp::solvers().find(col)) o = run_cpkit(*e, it.problem);
#ifdef CPKIT_HAVE_SICONOS
      for (const auto& s : siconos)
        if (s.first == col) {
          if (s.second == SICONOS_LCP_ENUM && it.problem.size() > 12) {
            o.status = "skipped(n>12)";
          } else {
            o = run_siconos(s.second, it.problem);
          }
        }
#endif
      outs.push_back(o);
    }
    return outs;
  };
  cpkit::rate::ChunkRun run;
  run.plan.rows = static_cast<int>(items.size());
  run.plan.chunk_rows = 1;
  run.plan.chunks = run.plan.rows;
  run.plan.columns = static_cast<int64_t>(columns.size());
  run.compute = [&](int k) {
    cpkit::rate::MapChunk c;
    c.index = k;
    c.row_begin = k;
    c.row_end = k + 1;
    nlohmann::json outs = nlohmann::json::array();
    for (const auto& o : solve_item(items[static_cast<std::size_t>(k)]))
      outs.push_back({o.status, o.solved, o.residual, o.seconds, o.answered_by});
    c.summary = outs;
    return c;
  };
  run.consume = [&](const cpkit::rate::MapChunk& c) {
    for (const auto& o : c.summary)
      results[static_cast<std::size_t>(c.index)].push_back(
          {o[0].get<std::string>(), o[1].get<bool>(), o[2].get<double>(), o[3].get<double>(),
           o[4].get<std::string>()});
    std::cerr << items[static_cast<std::size_t>(c.index)].name << " done\n";
  };
  run.transport = cpkit::cli::mpi::map_transport();
  const cpkit::rate::ChunkRunStats stats = cpkit::rate::run_chunks(run);
  if (cpkit::cli::mpi::rank() != 0) {
    cpkit::cli::mpi::finalize();
    return 0;
  }
  std::ofstream csv(out_dir / "results.csv");
  csv << "problem,family,n,solvable,solver,status,verified,residual,seconds,answered_by\n";
  // times[problem][solver] (infinity when not solved); solvable problems only.
  std::vector<std::vector<double>> times;
  std::map<std::string, int> ok, false_claims;
  int solvable = 0, infeasible = 0;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const Item& it = items[k];
    std::vector<double> row;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::string& col = columns[c];
      const Outcome& o = results[k][c];
      csv << it.name << ',' << it.family << ',' << it.problem.size() << ',' << it.solvable << ','
          << col << ',' << o.status << ',' << o.solved << ',' << o.residual << ',' << o.seconds
          << ',' << o.answered_by << '\n';
      if (it.solvable) {
        ok[col] += o.solved;
        row.push_back(o.solved ? std::max(o.seconds, 1e-7) : INFINITY);
      } else {
        false_claims[col] += o.solved;
      }
    }
    if (it.solvable) {
      times.push_back(row);
      ++solvable;
    } else {
      ++infeasible;
    }
  }
  // Dolan-More profile over the solvable problems.
  std::ofstream prof(out_dir / "profile.csv");
  prof << "tau";
  for (const auto& c : columns) prof << ',' << c;
  prof << '\n';
  for (double log_tau = 0; log_tau <= 6.0001; log_tau += 0.05) {
    const double tau = std::pow(10.0, log_tau);
    prof << tau;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      int count = 0;
      for (const auto& row : times) {
        const double best = *std::min_element(row.begin(), row.end());
        if (std::isfinite(row[c]) && row[c] <= tau * best) ++count;
      }
      prof << ',' << static_cast<double>(count) / std::max(1, solvable);
    }
    prof << '\n';
  }
  std::ostringstream runs;
  runs << "processes: " << stats.ranks << " (problems x solvers computed per rank:";
  for (auto cells : stats.rank_cells) runs << ' ' << cells;
  runs << ")\n";
  std::ofstream(out_dir / "machine.txt") << machine() << runs.str();
  std::cout << runs.str();
  std::ostringstream summary;
  summary << "| solver | solved (of " << solvable << " solvable) | false \"solved\" on " << infeasible
          << " infeasible |\n|---|---|---|\n";
  for (const auto& c : columns)
    summary << "| " << c << " | " << ok[c] << " | " << false_claims[c] << " |\n";
  std::ofstream(out_dir / "summary.md") << summary.str();
  std::cout << summary.str();
  cpkit::cli::mpi::finalize();
  return 0;
}
