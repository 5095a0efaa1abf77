// NumPy .npy writer (format 1.0), see npy_writer.hpp.
#include "cpkit/rate_problem/maps/npy_writer.hpp"

#include <cstring>

#include "cpkit/core/errors.hpp"

namespace cpkit::rate {

std::string npy_header(const std::string& descr, const std::vector<int64_t>& shape) {
  std::string dict = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': (";
  for (std::size_t k = 0; k < shape.size(); ++k)
    dict += std::to_string(shape[k]) + (shape.size() == 1 || k + 1 < shape.size() ? ", " : "");
  if (shape.size() == 1) dict.pop_back();  // "(n,)"
  dict += "), }";
  // magic (6) + version (2) + length (2) + dict + padding + '\n' = multiple of 64.
  std::size_t total = 10 + dict.size() + 1;
  total = (total + 63) / 64 * 64;
  const std::size_t len = total - 10;
  dict.append(len - dict.size() - 1, ' ');
  dict += '\n';
  std::string h = "\x93NUMPY";
  h += '\x01';
  h += '\x00';
  h += static_cast<char>(len & 0xff);
  h += static_cast<char>((len >> 8) & 0xff);
  return h + dict;
}

NpyWriter::NpyWriter(std::string path, const std::string& descr,
                     const std::vector<int64_t>& shape, int item_bytes)
    : path_(std::move(path)), item_bytes_(item_bytes) {
  expected_ = 1;
  for (const int64_t s : shape) expected_ *= s;
  file_ = std::fopen(path_.c_str(), "wb");
  if (!file_) throw InputError("cannot write '" + path_ + "'");
  const std::string h = npy_header(descr, shape);
  if (std::fwrite(h.data(), 1, h.size(), file_) != h.size()) {
    std::fclose(file_);
    file_ = nullptr;
    throw InputError("error writing '" + path_ + "'");
  }
}

NpyWriter::~NpyWriter() {
  if (file_) std::fclose(file_);
}

void NpyWriter::append(const void* data, int64_t items) {
  if (!file_ || written_ + items > expected_)
    throw InputError("'" + path_ + "': more data than its shape holds (internal error)");
  const std::size_t bytes = static_cast<std::size_t>(items) * static_cast<std::size_t>(item_bytes_);
  if (std::fwrite(data, 1, bytes, file_) != bytes)
    throw InputError("error writing '" + path_ + "' (disk full?)");
  written_ += items;
}

void NpyWriter::finish() {
  if (!file_) return;
  const bool ok = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!ok) throw InputError("error writing '" + path_ + "' (disk full?)");
  if (written_ != expected_)
    throw InputError("'" + path_ + "': " + std::to_string(written_) + " of " +
                     std::to_string(expected_) + " items written (internal error)");
}

void write_npy_vector(const std::string& path, const std::vector<double>& v) {
  static_assert(sizeof(double) == 8, "float64");
  const uint16_t probe = 1;
  unsigned char first = 0;
  std::memcpy(&first, &probe, 1);
  NpyWriter w(path, first == 1 ? "<f8" : ">f8", {static_cast<int64_t>(v.size())}, 8);
  w.append(v.data(), static_cast<int64_t>(v.size()));
  w.finish();
}

}  // namespace cpkit::rate
