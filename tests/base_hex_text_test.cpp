// base/hex_text.h: two lower-case digits a byte, in order.
#include <gtest/gtest.h>

#include <cstdint>

#include "base/hex_text.h"

namespace rayspec {
namespace {

TEST(HexText, TwoLowerCaseDigitsAByte) {
  const uint8_t bytes[] = {0x00, 0x0f, 0xa0, 0xff, 0x12};
  EXPECT_EQ(hexBytes(bytes, sizeof bytes), "000fa0ff12");
  EXPECT_EQ(hexBytes(bytes, 0), "");
}

}  // namespace
}  // namespace rayspec
