#include "results/sha256.h"

#include <openssl/core_names.h>
#include <openssl/evp.h>

#include <memory>

#include "base/hex_text.h"

namespace rayspec {

Result<std::string> sha256Hex(std::initializer_list<std::string_view> pieces) {
  const std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx(EVP_MD_CTX_new(),
                                                                    &EVP_MD_CTX_free);
  bool ok = ctx && EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) == 1;
  for (std::string_view p : pieces) ok = ok && EVP_DigestUpdate(ctx.get(), p.data(), p.size()) == 1;
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int size = 0;
  ok = ok && EVP_DigestFinal_ex(ctx.get(), digest, &size) == 1;
  if (!ok) return errorMessage("libcrypto: SHA-256 failed");
  return hexBytes(digest, size);
}

Result<std::string> hmacSha256Hex(std::string_view key,
                                  std::initializer_list<std::string_view> pieces) {
  const std::unique_ptr<EVP_MAC, decltype(&EVP_MAC_free)> mac(
      EVP_MAC_fetch(nullptr, OSSL_MAC_NAME_HMAC, nullptr), &EVP_MAC_free);
  const std::unique_ptr<EVP_MAC_CTX, decltype(&EVP_MAC_CTX_free)> ctx(
      mac ? EVP_MAC_CTX_new(mac.get()) : nullptr, &EVP_MAC_CTX_free);
  char digest_name[] = "SHA256";
  const OSSL_PARAM params[] = {
      OSSL_PARAM_construct_utf8_string(OSSL_MAC_PARAM_DIGEST, digest_name, 0),
      OSSL_PARAM_construct_end()};
  const auto bytes = [](std::string_view s) {
    return reinterpret_cast<const unsigned char*>(s.data());
  };
  bool ok = ctx && EVP_MAC_init(ctx.get(), bytes(key), key.size(), params) == 1;
  for (std::string_view p : pieces) ok = ok && EVP_MAC_update(ctx.get(), bytes(p), p.size()) == 1;
  unsigned char sum[EVP_MAX_MD_SIZE];
  size_t size = 0;
  ok = ok && EVP_MAC_final(ctx.get(), sum, &size, sizeof sum) == 1;
  if (!ok) return errorMessage("libcrypto: HMAC-SHA-256 failed");
  return hexBytes(sum, size);
}

}  // namespace rayspec
