#include <gtest/gtest.h>

#include "common/bad_input.hpp"
#include "common/printable.hpp"

namespace cnc {
namespace {

// The escapes are the bytes' own values; the UTF-8 cases are RFC 3629's table (§4) at its edges.
TEST(Printable, ControlBytesAndBrokenUtf8AreEscaped) {
    EXPECT_EQ(printable("G1 X10"), "G1 X10");
    EXPECT_EQ(printable(std::string("a\0b", 3)), "a\\x00b");
    EXPECT_EQ(printable("\x1b[2J\r\t\x7f"), "\\x1B[2J\\x0D\\x09\\x7F");
    EXPECT_EQ(printable("one\ntwo"), "one\ntwo");  // multi-line messages stay multi-line
    EXPECT_EQ(printable("\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80"), "\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80");
    EXPECT_EQ(printable("\xEF\xBB\xBF"), "\xEF\xBB\xBF");              // U+FEFF is a character
    EXPECT_EQ(printable("\xC0\xAF"), "\\xC0\\xAF");                    // overlong '/'
    EXPECT_EQ(printable("\xED\xA0\x80"), "\\xED\\xA0\\x80");           // surrogate U+D800
    EXPECT_EQ(printable("\xF4\x90\x80\x80"), "\\xF4\\x90\\x80\\x80");  // past U+10FFFF
    EXPECT_EQ(printable("\xE2\x82"), "\\xE2\\x82");                    // cut short at the end
    EXPECT_EQ(printable("\xFF"), "\\xFF");
}

TEST(Printable, BadInputMessagesAreEscaped) {
    const BadInput e("job.nc:3", std::string("unexpected character '\x1b'"));
    EXPECT_STREQ(e.what(), "job.nc:3: unexpected character '\\x1B'");
}

}  // namespace
}  // namespace cnc
