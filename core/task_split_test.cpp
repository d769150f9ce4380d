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

}  // namespace
}  // namespace prism
