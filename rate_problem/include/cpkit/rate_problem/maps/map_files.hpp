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

#include "cpkit/rate_problem/maps/grid_map.hpp"
#include "cpkit/rate_problem/maps/npy_writer.hpp"
#include "cpkit/rate_problem/maps/system_grid_map.hpp"

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

/// The values of a map axis (MapAxis, SystemMapAxis: n and value(i)), for PREFIX_x.npy.
template <class Axis>
std::vector<double> axis_values(const Axis& ax) {
  std::vector<double> v(static_cast<std::size_t>(ax.n));
  for (int i = 0; i < ax.n; ++i) v[static_cast<std::size_t>(i)] = ax.value(i);
  return v;
}

/// The sinks that stream a grid map's rows (in row order) to its files under `out`: with
/// `npy`, one .npy array per cell field (docs/maps.md, "Files") and the axis values (x, and
/// theta or y); with `csv`, PREFIX.csv (header, one line per cell, 17 digits); with neither,
/// nothing. The files are opened at the first rows (on the rank that writes). `cross`: the map
/// is cross-checked (analytic route): a "disagree" array / CSV column.
/// One point, parameter x direction: count (|i1), types (|u1), disagree (|u1), x, theta.
ParamDirectionSink param_direction_files(GridFiles& out, const MapAxis& axis,
                                         const std::vector<double>& theta, bool npy, bool csv,
                                         bool cross);
/// One point, parameter x parameter: class, min_count, max_count, types, disagree, x, y.
ParamParamSink param_param_files(GridFiles& out, const MapAxis& axis1, const MapAxis& axis2,
                                 bool npy, bool csv, bool cross);
/// N points, parameter x direction: count (|i1), pattern (<u2), x, theta.
SystemParamDirectionSink system_param_direction_files(GridFiles& out, const SystemMapAxis& axis,
                                                      const std::vector<double>& theta,
                                                      bool npy, bool csv);
/// N points, parameter x parameter: class, min_count, max_count, pattern, x, y.
SystemParamParamSink system_param_param_files(GridFiles& out, const SystemMapAxis& axis1,
                                              const SystemMapAxis& axis2, bool npy, bool csv);

}  // namespace cpkit::rate
