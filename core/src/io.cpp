// read_lcp_file: the problem-file dispatcher (one reader per format: io_json.cpp, io_dat.cpp,
// io_matrix_market.cpp, io_npy.cpp).
#include "cpkit/core/io.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "cpkit/core/errors.hpp"
#include "io_text.hpp"

namespace cpkit {
namespace {

namespace fs = std::filesystem;

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

std::string matrix_market_q_path(const std::string& m_path) {
  fs::path p(m_path);
  return (p.parent_path() / (p.stem().string() + ".q" + p.extension().string())).string();
}

LcpProblem read_lcp_matrix_market(const std::string& m_path, const std::string& q_path) {
  const std::string shown = io_text::valid_utf8(m_path);
  std::string qp = q_path;
  if (qp.empty()) {
    qp = matrix_market_q_path(m_path);
    std::error_code ec;
    if (!fs::exists(qp, ec))
      throw InputError(shown + ": a Matrix Market file holds M only; q is read from " +
                       io_text::valid_utf8(qp) + " beside it, which does not exist (give q with "
                       "--q FILE, or write a JSON file {\"M_mtx\": \"M.mtx\", \"q_mtx\": \"q.mtx\"})");
  }
  LcpProblem p;
  p.M_sparse = read_matrix_market(m_path);
  p.q = read_matrix_market_vector(qp);
  p.name = io_text::valid_utf8(fs::path(m_path).stem().string());
  throw_if_invalid(p.validate(), shown + " with q from " + io_text::valid_utf8(qp));
  return p;
}

LcpProblem read_lcp_file(const std::string& path, const std::string& q_path) {
  const auto ext = lower_extension(path);
  if (ext == ".mtx") return read_lcp_matrix_market(path, q_path);
  if (ext == ".npy") return read_lcp_npy(path, q_path);
  const std::string shown = io_text::valid_utf8(path);
  if (!q_path.empty() && (ext == ".json" || ext == ".dat"))
    throw InputError(shown + ": a separate q file is only read with a Matrix Market (.mtx) or "
                             "numpy (.npy) M; this file holds q itself");
  if (ext == ".json") return read_lcp_json(path);
  if (ext == ".dat") return read_lcp_dat(path);
  throw InputError(shown + ": unknown file type '" + io_text::valid_utf8(ext) +
                   "' (expected .json, .dat, .mtx or .npy)");
}

}  // namespace cpkit
