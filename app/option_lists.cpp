#include "app/option_lists.h"

#include <charconv>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "core/error.h"
#include "core/json_schema.h"

namespace prism::app {
namespace {

// One field of `text`: Error naming the option when it is no finite number within the limit,
// `what` saying what the option takes.
double parseField(std::string_view field, const std::string& text, const std::string& option, std::string_view what) {
  double v = 0.0;
  auto result = std::from_chars(field.data(), field.data() + field.size(), v);
  if (field.empty() || result.ec != std::errc() || result.ptr != field.data() + field.size() || !std::isfinite(v))
    throw Error(fmt::format("{}: '{}' is not {}", option, text, what));
  if (std::abs(v) > schema::kFloatInputLimit) {
    throw Error(fmt::format("{}: {} is beyond ±{:g}, the most any number Prism reads may reach", option,
                            std::string(field), schema::kFloatInputLimit));
  }
  return v;
}

}  // namespace

std::vector<double> parseNumbers(const std::string& text, const std::string& option, char separator) {
  const std::string what = fmt::format("a '{}'-separated list of numbers", separator);
  std::vector<double> values;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t comma = text.find(separator, start);
    std::string_view field(text.data() + start, (comma == std::string::npos ? text.size() : comma) - start);
    values.push_back(parseField(field, text, option, what));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return values;
}

double parseNumber(const std::string& text, const std::string& option) {
  return parseField(text, text, option, "a number");
}

std::vector<std::string> parseNames(const std::string& text, const std::string& option) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (true) {
    std::size_t comma = text.find(',', start);
    std::string name = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (name.empty()) throw Error(fmt::format("{}: '{}' has an empty name (names separated by commas)", option, text));
    names.push_back(std::move(name));
    if (comma == std::string::npos) return names;
    start = comma + 1;
  }
}

}  // namespace prism::app
