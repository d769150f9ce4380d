// The parts of `prism validate` split into tasks (`prism validate --task I/N -o DIR`, one Slurm
// array task each, then `prism validate --collect DIR`): each task runs its share of the
// experiments, writes their images into DIR as a whole run does, and last, atomically, its part:
// DIR/parts/task-I-of-N.json, {"format", "identity" (what every part must agree on: the sizes and
// the scenes), "experiments" (their names, in order), "results" (their rows of results.json)}.
// A part that exists is a task whose images are all written.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/task_split.h"

namespace prism::harness {

// A result row's statistics (harness/validate.cpp writes them), each a number, or null for +∞;
// the last only in the reef's rows.
inline constexpr std::array<const char*, 6> kResultStatistics = {"mean_delta_e", "median_delta_e", "p95_delta_e",
                                                                 "max_delta_e",  "mae_8bit",       "relative_error"};
inline constexpr const char* kResultVsMultipleScattering = "mean_delta_e_vs_multiple_scattering";

struct ValidatePart {
  nlohmann::json identity;
  std::vector<std::string> experiments;
  nlohmann::json results;  // an array of result rows
};

std::filesystem::path validatePartPath(const std::filesystem::path& dir, TaskIndex task);

void writeValidatePart(const std::filesystem::path& path, const ValidatePart& part);

// Error "PATH: not a part of `prism validate --task` (WHY)" when it is not one: every row has its
// scene (one the part names), its mode and its statistics.
ValidatePart readValidatePart(const std::filesystem::path& path);

// Every part in DIR/parts of a split into `tasks` (task-*-of-N.json; unset: the one split the
// folder holds), checked to agree on `identity` and to hold each of `experiments` exactly once:
// their rows in the order of `experiments`. Error "validate --collect: …" naming the experiment
// missing, the two parts that both hold one, the part of another sweep, or, unset, the splits
// the folder holds parts of (a sweep run again into it with another task count left its parts).
nlohmann::json collectValidateParts(const std::filesystem::path& dir, const nlohmann::json& identity,
                                    const std::vector<std::string>& experiments, std::optional<int> tasks = std::nullopt);

}  // namespace prism::harness
