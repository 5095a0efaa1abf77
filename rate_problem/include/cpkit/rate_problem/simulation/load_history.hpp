#pragma once
/// \file load_history.hpp
/// Load histories (t, F_T, F_N) for the quasi-static simulation (simulation.hpp,
/// docs/simulation.md): a CSV file, a built-in fretting cycle, or a ramp. The simulation starts
/// from the unloaded grazing state (F = 0, P = 0, w = 0) and takes one step to every point.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace cpkit::rate {

struct LoadPoint {
  double t = 0, F_T = 0, F_N = 0;
};

struct LoadHistory {
  std::vector<LoadPoint> points;  ///< t strictly increasing, values finite
  double period = 0;              ///< > 0: cycle length in t (slip/wear per cycle are reported)
  double cycle_start = 0;         ///< t at which cycle 0 begins
  /// Empty when usable; else names the first bad row.
  std::string validate() const;
};

/// What one line of a load CSV holds (parse_csv_row).
enum class CsvRow { kBlank, kNumbers, kHeader };

/// The numbers of one line of a load CSV (`,`, `;`, tabs or spaces between them; `#` starts a
/// comment), each parsed as a strict decimal (core/number_text.hpp: no hexadecimal `0x10`, no
/// nan/inf, and `1e400` or `1e-400`, which do not fit a double, refused). kHeader when
/// `header_allowed` and no token starts like a number (a line `t, F_T, F_N`). Anything else is an
/// InputError "where: ..." naming the token.
CsvRow parse_csv_row(const std::string& line, bool header_allowed, const std::string& where,
                     std::vector<double>& out);

/// Calls `row(values, where)` for every line of numbers of a load CSV `text` (blank lines and
/// comments skipped, one header line allowed before the first numbers; `where` is
/// "origin:line" for messages). The one loop of the one-point and N-point load readers.
void for_each_csv_row(const std::string& text, const std::string& origin,
                      const std::function<void(const std::vector<double>&, const std::string&)>& row);

/// CSV with columns t, F_T, F_N (a header line naming them is optional; '#' starts a comment;
/// numbers as parse_csv_row reads them). Throws InputError naming the file and line for
/// malformed input.
LoadHistory read_load_csv(const std::string& path);
LoadHistory parse_load_csv(const std::string& text, const std::string& origin = "<string>");

/// Constant normal load F_N (reached by a linear ramp over ramp_steps steps with F_T = 0) plus
/// F_T = amplitude sin(2 pi (t - t_ramp) / period) for `cycles` cycles of `steps_per_cycle`
/// steps each; the ramp takes one period / steps_per_cycle per step.
struct FrettingCycle {
  double F_N = 1;
  double amplitude = 0.1;
  double period = 1;
  int cycles = 10;
  int steps_per_cycle = 100;
  int ramp_steps = 10;
  std::string validate() const;
};
LoadHistory fretting_history(const FrettingCycle& cycle);

/// Linear ramp from (F_T0, F_N0) to (F_T1, F_N1) in `steps` steps over `duration`; when the
/// start is not zero a first step goes from the unloaded state to it.
struct LoadRamp {
  double F_T0 = 0, F_N0 = 0, F_T1 = 0, F_N1 = 1;
  double duration = 1;
  int steps = 100;
  std::string validate() const;
};
LoadHistory ramp_history(const LoadRamp& ramp);

/// A load produced point by point (memory independent of its length): `at(k)` for
/// k = 0 .. size - 1 returns the same points as a stored history would hold. A march reads each
/// point once, in order. One type for every march, by its load point: LoadSource (one 2-D
/// point), SystemLoadSource (N points, system_simulation.hpp), LoadSource3d (3-D fretting,
/// fretting_3d.hpp).
template <class Point>
struct LoadSourceOf {
  std::size_t size = 0;
  std::function<Point(std::size_t)> at;
  double period = 0;       ///< as LoadHistory::period (> 0: per-cycle sums are reported)
  double cycle_start = 0;  ///< as LoadHistory::cycle_start (t at which cycle 0 begins)
};
using LoadSource = LoadSourceOf<LoadPoint>;
/// A view of a stored history (which must outlive the source).
LoadSource history_source(const LoadHistory& history);
/// The fretting cycle / ramp generated on the fly (the points of fretting_history /
/// ramp_history, computed by the same formulas). Throw InputError for invalid settings.
LoadSource fretting_source(const FrettingCycle& cycle);
LoadSource ramp_source(const LoadRamp& ramp);

}  // namespace cpkit::rate
