#pragma once
// Where the `cpkit` program finds its installed companions (the plotting scripts) and the
// Python that runs them.
#include <string>

namespace cpkit::cli {

/// The path of data file `name` (e.g. "cpkit_plot.py"), searched in this order:
///  1. `<directory of the running cpkit>/<bin-to-data>/name`, i.e. `PREFIX/share/cpkit/name`
///     for a cpkit installed to any prefix (`cmake --install build --prefix PREFIX`);
///  2. the source tree's `scripts/name` (a cpkit run from its build directory).
/// Empty when neither exists; `searched` then lists the places tried, for the message.
std::string find_data_file(const std::string& name, std::string* searched = nullptr);

/// The Python interpreter for the plotting scripts: $CPKIT_PYTHON, else /usr/bin/python3 (Debian's,
/// which sees python3-matplotlib), else `python3` from PATH.
std::string plot_python();

}  // namespace cpkit::cli
