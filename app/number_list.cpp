#include "app/number_list.h"

#include <charconv>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "core/error.h"
#include "core/json_schema.h"

namespace prism::app {

std::vector<double> parseNumbers(const std::string& text, const std::string& option, char separator) {
  std::vector<double> values;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t comma = text.find(separator, start);
    std::string_view field(text.data() + start, (comma == std::string::npos ? text.size() : comma) - start);
    double v = 0.0;
    auto result = std::from_chars(field.data(), field.data() + field.size(), v);
    if (field.empty() || result.ec != std::errc() || result.ptr != field.data() + field.size() || !std::isfinite(v))
      throw Error(option + ": '" + text + "' is not a '" + separator + "'-separated list of numbers");
    if (std::abs(v) > schema::kFloatInputLimit) {
      throw Error(fmt::format("{}: {} is beyond ±{:g}, the most any number Prism reads may reach", option,
                              std::string(field), schema::kFloatInputLimit));
    }
    values.push_back(v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return values;
}

}  // namespace prism::app
