// SHA-256 and HMAC-SHA-256 through libcrypto, against published vectors.
#include <gtest/gtest.h>

#include "results/sha256.h"

namespace rayspec {
namespace {

TEST(Sha256, KnownDigest) {
  EXPECT_EQ(*sha256Hex({"a", "bc"}),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

// RFC 4231, test case 2; the message given in pieces.
TEST(Sha256, HmacMatchesRfc4231) {
  EXPECT_EQ(*hmacSha256Hex("Jefe", {"what do ya want ", "for nothing?"}),
            "5bdcc146bf60754e6a042426089575c75a003f089d2739839dec58b964ec3843");
  EXPECT_NE(*hmacSha256Hex("Jeff", {"what do ya want for nothing?"}),
            *hmacSha256Hex("Jefe", {"what do ya want for nothing?"}));
}

}  // namespace
}  // namespace rayspec
