#include "core/input_file.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include "core/error_test_support.h"
#include "core/temp_file_test_support.h"

namespace prism {
namespace {

TEST(InputFile, RefusesWhatCannotBeReadAsAFileInOneLine) {
  const std::filesystem::path file = writeTempFile("input_file.txt", "x");
  EXPECT_NO_THROW(requireInputFile(file, "a text"));
  const std::filesystem::path missing = file.parent_path() / "no_such_input.txt";
  EXPECT_EQ(errorOf([&] { requireInputFile(missing, "a text"); }), missing.string() + ": cannot open: no such file");
  EXPECT_EQ(errorOf([&] { requireInputFile(file.parent_path(), "a text"); }),
            file.parent_path().string() + ": is a folder, not a text");
  EXPECT_EQ(errorOf([&] { requireInputFile("/dev/zero", "a text"); }),
            "/dev/zero: not a regular file (a device or a socket), not a text");
  // A pipe is the user's own stream.
  const std::filesystem::path fifo = file.parent_path() / "input_file_fifo";
  std::filesystem::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NO_THROW(requireInputFile(fifo, "a text"));
  std::filesystem::remove(fifo);
}

}  // namespace
}  // namespace prism
