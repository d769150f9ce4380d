#include "app/parse_error_hint.h"

#include <fmt/format.h>

#include <string_view>

namespace prism::app {

std::string switchValueHint(int argc, char** argv, const std::vector<std::string>& extras) {
  if (extras.empty() || (extras.front() != "on" && extras.front() != "off")) return "";
  for (int i = 2; i < argc; ++i) {
    const std::string_view flag = argv[i - 1];
    if (argv[i] == extras.front() && flag.starts_with("--") && flag.find('=') == std::string_view::npos)
      return fmt::format(" ({} is a switch: write {}={})", flag, flag, extras.front());
  }
  return "";
}

std::string subcommandHint(const CLI::App& app) {
  const CLI::App* deepest = &app;
  std::string command = "prism";
  while (!deepest->get_subcommands().empty()) {
    deepest = deepest->get_subcommands().front();
    command += " " + deepest->get_name();
  }
  std::vector<std::string> names;
  for (const CLI::App* sub : deepest->get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
  if (names.empty()) return "";
  return fmt::format(": {} takes {} (see {} --help)", command, fmt::join(names, ", "), command);
}

}  // namespace prism::app
