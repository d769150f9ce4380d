#include "core/task_split.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace prism {
namespace {

TEST(TaskSplit, SharesTileTheCountAndDifferByAtMostOne) {
  for (int total : {1, 7, 135, 1'000'000}) {
    for (int count : {1, 2, 3, 8, 100}) {
      if (count > total) continue;
      int next = 0;
      for (int i = 0; i < count; ++i) {
        IndexRange share = shareOf({i, count}, total);
        ASSERT_EQ(share.begin, next) << i << "/" << count << " of " << total;
        ASSERT_GE(share.size(), total / count);
        ASSERT_LE(share.size(), total / count + 1);
        next = share.end;
      }
      EXPECT_EQ(next, total);
    }
  }
  // The job scripts compute the same bounds in the shell: ⌊I·total/N⌋.
  EXPECT_EQ(shareOf({2, 8}, 135), (IndexRange{33, 50}));
}

TEST(TaskSplit, ParsesTaskIndicesAndRanges) {
  TaskIndex t = parseTaskIndex("3/8", "--tile");
  EXPECT_EQ(t.index, 3);
  EXPECT_EQ(t.count, 8);
  EXPECT_EQ(parseIndexRange("32:48", "--samples"), (IndexRange{32, 48}));
  for (const char* bad : {"8/8", "-1/8", "3", "3/0", "a/b", "3/8/1", "3/", " 3/8"}) {
    EXPECT_THROW(parseTaskIndex(bad, "--tile"), Error) << bad;
  }
  for (const char* bad : {"48:32", "5:5", "-1:4", "1:", ":4", "1:4:5", "1:99999999999"}) {
    EXPECT_THROW(parseIndexRange(bad, "--samples"), Error) << bad;
  }
  try {
    parseTaskIndex("9/8", "--tile");
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "--tile: expected I/N with 0 ≤ I < N (task I of N), got \"9/8\"");
  }
}

std::string coverError(const std::vector<IndexRange>& ranges, int total) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    names.emplace_back("p");
    names.back() += std::to_string(i);
  }
  try {
    checkCoveredOnce(ranges, names, total, "rows");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(TaskSplit, PartsMustCoverTheCountExactlyOnce) {
  EXPECT_EQ(coverError({{4, 10}, {0, 4}}, 10), "");  // in any order
  EXPECT_EQ(coverError({{0, 4}, {5, 10}}, 10), "merge: rows 4:5 are missing");
  EXPECT_EQ(coverError({{0, 4}}, 10), "merge: rows 4:10 are missing");
  EXPECT_EQ(coverError({{2, 10}}, 10), "merge: rows 0:2 are missing");
  EXPECT_EQ(coverError({{0, 6}, {4, 10}}, 10), "merge: rows 4:6 are in both p0 and p1");
  EXPECT_EQ(coverError({{0, 10}, {0, 10}}, 10), "merge: rows 0:10 are in both p0 and p1");
  EXPECT_EQ(coverError({}, 10), "merge: rows 0:10 are missing");
}

}  // namespace
}  // namespace prism
