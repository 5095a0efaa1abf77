#include "cpkit/core/io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "cpkit/core/errors.hpp"

namespace cpkit {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

double json_number(const nlohmann::json& v, const std::string& origin, const std::string& where) {
  if (!v.is_number())
    throw InputError(origin + ": " + where + " is not a number (got " + v.dump() + ")");
  const double d = v.get<double>();
  if (!std::isfinite(d)) throw InputError(origin + ": " + where + " is not finite");
  return d;
}

// Tokenizer that remembers the line of each token (for error messages).
struct Token {
  std::string text;
  int line;
};
std::vector<Token> tokenize(const std::string& text) {
  std::vector<Token> out;
  int line = 1;
  std::string cur;
  for (char c : text) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      if (!cur.empty()) out.push_back({cur, line}), cur.clear();
      if (c == '\n') ++line;
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back({cur, line});
  return out;
}

bool parse_double(const std::string& s, double& v) {
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end != s.c_str() && *end == '\0';
}

}  // namespace

LcpProblem parse_lcp_json(const std::string& text, const std::string& origin) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(origin + ": malformed JSON: " + e.what());
  }
  if (!j.is_object()) throw InputError(origin + ": top level must be an object with \"M\" and \"q\"");
  LcpProblem p;
  if (j.contains("name") && j["name"].is_string()) p.name = j["name"].get<std::string>();
  if (j.contains("note") && j["note"].is_string()) p.note = j["note"].get<std::string>();
  if (j.contains("M_mtx") || j.contains("q_mtx")) {
    if (!j.contains("M_mtx") || !j.contains("q_mtx") || !j["M_mtx"].is_string() ||
        !j["q_mtx"].is_string())
      throw InputError(origin + ": \"M_mtx\" and \"q_mtx\" must both be file names");
    const auto base = std::filesystem::path(origin).parent_path();
    p.M_sparse = read_matrix_market((base / j["M_mtx"].get<std::string>()).string());
    p.q = read_matrix_market_vector((base / j["q_mtx"].get<std::string>()).string());
    throw_if_invalid(p.validate(), origin);
    return p;
  }
  if (!j.contains("M")) throw InputError(origin + ": missing field \"M\"");
  if (!j.contains("q")) throw InputError(origin + ": missing field \"q\"");
  const auto& jm = j["M"];
  const auto& jq = j["q"];
  if (!jq.is_array()) throw InputError(origin + ": field \"q\" must be an array of numbers");
  if (!jm.is_array()) throw InputError(origin + ": field \"M\" must be an array of rows");
  const auto n = static_cast<Eigen::Index>(jq.size());
  if (n == 0) throw InputError(origin + ": field \"q\" is empty");
  if (static_cast<Eigen::Index>(jm.size()) != n)
    throw InputError(origin + ": field \"M\" has " + std::to_string(jm.size()) +
                     " rows but \"q\" has " + std::to_string(n) + " entries");
  p.M.resize(n, n);
  p.q.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto& row = jm[static_cast<size_t>(i)];
    if (!row.is_array() || static_cast<Eigen::Index>(row.size()) != n)
      throw InputError(origin + ": M row " + std::to_string(i) + " must be an array of " +
                       std::to_string(n) + " numbers");
    for (Eigen::Index k = 0; k < n; ++k)
      p.M(i, k) = json_number(row[static_cast<size_t>(k)], origin,
                              "M[" + std::to_string(i) + "][" + std::to_string(k) + "]");
    p.q[i] = json_number(jq[static_cast<size_t>(i)], origin, "q[" + std::to_string(i) + "]");
  }
  throw_if_invalid(p.validate(), origin);
  return p;
}

LcpProblem read_lcp_json(const std::string& path) { return parse_lcp_json(read_text(path), path); }

LcpProblem parse_lcp_dat(const std::string& text, const std::string& origin) {
  const auto tokens = tokenize(text);
  if (tokens.empty()) throw InputError(origin + ": empty file (expected n, then M, then q)");
  double nd = 0;
  if (!parse_double(tokens[0].text, nd) || nd < 1 || nd != std::floor(nd) || nd > 1e6)
    throw InputError(origin + ":" + std::to_string(tokens[0].line) +
                     ": first token must be the size n >= 1 (got '" + tokens[0].text + "')");
  const auto n = static_cast<Eigen::Index>(nd);
  const size_t needed = 1 + static_cast<size_t>(n * n + n);
  if (tokens.size() < needed)
    throw InputError(origin + ": expected " + std::to_string(n * n) + " entries of M and " +
                     std::to_string(n) + " of q after n = " + std::to_string(n) + ", found only " +
                     std::to_string(tokens.size() - 1) + " tokens");
  std::vector<double> values(needed - 1);
  for (size_t k = 1; k < needed; ++k) {
    if (!parse_double(tokens[k].text, values[k - 1]) || !std::isfinite(values[k - 1]))
      throw InputError(origin + ":" + std::to_string(tokens[k].line) + ": expected a finite number, got '" +
                       tokens[k].text + "'");
  }
  LcpProblem p;
  p.M.resize(n, n);
  p.q.resize(n);
  // Siconos stores M column-major: the first n numbers are column 0.
  for (Eigen::Index c = 0; c < n; ++c)
    for (Eigen::Index r = 0; r < n; ++r) p.M(r, c) = values[static_cast<size_t>(c * n + r)];
  for (Eigen::Index i = 0; i < n; ++i) p.q[i] = values[static_cast<size_t>(n * n + i)];
  // Trailing free text is kept as the note.
  if (tokens.size() > needed) {
    std::string note;
    for (size_t k = needed; k < tokens.size(); ++k) note += (note.empty() ? "" : " ") + tokens[k].text;
    p.note = note;
  }
  p.name = std::filesystem::path(origin).stem().string();
  throw_if_invalid(p.validate(), origin);
  return p;
}

