#include "base/visible_text.h"

#include <cstdio>

namespace rayspec {

std::string visibleText(const std::string& text) {
  std::string out;
  for (unsigned char ch : text) {
    if ((ch >= 0x20 && ch < 0x7F) || ch == '\n' || ch == '\t') {
      out += static_cast<char>(ch);
      continue;
    }
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02X", ch);
    out += hex;
  }
  return out;
}

}  // namespace rayspec
