#pragma once
/// \file registry.hpp
/// Name -> solver, with capabilities, so the CLI, tests and benchmarks can run every solver on
/// the same problem. Solvers are plain functions (no hidden mutable state: safe on many threads).
#include <functional>
#include <string>
#include <vector>

#include "cpkit/core/friction_problem.hpp"
#include "cpkit/core/options.hpp"
#include "cpkit/core/problem.hpp"
#include "cpkit/core/result.hpp"
#include "cpkit/core/soc_problem.hpp"

namespace cpkit {

/// kFrictionContact: the local 3-D frictional contact problem (friction_problem.hpp);
/// kSoc: second-order-cone complementarity, per-block cones v0 >= |v1| (soc_problem.hpp).
enum class ProblemKind { kLcp, kBoxLcp, kMcp, kFrictionContact, kSoc };

struct SolverInfo {
  std::string name;          ///< registry key, e.g. "lemke", "fb-newton"
  std::string description;   ///< one line, with a citation key
  bool dense = true;         ///< accepts dense LCP storage
  bool sparse = false;       ///< accepts sparse LCP storage
  bool serialized = false;   ///< calls are serialized internally (e.g. Ipopt)
};

using LcpSolveFn = std::function<SolveResult(const LcpProblem&, const CommonOptions&)>;
using BoxLcpSolveFn = std::function<SolveResult(const BoxLcpProblem&, const CommonOptions&)>;
using McpSolveFn = std::function<SolveResult(const McpProblem&, const CommonOptions&)>;
/// Friction solvers return r in SolveResult::z (3 per contact, normal first) and u = W r + q in
/// w, through finalize(const FrictionContactProblem&, ...) (friction_verdict.hpp).
using FrictionSolveFn =
    std::function<SolveResult(const FrictionContactProblem&, const CommonOptions&)>;
/// Cone solvers return z and w = M z + q through finalize(const SocProblem&, ...).
using SocSolveFn = std::function<SolveResult(const SocProblem&, const CommonOptions&)>;

/// One registered solver. Entry points that are empty mean "does not accept that kind".
struct SolverEntry {
  SolverInfo info;
  LcpSolveFn solve_lcp;
  BoxLcpSolveFn solve_box_lcp;
  McpSolveFn solve_mcp;
  FrictionSolveFn solve_fc;
  SocSolveFn solve_soc;
  bool accepts(ProblemKind kind) const;
  /// Accepts this LCP (kind and storage).
  bool accepts(const LcpProblem& p) const;
};

class SolverRegistry {
 public:
  /// Adds a solver; throws std::invalid_argument on a duplicate or empty name.
  void add(SolverEntry entry);
  /// nullptr when unknown.
  const SolverEntry* find(const std::string& name) const;
  /// Names in registration order, optionally only those accepting `kind`.
  std::vector<std::string> names() const;
  std::vector<std::string> names(ProblemKind kind) const;
  const std::vector<SolverEntry>& entries() const { return entries_; }

 private:
  std::vector<SolverEntry> entries_;
};

}  // namespace cpkit
