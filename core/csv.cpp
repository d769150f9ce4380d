#include "core/csv.h"

#include <csv.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "core/input_file.h"
#include "core/json_schema.h"

namespace prism {
namespace {

struct FieldCollector {
  std::vector<std::string> fields;
};

void onField(void* data, size_t length, void* sink) {
  static_cast<FieldCollector*>(sink)->fields.emplace_back(static_cast<const char*>(data), length);
}

void onRowEnd(int, void*) {}

// Splits one physical line into fields. Prism's files never quote a newline, so one line is one
// record and line numbers stay exact.
std::vector<std::string> splitLine(const std::string& path, int lineNumber, const std::string& line) {
  csv_parser parser;
  if (csv_init(&parser, CSV_STRICT | CSV_STRICT_FINI) != 0)
    throw Error(FileLocation{path, lineNumber}, "cannot initialise the CSV parser");
  FieldCollector collector;
  size_t parsed = csv_parse(&parser, line.data(), line.size(), onField, onRowEnd, &collector);
  bool ok = parsed == line.size() && csv_fini(&parser, onField, onRowEnd, &collector) == 0;
  std::string why = ok ? "" : csv_strerror(csv_error(&parser));
  csv_free(&parser);
  if (!ok) throw Error(FileLocation{path, lineNumber}, "malformed CSV (" + why + ")");
  return std::move(collector.fields);
}

}  // namespace

CsvTable CsvTable::read(const std::filesystem::path& path) {
  CsvTable table;
  table.mPath = path.string();
  requireInputFile(path, "a CSV file");
  std::ifstream in(path);
  if (!in) throw Error(table.mPath + ": cannot open file");
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    std::vector<std::string> fields = splitLine(table.mPath, lineNumber, line);
    if (table.mHeader.empty()) {
      table.mHeader = std::move(fields);
      table.mHeaderLine = lineNumber;
      continue;
    }
    if (fields.size() != table.mHeader.size())
      throw Error(FileLocation{table.mPath, lineNumber},
                  "expected " + std::to_string(table.mHeader.size()) + " fields, found " +
                      std::to_string(fields.size()));
    table.mRows.push_back({lineNumber, std::move(fields)});
  }
  if (table.mHeader.empty()) throw Error(table.mPath + ": no header line (the file is empty, or blank and # lines)");
  if (table.mRows.empty()) throw Error(table.mPath + ": no data rows after the header");
  return table;
}

int CsvTable::column(std::string_view name) const {
  auto it = std::find(mHeader.begin(), mHeader.end(), name);
  if (it == mHeader.end())
    throw Error(FileLocation{mPath, mHeaderLine}, "missing column '" + std::string(name) + "'");
  return static_cast<int>(it - mHeader.begin());
}

double CsvTable::number(const CsvRow& row, int column) const {
  const std::string& field = row.fields[static_cast<std::size_t>(column)];
  std::size_t first = field.find_first_not_of(' ');
  std::size_t last = field.find_last_not_of(' ');
  double value = 0.0;
  std::from_chars_result result{};
  if (first != std::string::npos)
    result = std::from_chars(field.data() + first, field.data() + last + 1, value);
  FileLocation where{mPath, row.line, column + 1};
  if (first == std::string::npos || result.ec != std::errc() || result.ptr != field.data() + last + 1)
    throw Error(where, "expected a number in column '" + mHeader[static_cast<std::size_t>(column)] +
                           "', found '" + field + "'");
  if (!std::isfinite(value))
    throw Error(where, "value '" + field + "' is not finite");
  if (std::abs(value) > schema::kFloatInputLimit)
    throw Error(where, "value '" + field + "' is beyond ±1e12, the most any number Prism reads may reach");
  return value;
}

void checkIncreasingWavelengths(const std::string& path, std::span<const double> lambdasNm,
                                std::span<const int> lines) {
  if (!lambdasNm.empty() && !(lambdasNm[0] > 0.0))
    throw Error(FileLocation{path, lines[0]}, "wavelengths must be positive (" + shortestNumber(lambdasNm[0]) + " nm)");
  for (std::size_t i = 1; i < lambdasNm.size(); ++i)
    if (!(lambdasNm[i] > lambdasNm[i - 1]))
      throw Error(FileLocation{path, lines[i]}, "wavelengths must increase strictly (" +
                                                    shortestNumber(lambdasNm[i]) + " nm after " +
                                                    shortestNumber(lambdasNm[i - 1]) + " nm)");
  if (lambdasNm.size() < 2) throw Error(path + ": a spectrum needs at least two wavelengths");
}

}  // namespace prism
