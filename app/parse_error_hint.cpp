#include "app/parse_error_hint.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <string_view>
#include <utility>
#include <vector>

#include "render/setting_keys.h"

namespace prism::app {

namespace {

// The command the line ran (its deepest subcommand) and its words: "prism wavelengths optimise".
std::pair<const CLI::App*, std::string> deepestCommand(const CLI::App& app) {
  const CLI::App* deepest = &app;
  std::string command = "prism";
  while (!deepest->get_subcommands().empty()) {
    deepest = deepest->get_subcommands().front();
    command += " " + deepest->get_name();
  }
  return {deepest, command};
}

// Levenshtein distance, for names a few letters long.
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// The option of `command` nearest to `given` ("--widht" → "--width"), if within two edits.
std::string nearestOption(const CLI::App& command, std::string_view given) {
  std::string best;
  std::size_t bestDistance = 3;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames()) {
      const std::size_t d = editDistance(given, "--" + name);
      if (d < bestDistance) {
        bestDistance = d;
        best = "--" + name;
      }
    }
  }
  return best;
}

}  // namespace

std::string unexpectedArgumentsMessage(const CLI::App& app, int argc, char** argv, const std::vector<std::string>& extras) {
  std::vector<std::string> ordered;  // as given: CLI11 hands them over last first
  std::vector<std::string> left = extras;
  for (int i = 1; i < argc; ++i) {
    auto it = std::find(left.begin(), left.end(), std::string(argv[i]));
    if (it == left.end()) continue;
    ordered.push_back(*it);
    left.erase(it);
  }
  ordered.insert(ordered.end(), left.begin(), left.end());
  const auto [command, name] = deepestCommand(app);
  for (const std::string& word : ordered) {
    if (!word.starts_with("--") || word.size() == 2) continue;
    const std::string option = word.substr(0, word.find('='));
    const std::string nearest = nearestOption(*command, option);
    // Its own option, given before the command's name (`prism --width 64 render …`).
    if (nearest == option) return fmt::format("{} is an option of {}: give it after `{}`", option, name, command->get_name());
    return fmt::format("unknown option {} for {} ({})", option, name,
                       nearest.empty() ? fmt::format("see {} --help", name) : fmt::format("did you mean {}?", nearest));
  }
  std::string message = fmt::format("The following argument{} not expected: {}", ordered.size() == 1 ? " was" : "s were",
                                    fmt::join(ordered, " "));
  if (!ordered.empty() && (ordered.front() == "on" || ordered.front() == "off")) {
    for (int i = 2; i < argc; ++i) {
      const std::string_view flag = argv[i - 1];
      if (argv[i] == ordered.front() && flag.starts_with("--") && flag.find('=') == std::string_view::npos)
        return message + fmt::format(" ({} is a switch: write {}={})", flag, flag, ordered.front());
    }
  }
  return message;
}

std::string subcommandHint(const CLI::App& app) {
  const auto [deepest, command] = deepestCommand(app);
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
  const CLI::Option* option = deepestCommand(app).first->get_option_no_throw(name);
  if (option == nullptr) return "";
  const std::string type = option->get_type_name();
  if (type == "INT") return fmt::format(" ({} takes a whole number written out, such as 1000)", name);
  if (type == "UINT") return fmt::format(" ({} takes a whole number from 0 to 4294967295, written out)", name);
  return "";
}

CLI::Validator decimalNumber(bool numberLike) {
  return CLI::Validator(
      [numberLike](std::string& text) -> std::string {
        const std::string_view digits = render::withoutPlusSign(text);
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
        const std::string_view digits = render::withoutPlusSign(text);
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
