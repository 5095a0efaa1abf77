// `cpkit lcp enumerate FILE [--json] [--tol T] [--time-limit S] [--max-size N]`
// Reads an LCP (.json or .dat) and prints its whole solution set (enumerate_all): the extreme
// solutions, whether the set is a continuum, and its directions. JSON fields (stable):
//   complete (bool), count (integer, or "inf" when the set is infinite), solutions
//   [{"z": [...], "w": [...], "basis": [...]}] (the extreme solutions), continuum (bool),
//   directions (when infinite: rays and vertex-pair directions, ||d||_inf = 1), pieces
//   [{"support", "vertices", "rays"}], num_extreme, ambiguous, nodes, seconds, message.
// Exit codes: 0 at least one solution; 1 no solution (the enumeration is complete); 5
// inconclusive: complete = false (time limit) and no solution found so far, which proves
// nothing; 2 bad input, including n above the size limit (message on stderr, nothing on
// stdout). When complete = false, "count" counts the solutions found so far (a lower bound).
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "cli_common.hpp"
#include "cli_options.hpp"
#include "cpkit/core/errors.hpp"
#include "cpkit/core/io.hpp"
#include "cpkit/core/report.hpp"
#include "cpkit/lcp/enumerate.hpp"
#include "lcp_actions.hpp"

namespace cpkit::cli {
namespace {

struct LcpEnumerateArgs {
  std::string file;
  bool json = false;
  double tol = lcp::EnumerationOptions{}.tol;
  double time_limit_s = lcp::EnumerationOptions{}.time_limit_s;
  int max_size = lcp::EnumerationOptions{}.max_size;
};

nlohmann::json set_json(const lcp::SolutionSet& s, const LcpProblem& p) {
  nlohmann::json j;
  if (!p.name.empty()) j["problem"] = p.name;
  j["n"] = p.size();
  j["complete"] = s.complete;
  if (s.infinite)
    j["count"] = "inf";
  else
    j["count"] = s.count();
  j["num_extreme"] = s.count();
  j["continuum"] = s.infinite;
  nlohmann::json sols = nlohmann::json::array();
  for (const auto& e : s.solutions)
    sols.push_back({{"z", to_json(e.z)}, {"w", to_json(e.w)}, {"basis", e.basis}});
  j["solutions"] = sols;
  if (s.infinite) {
    nlohmann::json dirs = nlohmann::json::array();
    for (const auto& d : s.directions) dirs.push_back(to_json(d));
    j["directions"] = dirs;
    nlohmann::json pieces = nlohmann::json::array();
    for (const auto& pc : s.pieces) {
      nlohmann::json rays = nlohmann::json::array();
      for (const auto& r : pc.rays) rays.push_back(to_json(r));
      pieces.push_back({{"support", pc.support}, {"vertices", pc.vertices}, {"rays", rays}});
    }
    j["pieces"] = pieces;
  }
  j["ambiguous"] = s.ambiguous;
  j["nodes"] = s.nodes;
  j["seconds"] = s.seconds;
  j["message"] = s.message;  // always present (documented field; empty when nothing to say)
  return j;
}

std::string vec_text(const Vec& v) {
  std::ostringstream o;
  o << '[';
  for (Eigen::Index i = 0; i < v.size(); ++i) o << (i ? ", " : "") << v(i);
  o << ']';
  return o.str();
}

std::string set_text(const lcp::SolutionSet& s, const LcpProblem& p) {
  std::ostringstream o;
  if (!p.name.empty()) o << "problem:    " << p.name << " (n = " << p.size() << ")\n";
  o << "complete:   " << (s.complete ? "yes" : "NO") << '\n';
  if (s.complete)
    o << "count:      " << (s.infinite ? std::string("inf (a continuum)") : std::to_string(s.count()))
      << '\n';
  else
    o << "count:      at least " << (s.infinite ? std::string("a continuum") : std::to_string(s.count()))
      << " (the enumeration is INCOMPLETE: more solutions may exist)\n";
  o << "extreme solutions: " << s.count() << '\n';
  for (size_t k = 0; k < s.solutions.size(); ++k)
    o << "  " << k << ": z = " << vec_text(s.solutions[k].z) << "  w = " << vec_text(s.solutions[k].w)
      << '\n';
  if (s.infinite) {
    o << "pieces of positive dimension: " << s.pieces.size() << '\n';
    for (const auto& pc : s.pieces) {
      o << "  support {";
      for (size_t i = 0; i < pc.support.size(); ++i) o << (i ? ", " : "") << pc.support[i];
      o << "}: vertices {";
      for (size_t i = 0; i < pc.vertices.size(); ++i) o << (i ? ", " : "") << pc.vertices[i];
      o << "}";
      for (const auto& r : pc.rays) o << " ray " << vec_text(r);
      o << '\n';
    }
    o << "directions: " << s.directions.size() << '\n';
    for (const auto& d : s.directions) o << "  " << vec_text(d) << '\n';
  }
  if (s.ambiguous) o << "ambiguous sign tests: " << s.ambiguous << '\n';
  if (!s.message.empty()) o << "message:    " << s.message << '\n';
  o << "time:       " << s.seconds << " s\n";
  return o.str();
}

int run_lcp_enumerate(const LcpEnumerateArgs& a) {
  const LcpProblem problem = read_lcp_file(a.file);
  lcp::EnumerationOptions opt;
  opt.tol = a.tol;
  opt.time_limit_s = a.time_limit_s;
  opt.max_size = a.max_size;
  throw_if_invalid_option(opt.validate(), {{"EnumerationOptions::max_size", "--max-size"},
                                           {"EnumerationOptions::tol", "--tol"},
                                           {"EnumerationOptions::time_limit_s", "--time-limit"}});
  const lcp::SolutionSet s = lcp::enumerate_all(problem, opt);
  if (a.json)
    print_json(set_json(s, problem));
  else
    std::cout << set_text(s, problem) << std::flush;
  if (!s.solutions.empty()) return kExitOk;
  return s.complete ? kExitNoSolution : kExitInconclusive;
}

}  // namespace

void add_lcp_enumerate(CLI::App& lcp, Context& ctx) {
  auto args = std::make_shared<LcpEnumerateArgs>();
  auto* cmd = lcp.add_subcommand(
      "enumerate", "All solutions of an LCP (extreme solutions, continua, directions)");
  cmd->add_option("FILE", args->file, "problem file (.json or Siconos .dat)")->required();
  cmd->add_flag("--json", args->json, "print one JSON object on stdout");
  cmd->add_option("--tol", args->tol, "relative tolerance of the sign tests (default 1e-12)");
  cmd->add_option("--time-limit", args->time_limit_s,
                  "wall-clock limit in seconds, every phase (default 60; then complete = false)");
  cmd->add_option("--max-size", args->max_size,
                  "largest n the general engine attempts (default and at most 64); a larger problem that is "
                  "not a bimatrix game ends with complete = false");
  cmd->callback([args, &ctx]() { ctx.exit_code = run_lcp_enumerate(*args); });
}

}  // namespace cpkit::cli
