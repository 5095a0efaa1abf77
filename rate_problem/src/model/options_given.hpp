#pragma once
// Internal: the options a request was given, checked the same way by every request (rate,
// step, map): an option that would have no effect is refused, a required one demanded, each by
// its name as the program spells it. In model/, the lowest layer that knows ModelOptions, so
// that maps/ (below requests/) reads the same type.
#include <optional>
#include <string>
#include <vector>

#include "cpkit/core/errors.hpp"
#include "cpkit/rate_problem/model/model_options.hpp"

namespace cpkit::rate::detail {

/// An option's name in messages (with its "--") and whether the request gave it.
struct Given {
  const char* name;
  bool given;
};

template <class T>
Given option(const char* name, const std::optional<T>& value) {
  return {name, value.has_value()};
}

/// InputError "<the first of `options` given><why>" when one was given.
inline void refuse_given(const std::vector<Given>& options, const std::string& why) {
  for (const Given& o : options)
    if (o.given) throw InputError(o.name + why);
}

/// InputError "<the first of `options` missing><why>" when one is missing.
inline void require_given(const std::vector<Given>& options, const std::string& why) {
  for (const Given& o : options)
    if (!o.given) throw InputError(o.name + why);
}

/// The one-point model options, in the order their refusals name the first one given.
inline std::vector<Given> model_options_given(const ModelOptions& m) {
  return {option("--a11", m.a11), option("--a12", m.a12), option("--a22", m.a22),
          option("--mu", m.mu),   option("--C_T", m.C_T), option("--k_a", m.k_a),
          option("--P_s", m.P_s), option("--criterion", m.criterion)};
}

}  // namespace cpkit::rate::detail
