#include "run_echo.hpp"

#include <cmath>
#include <cstdlib>

namespace cpkit::cli {
namespace {

const CLI::App* g_app = nullptr;
std::vector<std::string> g_args;

nlohmann::json value_json(const std::string& v) {
  if (v == "true") return true;  // a flag
  if (v == "false") return false;
  if (!v.empty()) {
    char* end = nullptr;
    const double d = std::strtod(v.c_str(), &end);
    if (end == v.c_str() + v.size() && std::isfinite(d) && v.find_first_of("xX") == std::string::npos) {
      if (d == std::floor(d) && std::abs(d) < 9.0e15) return static_cast<long long>(d);
      return d;
    }
  }
  return v;
}

void add_options(const CLI::App& app, nlohmann::json& out) {
  for (const CLI::Option* o : app.get_options()) {
    const std::string name = o->get_name();
    if (name == "--help" || name == "-h" || name == "--version" || name == "--list-presets")
      continue;
    const std::string key = o->get_lnames().empty() ? name : o->get_lnames().front();
    if (o->get_type_size_max() == 0) {  // a flag
      out[key] = o->count() > 0;
      continue;
    }
    std::vector<std::string> values = o->results();
    if (o->count() == 0) {
      const std::string d = o->get_default_str();
      if (d.empty() || d == "[]") continue;  // no default: the option was not used
      values = {d};
    }
    if (values.size() == 1) {
      out[key] = value_json(values.front());
    } else {
      nlohmann::json arr = nlohmann::json::array();
      for (const auto& v : values) arr.push_back(value_json(v));
      out[key] = arr;
    }
  }
}

}  // namespace

void remember_command_line(const CLI::App& app, const std::vector<std::string>& args) {
  g_app = &app;
  g_args = args;
}

nlohmann::json run_echo() {
  nlohmann::json j;
  j["cpkit_version"] = CPKIT_VERSION;
  j["command"] = g_args;
  nlohmann::json options = nlohmann::json::object();
  // The chain of subcommands being run (cpkit lcp solve: lcp, then solve); options of each.
  for (const CLI::App* a = g_app; a != nullptr;) {
    const auto subs = a->get_subcommands();
    if (subs.empty()) break;
    a = subs.front();
    add_options(*a, options);
  }
  j["options"] = options;
  return j;
}

}  // namespace cpkit::cli
