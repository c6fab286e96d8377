// Bytes as lower-case hexadecimal text, two digits a byte: device and cache
// UUIDs, digests.
#pragma once

#include <cstddef>
#include <string>

namespace rayspec {

std::string hexBytes(const void* bytes, size_t n);

}  // namespace rayspec
