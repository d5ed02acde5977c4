// The line-break test of a response header's text (server/http/header_text.h).
#include "server/http/header_text.h"

#include <gtest/gtest.h>

#include <string>

namespace clearsky::server {
namespace {

TEST(HeaderText, FindsCarriageReturnOrLineFeedAnywhere) {
  EXPECT_FALSE(holds_line_break(""));
  EXPECT_FALSE(holds_line_break("quality=standard; setting=scattering_orders=4"));
  EXPECT_TRUE(holds_line_break("a\r"));
  EXPECT_TRUE(holds_line_break("\nb"));
  EXPECT_TRUE(holds_line_break("x\r\nSet-Cookie: y"));
  // Past the first vector width of memchr, and a NUL before the break.
  std::string long_text(300, 'v');
  EXPECT_FALSE(holds_line_break(long_text));
  long_text[257] = '\n';
  EXPECT_TRUE(holds_line_break(long_text));
  const std::string with_nul("a\0b\rc", 5);
  EXPECT_TRUE(holds_line_break(with_nul));
}

}  // namespace
}  // namespace clearsky::server
