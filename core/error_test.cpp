#include "core/error.h"

#include <gtest/gtest.h>

#include <string>

namespace prism {
namespace {

TEST(Excerpt, QuotesOneLineOfValidTextWithinItsLimit) {
  EXPECT_EQ(excerpt("λ in µm"), "λ in µm");  // UTF-8 stays as it is
  EXPECT_EQ(excerpt("a\nb\tc\x7f"), "a?b?c?");
  // A PNG's signature quoted by the JSON parser: its first byte is no UTF-8.
  EXPECT_EQ(excerpt("\x89PNG"), "?PNG");
  EXPECT_EQ(excerpt("\xc3("), "?(");           // a lead byte without its continuation
  EXPECT_EQ(excerpt("\xc0\xaf"), "??");         // an overlong form's lead byte, and a lone continuation
  EXPECT_EQ(excerpt(std::string(100, 'x')), std::string(77, 'x') + "...");
  // A character cut by the limit becomes '?', not half a character.
  EXPECT_EQ(excerpt(std::string(76, 'x') + "λλ", 10), std::string(7, 'x') + "...");
  EXPECT_EQ(excerpt("xxxxxxλyyy", 10), "xxxxxx?...");
}

}  // namespace
}  // namespace prism
