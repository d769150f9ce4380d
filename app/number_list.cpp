#include "app/number_list.h"

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

}  // namespace prism::app
