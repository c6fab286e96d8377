#include "base/visible_text.h"

#include <cstdio>
#include <string>

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

std::string visibleText(const std::string& text, size_t max_bytes) {
  const std::string out = visibleText(text.substr(0, max_bytes));
  return text.size() > max_bytes ? out + "... (" + std::to_string(text.size()) + " bytes)" : out;
}

}  // namespace rayspec
