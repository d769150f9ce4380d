#include "harness/validate_parts.h"

#include <algorithm>
#include <map>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "core/json_schema.h"

namespace prism::harness {
namespace {

constexpr const char* kFormat = "prism-validate-part 1";

// N of a part's file name, task-I-of-N.json as validatePartPath writes it; 0 for another name.
int splitOf(const std::filesystem::path& file) {
  const std::string name = file.filename().string();
  const std::size_t of = name.find("-of-");
  if (!name.starts_with("task-") || !name.ends_with(".json") || of == std::string::npos) return 0;
  try {
    const TaskIndex task = parseTaskIndex(name.substr(5, of - 5) + "/" + name.substr(of + 4, name.size() - 5 - (of + 4)), "");
    return validatePartPath({}, task).filename() == name ? task.count : 0;
  } catch (const Error&) {
    return 0;
  }
}

}  // namespace

std::filesystem::path validatePartPath(const std::filesystem::path& dir, TaskIndex task) {
  return dir / "parts" / fmt::format("task-{}-of-{}.json", task.index, task.count);
}

void writeValidatePart(const std::filesystem::path& path, const ValidatePart& part) {
  nlohmann::json json = {{"format", kFormat}, {"identity", part.identity}, {"experiments", part.experiments},
                         {"results", part.results}};
  writeFileAtomically(path, json.dump(2) + "\n");
}

ValidatePart readValidatePart(const std::filesystem::path& path) {
  auto fail = [&](const std::string& why) {
    return Error(fmt::format("{}: not a part of `prism validate --task` ({})", path.string(), why));
  };
  const std::vector<unsigned char> bytes = schema::readBinaryFile(path);  // a folder: its own error
  nlohmann::json json = nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, false);
  if (json.is_discarded() || !json.is_object()) throw fail("not JSON");
  // Members looked up, not value()d: value("format", "") throws nlohmann's own error on a number.
  auto member = [&json](const char* key) {
    auto it = json.find(key);
    return it == json.end() ? nlohmann::json() : *it;
  };
  if (member("format") != kFormat) throw fail("format is not \"" + std::string(kFormat) + "\"");
  ValidatePart part;
  part.identity = member("identity");
  part.results = member("results");
  const nlohmann::json experiments = member("experiments");
  if (!experiments.is_array() || !part.results.is_array()) throw fail("no experiments or results");
  for (const nlohmann::json& e : experiments) {
    if (!e.is_string()) throw fail("an experiment's name is not a string");
    part.experiments.push_back(e.get<std::string>());
  }
  for (const nlohmann::json& row : part.results) {
    if (!row.is_object() || !row.contains("scene") || !row["scene"].is_string()) throw fail("a result without its scene");
    const std::string scene = row["scene"].get<std::string>();
    if (std::find(part.experiments.begin(), part.experiments.end(), scene) == part.experiments.end())
      throw fail("a result of an experiment it does not name");
    if (!row.contains("mode") || !row["mode"].is_string()) throw fail("a result of " + scene + " without its mode");
    auto statistic = [&](const char* key, bool required) {
      auto it = row.find(key);
      if (it == row.end() ? required : !(it->is_number() || it->is_null()))
        throw fail(fmt::format("the result of {} {} has \"{}\": {}, not a number or null", scene,
                               row["mode"].get<std::string>(), key, it == row.end() ? "missing" : excerpt(it->dump())));
    };
    for (const char* key : kResultStatistics) statistic(key, true);
    statistic(kResultVsMultipleScattering, false);
  }
  return part;
}

nlohmann::json collectValidateParts(const std::filesystem::path& dir, const nlohmann::json& identity,
                                    const std::vector<std::string>& experiments, std::optional<int> tasks) {
  const std::filesystem::path folder = dir / "parts";
  std::vector<std::filesystem::path> files;
  std::set<int> splits;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    if (lowercaseExtension(entry.path()) != ".json" || (tasks && splitOf(entry.path()) != *tasks)) continue;
    files.push_back(entry.path());
    if (const int n = splitOf(entry.path()); n > 0) splits.insert(n);
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) {
    throw Error(fmt::format("validate --collect: {} holds no parts{} (`prism validate --task I/{} -o {}` writes them)",
                            folder.string(), tasks ? fmt::format(" of a split into {} tasks", *tasks) : "",
                            tasks ? std::to_string(*tasks) : "N", dir.string()));
  }
  if (splits.size() > 1) {
    throw Error(fmt::format("validate --collect: {} holds parts of splits into {} tasks: --tasks N collects those of "
                            "one (the cluster script's job gives its own)",
                            folder.string(), fmt::join(splits, ", ")));
  }
  std::map<std::string, std::pair<std::filesystem::path, nlohmann::json>> found;  // experiment → part, its rows
  for (const std::filesystem::path& file : files) {
    ValidatePart part = readValidatePart(file);
    if (part.identity != identity) {
      // Where they differ first: the two whole identities, cut at 120 characters, showed the same
      // beginning and hid it (--quick's sizes against a full run's).
      nlohmann::json::json_pointer where(nlohmann::json::diff(part.identity, identity).front()["path"].get<std::string>());
      if (!where.empty() && where.back() == "-") where = where.parent_pointer();  // an array's end: the array
      auto at = [&where](const nlohmann::json& j) { return j.contains(where) ? excerpt(j.at(where).dump(), 120) : "none"; };
      throw Error(fmt::format("validate --collect: {} is a part of another sweep (its {}: {}; this one's: {})",
                              file.string(), where.empty() ? "identity" : where.to_string(), at(part.identity),
                              at(identity)));
    }
    for (const std::string& name : part.experiments) {
      if (std::find(experiments.begin(), experiments.end(), name) == experiments.end())
        throw Error(fmt::format("validate --collect: {}: experiment \"{}\" is not one of this report's ({})",
                                file.string(), excerpt(name), excerpt(fmt::format("{}", fmt::join(experiments, ", ")), 120)));
      auto [it, added] = found.try_emplace(name, file, nlohmann::json::array());
      if (!added) {
        throw Error(fmt::format("validate --collect: experiment {} is in both {} and {}", name, it->second.first.string(),
                                file.string()));
      }
      for (const nlohmann::json& row : part.results)
        if (row["scene"] == name) it->second.second.push_back(row);
      if (it->second.second.empty())  // every experiment has a row; a part without one was cut short
        throw Error(fmt::format("validate --collect: {} names experiment {} but holds no result of it", file.string(),
                                name));
    }
  }
  nlohmann::json rows = nlohmann::json::array();
  for (const std::string& name : experiments) {
    auto it = found.find(name);
    if (it == found.end()) {
      throw Error(fmt::format("validate --collect: experiment {} is missing (no part in {} holds it)", name,
                              folder.string()));
    }
    for (const nlohmann::json& row : it->second.second) rows.push_back(row);
  }
  return rows;
}

}  // namespace prism::harness
