// The files of a map (maps/map_files.hpp), moved out of the program: every file is written as
// <name>.partial and renamed when complete, so a map that stops part-way (an error, a killed
// job) never leaves a file that looks complete.
#include "cpkit/rate_problem/maps/map_files.hpp"

#include <filesystem>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/maps/map_output.hpp"

namespace cpkit::rate {

namespace fs = std::filesystem;

void write_text_file(const std::string& path, const std::function<void(std::ostream&)>& fn) {
  // Written under a temporary name and renamed: a reader never sees a half-written file.
  const std::string tmp = path + ".partial";
  {
    std::ofstream f(tmp);
    if (!f) throw InputError("cannot write '" + path + "'");
    fn(f);
    f.close();
    if (!f) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw InputError("error writing '" + path + "' (disk full?)");
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw InputError("cannot write '" + path + "': " + ec.message());
}

GridFiles::GridFiles(std::string prefix, nlohmann::json& files)
    : prefix_(std::move(prefix)), name_(fs::path(prefix_).filename().string()), files_(files) {}

// Every file is written as <name>.partial and renamed by finish(): a map that stops part-way
// (an error, a killed job) never leaves a file that looks complete.
std::string GridFiles::partial(const std::string& final_path) {
  finals_.push_back(final_path);
  return final_path + ".partial";
}

void GridFiles::add_npy(const std::string& key, const char* descr, int64_t rows, int64_t cols,
                        int item_bytes) {
  npy_.push_back(std::make_unique<NpyWriter>(partial(prefix_ + "_" + key + ".npy"), descr,
                                                   std::vector<int64_t>{rows, cols}, item_bytes));
  files_[key] = name_ + "_" + key + ".npy";
}

void GridFiles::write_vector(const std::string& key, const std::vector<double>& v) {
  files_[key] = name_ + "_" + key + ".npy";
  write_npy_vector(partial(prefix_ + "_" + key + ".npy"), v);
}

std::ostream& GridFiles::open_csv() {
  csv_.open(partial(prefix_ + ".csv"));
  if (!csv_) throw InputError("cannot write '" + prefix_ + ".csv'");
  files_["csv"] = name_ + ".csv";
  return csv_;
}

void GridFiles::append(std::initializer_list<const void*> arrays, int64_t cells) {
  std::size_t k = 0;
  for (const void* p : arrays)
    if (p && k < npy_.size()) npy_[k++]->append(p, cells);
}

void GridFiles::finish() {
  for (auto& w : npy_) w->finish();
  if (csv_.is_open()) {
    csv_.close();
    if (!csv_) throw InputError("error writing '" + prefix_ + ".csv' (disk full?)");
  }
  for (const auto& f : finals_) {
    std::error_code ec;
    fs::rename(f + ".partial", f, ec);
    if (ec) throw InputError("cannot write '" + f + "': " + ec.message());
  }
  finals_.clear();
}

void GridFiles::discard() {
  npy_.clear();
  if (csv_.is_open()) csv_.close();
  for (const auto& f : finals_) {
    std::error_code ec;
    fs::remove(f + ".partial", ec);
  }
  finals_.clear();
}

ParamDirectionSink param_direction_files(GridFiles& out, const MapAxis& axis,
                                         const std::vector<double>& theta, bool npy, bool csv,
                                         bool cross) {
  auto opened = std::make_shared<bool>(false);
  return [&out, axis, theta, npy, csv, cross, opened](const ParamDirectionRows& r) {
    const int64_t cols = static_cast<int64_t>(theta.size());
    if (!*opened) {
      if (npy) {
        out.add_npy("count", "|i1", axis.n, cols);
        out.add_npy("types", "|u1", axis.n, cols);
        if (cross) out.add_npy("disagree", "|u1", axis.n, cols);
        out.write_vector("x", axis_values(axis));
        out.write_vector("theta", theta);
      } else if (csv) {
        write_csv_header(axis, cross, out.open_csv());
      }
      *opened = true;
    }
    out.append({r.count, r.types, r.disagree}, (r.row_end - r.row_begin) * cols);
    if (out.has_csv()) write_csv_rows(axis, theta, r, out.csv());
  };
}

ParamParamSink param_param_files(GridFiles& out, const MapAxis& axis1, const MapAxis& axis2,
                                 bool npy, bool csv, bool cross) {
  auto opened = std::make_shared<bool>(false);
  return [&out, axis1, axis2, npy, csv, cross, opened](const ParamParamRows& r) {
    if (!*opened) {
      if (npy) {
        out.add_npy("class", "|u1", axis1.n, axis2.n);
        out.add_npy("min_count", "|i1", axis1.n, axis2.n);
        out.add_npy("max_count", "|i1", axis1.n, axis2.n);
        out.add_npy("types", "|u1", axis1.n, axis2.n);
        if (cross) out.add_npy("disagree", "|u1", axis1.n, axis2.n);
        out.write_vector("x", axis_values(axis1));
        out.write_vector("y", axis_values(axis2));
      } else if (csv) {
        write_csv_header(axis1, axis2, cross, out.open_csv());
      }
      *opened = true;
    }
    out.append({r.cls, r.min_count, r.max_count, r.types, r.disagree},
               static_cast<int64_t>(r.row_end - r.row_begin) * axis2.n);
    if (out.has_csv()) write_csv_rows(axis1, axis2, r, out.csv());
  };
}

SystemParamDirectionSink system_param_direction_files(GridFiles& out, const SystemMapAxis& axis,
                                                      const std::vector<double>& theta,
                                                      bool npy, bool csv) {
  auto opened = std::make_shared<bool>(false);
  return [&out, axis, theta, npy, csv, opened](const SystemParamDirectionRows& r) {
    const int64_t cols = static_cast<int64_t>(theta.size());
    if (!*opened) {
      if (npy) {
        out.add_npy("count", "|i1", axis.n, cols);
        out.add_npy("pattern", "<u2", axis.n, cols, 2);
        out.write_vector("x", axis_values(axis));
        out.write_vector("theta", theta);
      } else if (csv) {
        write_system_csv_header(axis, out.open_csv());
      }
      *opened = true;
    }
    out.append({r.count, r.pattern}, (r.row_end - r.row_begin) * cols);
    if (out.has_csv()) write_system_csv_rows(axis, theta, r, out.csv());
  };
}

SystemParamParamSink system_param_param_files(GridFiles& out, const SystemMapAxis& axis1,
                                              const SystemMapAxis& axis2, bool npy, bool csv) {
  auto opened = std::make_shared<bool>(false);
  return [&out, axis1, axis2, npy, csv, opened](const SystemParamParamRows& r) {
    if (!*opened) {
      if (npy) {
        out.add_npy("class", "|u1", axis1.n, axis2.n);
        out.add_npy("min_count", "|i1", axis1.n, axis2.n);
        out.add_npy("max_count", "|i1", axis1.n, axis2.n);
        out.add_npy("pattern", "<u2", axis1.n, axis2.n, 2);
        out.write_vector("x", axis_values(axis1));
        out.write_vector("y", axis_values(axis2));
      } else if (csv) {
        write_system_csv_header(axis1, axis2, out.open_csv());
      }
      *opened = true;
    }
    out.append({r.cls, r.min_count, r.max_count, r.pattern},
               static_cast<int64_t>(r.row_end - r.row_begin) * axis2.n);
    if (out.has_csv()) write_system_csv_rows(axis1, axis2, r, out.csv());
  };
}

}  // namespace cpkit::rate
