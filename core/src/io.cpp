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

/// The formats read_lcp_file knows.
enum class Format { kJson, kDat, kMatrixMarket, kNpy, kUnknown };

/// The format of a file without an extension (a pipe such as `<(cat f.json)`), from its first
/// bytes: the .npy magic, the Matrix Market banner, '{' (JSON), or what a Siconos .dat starts
/// with (a number or a '#' comment).
Format sniff_format(const std::string& text) {
  if (text.rfind("\x93NUMPY", 0) == 0) return Format::kNpy;
  if (text.rfind("%%MatrixMarket", 0) == 0) return Format::kMatrixMarket;
  const auto first = text.find_first_not_of(" \t\r\n\v\f");
  if (first == std::string::npos) return Format::kUnknown;
  const char c = text[first];
  if (c == '{') return Format::kJson;
  if (c == '#' || c == '+' || c == '-' || (c >= '0' && c <= '9')) return Format::kDat;
  return Format::kUnknown;
}

/// The q file of a Matrix Market or .npy M: `q_path`, or the one beside M (`what` names M's
/// format in the message when it does not exist).
std::string q_file_for(const std::string& m_path, const std::string& q_path, const char* what) {
  if (!q_path.empty()) return q_path;
  const std::string qp = matrix_market_q_path(m_path);
  std::error_code ec;
  if (!fs::exists(qp, ec))
    throw InputError(io_text::valid_utf8(m_path) + ": " + what + " holds M only; q is read from " +
                     io_text::valid_utf8(qp) + " beside it, which does not exist (give q with "
                     "--q FILE" + (std::string(what) == "a Matrix Market file"
                                       ? ", or write a JSON file {\"M_mtx\": \"M.mtx\", \"q_mtx\": \"q.mtx\"})"
                                       : ")"));
  return qp;
}

/// A file without an extension: read once and parsed by the format of its content.
LcpProblem read_lcp_sniffed(const std::string& path, const std::string& q_path) {
  const std::string shown = io_text::valid_utf8(path);
  const std::string text = io_text::read_text(path);
  const Format f = sniff_format(text);
  if (!q_path.empty() && (f == Format::kJson || f == Format::kDat))
    throw InputError(shown + ": a separate q file is only read with a Matrix Market or numpy M; "
                             "this file (" + (f == Format::kJson ? "JSON" : "Siconos .dat") +
                             ", told by its content) holds q itself");
  switch (f) {
    case Format::kJson:
      return parse_lcp_json(text, path);
    case Format::kDat:
      return parse_lcp_dat(text, path);
    case Format::kMatrixMarket: {
      const std::string qp = q_file_for(path, q_path, "a Matrix Market file");
      LcpProblem p;
      p.M_sparse = parse_matrix_market(text, path);
      p.q = read_matrix_market_vector(qp);
      p.name = io_text::valid_utf8(fs::path(path).stem().string());
      throw_if_invalid(p.validate(), shown + " with q from " + io_text::valid_utf8(qp));
      return p;
    }
    case Format::kNpy: {
      const std::string qp = q_file_for(path, q_path, "a .npy file");
      LcpProblem p;
      p.M = parse_npy_matrix(text, path);
      if (p.M.rows() != p.M.cols())
        throw InputError(shown + ": M has shape (" + std::to_string(p.M.rows()) + ", " +
                         std::to_string(p.M.cols()) + "); an LCP needs a square M");
      p.q = parse_npy_vector(io_text::read_text(qp), qp);
      if (p.q.size() != p.M.rows())
        throw InputError(io_text::valid_utf8(qp) + ": q has " + std::to_string(p.q.size()) +
                         " entries but M (" + shown + ") is " + std::to_string(p.M.rows()) +
                         " x " + std::to_string(p.M.cols()));
      p.name = io_text::valid_utf8(fs::path(path).stem().string());
      throw_if_invalid(p.validate(), shown + " with q from " + io_text::valid_utf8(qp));
      return p;
    }
    case Format::kUnknown:
      break;
  }
  throw InputError(shown + ": no extension, and the content is not a known problem format (JSON "
                           "starts with '{', Matrix Market with %%MatrixMarket, .npy with its "
                           "magic \\x93NUMPY, Siconos .dat with a number or a '#' comment)");
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
  if (ext.empty()) return read_lcp_sniffed(path, q_path);  // e.g. <(cat f.json): by content
  throw InputError(shown + ": unknown file type '" + io_text::valid_utf8(ext) +
                   "' (expected .json, .dat, .mtx or .npy, or no extension: then the format is told by the "
                   "content)");
}

}  // namespace cpkit
