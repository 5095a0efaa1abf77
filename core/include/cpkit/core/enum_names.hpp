#pragma once
/// \file enum_names.hpp
/// The text names of an enum as one table, read by both directions (to_string and the parser),
/// so that each name is written once. Within a table the first entry of a value is its name
/// (what to_string returns); further entries of the same value are aliases the parser also
/// accepts. Names are compared exactly (case-sensitive).
///
///     inline constexpr EnumName<WearLaw> kWearLawNames[] = {
///         {WearLaw::kArchard, "archard"}, {WearLaw::kArchard, "37"}, ...};
///     std::string_view to_string(WearLaw w) { return name_of(kWearLawNames, w); }
#include <cstddef>
#include <optional>
#include <string_view>

namespace cpkit {

/// One entry of a name table: a value and one of its names.
template <class E>
struct EnumName {
  E value;
  std::string_view name;
};

/// The name of `value`: its first entry in `table`; "unknown" when it has none.
template <class E, std::size_t N>
constexpr std::string_view name_of(const EnumName<E> (&table)[N], E value) noexcept {
  for (const EnumName<E>& e : table)
    if (e.value == value) return e.name;
  return "unknown";
}

/// The value that `name` (a name or an alias) names in `table`; std::nullopt when none does.
template <class E, std::size_t N>
constexpr std::optional<E> value_of(const EnumName<E> (&table)[N], std::string_view name) noexcept {
  for (const EnumName<E>& e : table)
    if (e.name == name) return e.value;
  return std::nullopt;
}

}  // namespace cpkit