LcpProblem read_lcp_dat(const std::string& path) { return parse_lcp_dat(read_text(path), path); }

LcpProblem read_lcp_file(const std::string& path) {
  const auto ext = lower_extension(path);
  if (ext == ".json") return read_lcp_json(path);
  if (ext == ".dat") return read_lcp_dat(path);
  throw InputError(path + ": unknown file type '" + ext + "' (expected .json or .dat)");
}

void write_lcp_json(const LcpProblem& p, const std::string& path) {
  nlohmann::json j;
  if (!p.name.empty()) j["name"] = p.name;
  if (!p.note.empty()) j["note"] = p.note;
  const Mat m = p.dense_M();
  j["M"] = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index k = 0; k < m.cols(); ++k) row.push_back(m(i, k));
    j["M"].push_back(row);
  }
  j["q"] = std::vector<double>(p.q.data(), p.q.data() + p.q.size());
  std::ofstream out(path);
  if (!out) throw InputError(path + ": cannot write file");
  out << j.dump(1) << '\n';
}

void write_lcp_dat(const LcpProblem& p, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw InputError(path + ": cannot write file");
  const Mat m = p.dense_M();
  out << std::setprecision(17) << m.rows() << '\n';
  for (Eigen::Index c = 0; c < m.cols(); ++c) {  // column-major, as Siconos
    for (Eigen::Index r = 0; r < m.rows(); ++r) out << (r ? " " : "") << m(r, c);
    out << '\n';
  }
  for (Eigen::Index i = 0; i < p.q.size(); ++i) out << (i ? " " : "") << p.q[i];
  out << '\n';
  if (!p.note.empty()) out << p.note << '\n';
}

SparseMat read_matrix_market(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open file");
  std::string line;
  int lineno = 0;
  if (!std::getline(in, line)) throw InputError(path + ": empty Matrix Market file");
  ++lineno;
  std::string lower = line;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  std::istringstream hs(lower);
  std::string banner, object, format, field, symmetry;
  hs >> banner >> object >> format >> field >> symmetry;
  if (banner != "%%matrixmarket" || object != "matrix")
    throw InputError(path + ":1: not a Matrix Market matrix header");
  if (format != "coordinate" && format != "array")
    throw InputError(path + ":1: unsupported format '" + format + "'");
  if (field != "real" && field != "integer" && field != "double")
    throw InputError(path + ":1: unsupported field '" + field + "' (real or integer only)");
  const bool symmetric = symmetry == "symmetric";
  if (!symmetric && symmetry != "general")
    throw InputError(path + ":1: unsupported symmetry '" + symmetry + "'");
  // Skip comments.
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line[0] != '%') break;
  }
  std::istringstream ss(line);
  long rows = 0, cols = 0, nnz = 0;
  if (format == "coordinate") {
    if (!(ss >> rows >> cols >> nnz) || rows < 1 || cols < 1 || nnz < 0)
      throw InputError(path + ":" + std::to_string(lineno) + ": bad size line '" + line + "'");
  } else {
    if (!(ss >> rows >> cols) || rows < 1 || cols < 1)
      throw InputError(path + ":" + std::to_string(lineno) + ": bad size line '" + line + "'");
    nnz = rows * cols;
  }
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(static_cast<size_t>(symmetric ? 2 * nnz : nnz));
  long count = 0;
  while (count < nnz && std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == '%') continue;
    std::istringstream es(line);
    long i = 0, j = 0;
    double v = 0;
    if (format == "coordinate") {
      if (!(es >> i >> j >> v) || i < 1 || i > rows || j < 1 || j > cols || !std::isfinite(v))
        throw InputError(path + ":" + std::to_string(lineno) + ": bad entry '" + line + "'");
    } else {
      if (!(es >> v) || !std::isfinite(v))
        throw InputError(path + ":" + std::to_string(lineno) + ": bad entry '" + line + "'");
      i = count % rows + 1;  // array format is column-major
      j = count / rows + 1;
    }
    trip.emplace_back(i - 1, j - 1, v);
    if (symmetric && i != j) trip.emplace_back(j - 1, i - 1, v);
    ++count;
  }
  if (count < nnz)
    throw InputError(path + ": expected " + std::to_string(nnz) + " entries, found " +
                     std::to_string(count));
  SparseMat m(rows, cols);
  m.setFromTriplets(trip.begin(), trip.end());
  m.makeCompressed();
  return m;
}

Vec read_matrix_market_vector(const std::string& path) {
  const SparseMat m = read_matrix_market(path);
  if (m.cols() != 1 && m.rows() != 1)
    throw InputError(path + ": expected a vector (n x 1), got " + std::to_string(m.rows()) + " x " +
                     std::to_string(m.cols()));
  Mat d(m);
  if (d.cols() == 1) return d.col(0);
  return d.row(0).transpose();
}

}  // namespace cpkit
