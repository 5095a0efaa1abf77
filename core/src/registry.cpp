#include "cpkit/core/registry.hpp"

#include <stdexcept>

namespace cpkit {

bool SolverEntry::accepts(ProblemKind kind) const {
  switch (kind) {
    case ProblemKind::kLcp: return static_cast<bool>(solve_lcp);
    case ProblemKind::kBoxLcp: return static_cast<bool>(solve_box_lcp);
    case ProblemKind::kMcp: return static_cast<bool>(solve_mcp);
    case ProblemKind::kFrictionContact: return static_cast<bool>(solve_fc);
    case ProblemKind::kSoc: return static_cast<bool>(solve_soc);
  }
  return false;
}

bool SolverEntry::accepts(const LcpProblem& p) const {
  if (!solve_lcp) return false;
  return p.is_sparse() ? info.sparse : info.dense;
}

void SolverRegistry::add(SolverEntry entry) {
  if (entry.info.name.empty()) throw std::invalid_argument("solver registry: empty solver name");
  if (find(entry.info.name) != nullptr)
    throw std::invalid_argument("solver registry: duplicate solver name '" + entry.info.name + "'");
  entries_.push_back(std::move(entry));
}

const SolverEntry* SolverRegistry::find(const std::string& name) const {
  for (const auto& e : entries_)
    if (e.info.name == name) return &e;
  return nullptr;
}

std::vector<std::string> SolverRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& e : entries_) out.push_back(e.info.name);
  return out;
}

std::vector<std::string> SolverRegistry::names(ProblemKind kind) const {
  std::vector<std::string> out;
  for (const auto& e : entries_)
    if (e.accepts(kind)) out.push_back(e.info.name);
  return out;
}

}  // namespace cpkit
