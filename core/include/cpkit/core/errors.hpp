#pragma once
/// \file errors.hpp
/// Misuse (bad sizes, NaN/Inf, invalid options, malformed files) throws before any work.
/// An algorithmic outcome is never an exception: it is a Status.
#include <stdexcept>
#include <string>

namespace cpkit {

/// Bad input: the message names the problem (field, file and line where known).
class InputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// Throws InputError(context + ": " + message) when message is non-empty (the validate() idiom).
void throw_if_invalid(const std::string& message, const std::string& context = {});

}  // namespace cpkit
