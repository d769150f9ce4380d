#include "app/parse_error_hint.h"

#include <fmt/format.h>

#include <charconv>
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

std::string conversionHint(const CLI::App& app, const std::string& message) {
  constexpr std::string_view kPrefix = "Could not convert: ";
  const std::size_t equals = message.find(" = ");
  if (!message.starts_with(kPrefix) || equals == std::string::npos) return "";
  const std::string name = message.substr(kPrefix.size(), equals - kPrefix.size());
  const CLI::App* deepest = &app;
  while (!deepest->get_subcommands().empty()) deepest = deepest->get_subcommands().front();
  const CLI::Option* option = deepest->get_option_no_throw(name);
  if (option == nullptr) return "";
  const std::string type = option->get_type_name();
  if (type == "INT") return fmt::format(" ({} takes a whole number written out, such as 1000)", name);
  if (type == "UINT") return fmt::format(" ({} takes a whole number from 0 to 4294967295, written out)", name);
  return "";
}

namespace {

// The text without one leading '+', as from_chars reads no sign but '-'.
std::string_view unsigned_(const std::string& text) {
  return text.starts_with('+') ? std::string_view(text).substr(1) : std::string_view(text);
}

}  // namespace

CLI::Validator decimalNumber(bool numberLike) {
  return CLI::Validator(
      [numberLike](std::string& text) -> std::string {
        const std::string_view digits = unsigned_(text);
        if (numberLike && !digits.empty() && std::string_view("0123456789.-").find(digits.front()) == std::string_view::npos)
          return "";  // a word: the option's own to take or refuse
        double value = 0.0;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (!digits.empty() && ec == std::errc() && end == digits.data() + digits.size()) return "";
        return fmt::format("'{}' is not a decimal number (such as 6500, -2.5 or 1e-3)", text);
      },
      "");
}

// Whole numbers in base 10: CLI11 read "0x40" as 64 and "0b11" as 3 (its range errors still apply).
CLI::Validator decimalWholeNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::string_view digits = unsigned_(text);
        long long value = 0;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (!digits.empty() && ec != std::errc::invalid_argument && end == digits.data() + digits.size()) return "";
        return fmt::format("'{}' is not a whole number written out in decimal (such as 1000)", text);
      },
      "");
}

void requireDecimalNumbers(CLI::App& app, const std::function<bool(const CLI::Option*)>& parsedByPrism) {
  const CLI::Validator decimal = decimalNumber();
  const CLI::Validator whole = decimalWholeNumber();
  for (CLI::Option* option : app.get_options()) {
    if (parsedByPrism(option)) continue;
    const std::string type = option->get_type_name();
    if (type == "FLOAT") option->check(decimal);
    if (type == "INT" || type == "UINT") option->check(whole);
  }
  for (CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) requireDecimalNumbers(*sub, parsedByPrism);
}

}  // namespace prism::app
