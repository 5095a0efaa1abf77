#pragma once
/// \file option_words.hpp
/// A library validation message in the words of the user who gave the values: options structs
/// name their fields (`EnumerationOptions::max_size must be ...`), the program and the request
/// functions (cpkit/lcp/lcp_request.hpp) report the option the user typed (`--max-size`).
#include <string>
#include <utility>
#include <vector>

namespace cpkit {

/// Every whole-word occurrence of a C++ field name (`EnumerationOptions::max_size`,
/// `time_limit_s`) in `message` replaced by its option (`--max-size`, `--time-limit`); longer
/// names are replaced first.
std::string in_option_words(std::string message,
                            const std::vector<std::pair<std::string, std::string>>& field_to_option);

/// Throws InputError with in_option_words(message) when `message` is not empty (errors.hpp).
void throw_if_invalid_option(const std::string& message,
                             const std::vector<std::pair<std::string, std::string>>& field_to_option);

}  // namespace cpkit
