// Input quoted in messages (core/quote_input.hpp): shortened, control bytes and broken UTF-8 escaped,
// valid UTF-8 kept.
#include "emit/core/quote_input.hpp"

#include <string>

#include <gtest/gtest.h>

namespace emit {
namespace {

TEST(QuoteInput, PlainTextIsQuoted) { EXPECT_EQ(quote_input("volts"), "\"volts\""); }

TEST(QuoteInput, LongTextIsCutAtTheLimit) {
  const std::string line(4096, ';');
  EXPECT_EQ(quote_input(line, 5), "\";;;;;...\"");
  EXPECT_EQ(quote_input(line).size(), 40u + 5u);  // 40 characters, two quotes, "..."
}

TEST(QuoteInput, ControlBytesBrokenUtf8AndTheByteOrderMarkAreEscaped) {
  EXPECT_EQ(quote_input(std::string("a\0b\tc", 5)), "\"a\\x00b\\x09c\"");
  EXPECT_EQ(quote_input("\xff\xfe"), "\"\\xff\\xfe\"");
  EXPECT_EQ(quote_input("\xef\xbb\xbf"
                        "1.0"),
            "\"\\xef\\xbb\\xbf1.0\"");
  EXPECT_EQ(quote_input("\xc3"), "\"\\xc3\"");  // a sequence cut short
}

TEST(QuoteInput, ValidUtf8IsKeptAndCountsAsOneCharacter) {
  EXPECT_EQ(quote_input("5 \xc2\xb5m"), "\"5 \xc2\xb5m\"");
  EXPECT_EQ(quote_input("\xce\xbb\xce\xbb\xce\xbb", 2), "\"\xce\xbb\xce\xbb...\"");
}

}  // namespace
}  // namespace emit
