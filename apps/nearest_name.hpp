#pragma once
// "Did you mean ...?" for a mistyped option or subcommand name (CLI11 offers no suggestions).
#include <string>
#include <vector>

namespace cpkit::cli {

/// The name of `names` closest to `word` by edit distance (insertions, deletions, substitutions
/// and swaps of adjacent characters, case-insensitive), when it is close enough to be a typo:
/// at most 1 edit for words of up to 4 characters, 2 up to 8, 3 beyond. Empty otherwise, and
/// when two names are equally close (a guess between them would mislead).
std::string nearest_name(const std::string& word, const std::vector<std::string>& names);

}  // namespace cpkit::cli
