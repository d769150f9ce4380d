#include "harness/validate_parts.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "core/error.h"

namespace prism::harness {
namespace {

class ValidateParts : public ::testing::Test {
 protected:
  void SetUp() override {
    mRoot = std::filesystem::path(::testing::TempDir()) / ("prism_validate_parts_" + std::to_string(::getpid()));
    std::filesystem::remove_all(mRoot);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(mRoot, ec);
  }
  // A part of task I/N holding `experiments`, one row each (and two for "b").
  void part(TaskIndex task, const std::vector<std::string>& experiments, const nlohmann::json& identity = kIdentity) {
    ValidatePart p{identity, experiments, nlohmann::json::array()};
    for (const std::string& e : experiments) {
      p.results.push_back(row(e, "rgb"));
      if (e == "b") p.results.push_back(row(e, "naive"));
    }
    writeValidatePart(validatePartPath(mRoot, task), p);
  }
  static nlohmann::json row(const std::string& scene, const std::string& mode) {
    nlohmann::json r = {{"scene", scene}, {"mode", mode}};
    for (const char* key : kResultStatistics) r[key] = 0.5;
    return r;
  }
  std::string collectError() {
    try {
      collectValidateParts(mRoot, kIdentity, kExperiments);
    } catch (const Error& e) {
      return e.what();
    }
    return "collected";
  }

  inline static const nlohmann::json kIdentity = {{"sizes", 1}};
  inline static const std::vector<std::string> kExperiments = {"a", "b", "c"};
  std::filesystem::path mRoot;
};

TEST_F(ValidateParts, CollectsEveryExperimentsRowsInOrder) {
  part({1, 2}, {"c"});
  part({0, 2}, {"a", "b"});
  nlohmann::json rows = collectValidateParts(mRoot, kIdentity, kExperiments);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0]["scene"], "a");
  EXPECT_EQ(rows[1]["mode"], "rgb");
  EXPECT_EQ(rows[2]["mode"], "naive");
  EXPECT_EQ(rows[3]["scene"], "c");
  EXPECT_EQ(readValidatePart(validatePartPath(mRoot, {0, 2})).experiments, (std::vector<std::string>{"a", "b"}));
}

// A sweep run again into the same folder with another task count: its parts stand beside the
// earlier ones, and the collect job, which knew no N, failed on an experiment in both.
TEST_F(ValidateParts, CollectsTheSplitItIsGivenAndNamesTheSplitsOtherwise) {
  part({0, 3}, {"a"});
  part({1, 3}, {"b"});
  part({0, 2}, {"a", "b"});
  part({1, 2}, {"c"});
  EXPECT_EQ(collectError(), "validate --collect: " + (mRoot / "parts").string() +
                                " holds parts of splits into 2, 3 tasks: --tasks N collects those of one (the cluster "
                                "script's job gives its own)");
  EXPECT_EQ(collectValidateParts(mRoot, kIdentity, kExperiments, 2).size(), 4u);
  EXPECT_EQ(collectValidateParts(mRoot, kIdentity, {"a", "b"}, 3).size(), 3u);
  try {
    collectValidateParts(mRoot, kIdentity, kExperiments, 5);
    ADD_FAILURE() << "collected a split with no parts";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("holds no parts of a split into 5 tasks (`prism validate --task I/5 -o"),
              std::string::npos) << e.what();
  }
}

TEST_F(ValidateParts, RefusesAMissingExperimentATwiceRunOneAndAnotherSweep) {
  EXPECT_NE(collectError().find("parts holds no parts (`prism validate --task I/N -o"), std::string::npos) << collectError();
  part({0, 2}, {"a", "b"});
  EXPECT_EQ(collectError(), "validate --collect: experiment c is missing (no part in " + (mRoot / "parts").string() +
                                " holds it)");
  part({1, 2}, {"b", "c"});
  EXPECT_EQ(collectError(), "validate --collect: experiment b is in both " +
                                validatePartPath(mRoot, {0, 2}).string() + " and " +
                                validatePartPath(mRoot, {1, 2}).string());
  std::filesystem::remove(validatePartPath(mRoot, {1, 2}));
  part({1, 2}, {"c"}, {{"sizes", 2}});
  EXPECT_EQ(collectError(), "validate --collect: " + validatePartPath(mRoot, {1, 2}).string() +
                                " is a part of another sweep (its /sizes: 2; this one's: 1)");
  std::ofstream(validatePartPath(mRoot, {1, 2})) << "{\"format\": \"prism-validate-part 1\", \"experi";
  EXPECT_NE(collectError().find("not a part of `prism validate --task` (not JSON)"), std::string::npos);
  // A part naming an experiment with no row of it (it reported a report without that experiment,
  // exit 0), one of an experiment this report does not collect, a folder in a part's place (exit 70).
  ValidatePart cut{kIdentity, {"c"}, nlohmann::json::array()};
  writeValidatePart(validatePartPath(mRoot, {1, 2}), cut);
  EXPECT_EQ(collectError(), "validate --collect: " + validatePartPath(mRoot, {1, 2}).string() +
                                " names experiment c but holds no result of it");
  part({1, 2}, {"c", "d"});
  EXPECT_EQ(collectError(), "validate --collect: " + validatePartPath(mRoot, {1, 2}).string() +
                                ": experiment \"d\" is not one of this report's (a, b, c)");
  // Types that nlohmann's value() and get() refused in their own words (exit 70 for a numeric
  // format), and a row without its statistics: each the part's file and what is wrong.
  std::ofstream(validatePartPath(mRoot, {1, 2})) << R"({"format": 1})";
  EXPECT_EQ(collectError(), validatePartPath(mRoot, {1, 2}).string() +
                                ": not a part of `prism validate --task` (format is not \"prism-validate-part 1\")");
  ValidatePart wrong{kIdentity, {"c"}, nlohmann::json::array({row("c", "rgb")})};
  wrong.results[0]["p95_delta_e"] = "x";
  writeValidatePart(validatePartPath(mRoot, {1, 2}), wrong);
  EXPECT_EQ(collectError(), validatePartPath(mRoot, {1, 2}).string() +
                                ": not a part of `prism validate --task` (the result of c rgb has \"p95_delta_e\": "
                                "\"x\", not a number or null)");
  wrong.results[0].erase("p95_delta_e");
  wrong.results[0]["max_delta_e"] = nullptr;  // +∞, as a non-finite pixel writes it
  writeValidatePart(validatePartPath(mRoot, {1, 2}), wrong);
  EXPECT_NE(collectError().find("\"p95_delta_e\": missing"), std::string::npos) << collectError();
  std::filesystem::remove(validatePartPath(mRoot, {1, 2}));
  std::filesystem::create_directories(validatePartPath(mRoot, {1, 2}));
  EXPECT_EQ(collectError(), validatePartPath(mRoot, {1, 2}).string() + ": is a folder, not a file");
}

}  // namespace
}  // namespace prism::harness
