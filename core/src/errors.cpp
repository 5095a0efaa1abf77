#include "cpkit/core/errors.hpp"

namespace cpkit {

void throw_if_invalid(const std::string& message, const std::string& context) {
  if (message.empty()) return;
  throw InputError(context.empty() ? message : context + ": " + message);
}

}  // namespace cpkit
