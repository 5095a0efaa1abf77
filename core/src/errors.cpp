#include "cpkit/core/errors.hpp"

#include <algorithm>
#include <cctype>

#include "cpkit/core/option_words.hpp"

namespace cpkit {

void throw_if_invalid(const std::string& message, const std::string& context) {
  if (message.empty()) return;
  throw InputError(context.empty() ? message : context + ": " + message);
}

std::string in_option_words(std::string message,
                            const std::vector<std::pair<std::string, std::string>>& field_to_option) {
  auto table = field_to_option;
  std::sort(table.begin(), table.end(),
            [](const auto& x, const auto& y) { return x.first.size() > y.first.size(); });
  auto word_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ':' || c == '-';
  };
  for (const auto& [field, option] : table) {
    for (std::size_t at = message.find(field); at != std::string::npos;
         at = message.find(field, at)) {
      const std::size_t end = at + field.size();
      const bool whole = (at == 0 || !word_char(message[at - 1])) &&
                         (end == message.size() || !word_char(message[end]));
      if (whole) {
        message.replace(at, field.size(), option);
        at += option.size();
      } else {
        at = end;
      }
    }
  }
  return message;
}

void throw_if_invalid_option(const std::string& message,
                             const std::vector<std::pair<std::string, std::string>>& field_to_option) {
  if (!message.empty()) throw InputError(in_option_words(message, field_to_option));
}

}  // namespace cpkit
