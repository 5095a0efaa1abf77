#pragma once
/// \file npy_writer.hpp
/// Writes a NumPy .npy file (format version 1.0) in pieces: the header with the final shape
/// first, then the C-order data appended block by block, so a grid map is written while its
/// cells are computed. Format: magic "\x93NUMPY", version 1.0, a little-endian uint16 header
/// length, then a Python dict literal {'descr', 'fortran_order', 'shape'} padded with spaces and
/// a final '\n' so that the data starts at a multiple of 64 bytes
/// (https://numpy.org/doc/stable/reference/generated/numpy.lib.format.html).
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace cpkit::rate {

/// The complete header of an .npy file for `descr` ("|i1", "|u1", "<f8") and `shape`.
std::string npy_header(const std::string& descr, const std::vector<int64_t>& shape);

class NpyWriter {
 public:
  /// Creates `path` and writes the header. Throws InputError when the file cannot be written.
  NpyWriter(std::string path, const std::string& descr, const std::vector<int64_t>& shape,
            int item_bytes);
  ~NpyWriter();
  NpyWriter(const NpyWriter&) = delete;
  NpyWriter& operator=(const NpyWriter&) = delete;

  /// Appends `items` items (item_bytes each, host byte order: little-endian machines only for
  /// multi-byte items). Throws InputError on a write error or when more than the shape holds.
  void append(const void* data, int64_t items);
  /// Flushes and closes; throws InputError unless exactly the shape's item count was written.
  void finish();

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  int64_t expected_ = 0, written_ = 0;
  int item_bytes_ = 1;
};

/// Writes a whole float64 vector as a 1-D .npy file.
void write_npy_vector(const std::string& path, const std::vector<double>& v);

}  // namespace cpkit::rate
