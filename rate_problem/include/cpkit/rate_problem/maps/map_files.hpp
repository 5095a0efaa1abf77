#pragma once
/// \file map_files.hpp
/// The files of a map under an output PREFIX (docs/maps.md, "Files"): a text file written
/// atomically, and the cell files of a grid map (PREFIX_<key>.npy arrays appended block by
/// block while the cells are computed, or one PREFIX.csv), each recorded in a JSON object of
/// file names relative to PREFIX's folder. Nothing that looks complete stays behind a map that
/// fails: every file is NAME.partial until it is complete.
#include <cstdint>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cpkit/rate_problem/maps/npy_writer.hpp"

namespace cpkit::rate {

/// Writes a text file through fn, under a temporary name renamed at the end (atomic); throws
/// InputError naming the file when it cannot be written.
void write_text_file(const std::string& path, const std::function<void(std::ostream&)>& fn);

/// The cell files of a grid map under PREFIX: .npy arrays appended block by block (or one CSV),
/// each recorded in `files` under its key (file names relative to PREFIX's folder). Files are
/// written as NAME.partial and renamed by finish(); a map that fails part-way calls discard():
/// no file that looks complete stays behind.
class GridFiles {
 public:
  GridFiles(std::string prefix, nlohmann::json& files);
  /// PREFIX_<key>.npy, rows x cols items of item_bytes (descr "|i1", "|u1", "<u2").
  void add_npy(const std::string& key, const char* descr, int64_t rows, int64_t cols,
               int item_bytes = 1);
  /// PREFIX_<key>.npy written at once (axis values).
  void write_vector(const std::string& key, const std::vector<double>& v);
  /// PREFIX.csv, opened for writing.
  std::ostream& open_csv();
  bool has_csv() const { return csv_.is_open(); }
  std::ostream& csv() { return csv_; }
  /// Appends `cells` items of each array to the .npy files in the order they were added
  /// (nullptr entries are skipped).
  void append(std::initializer_list<const void*> arrays, int64_t cells);
  void finish();
  void discard();

 private:
  std::string prefix_, name_;
  nlohmann::json& files_;
  std::vector<std::unique_ptr<NpyWriter>> npy_;
  std::ofstream csv_;
  std::vector<std::string> finals_;  ///< final paths, written as <path>.partial until finish()
  std::string partial(const std::string& final_path);
};

}  // namespace cpkit::rate
