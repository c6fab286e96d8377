#include "base/visible_text.h"

#include <cstdio>
#include <string>

namespace rayspec {

namespace {

// The text with every byte that is not printable ASCII (and, unless
// `lines`, newline and tab too) written as \xNN.
std::string escaped(const std::string& text, bool lines) {
  std::string out;
  for (unsigned char ch : text) {
    if ((ch >= 0x20 && ch < 0x7F) || (lines && (ch == '\n' || ch == '\t'))) {
      out += static_cast<char>(ch);
      continue;
    }
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02X", ch);
    out += hex;
  }
  return out;
}

}  // namespace

std::string visibleText(const std::string& text) {
  return escaped(text, true);
}

std::string visibleLine(const std::string& text) {
  return escaped(text, false);
}

std::string visibleText(const std::string& text, size_t max_bytes) {
  const std::string out = visibleText(text.substr(0, max_bytes));
  return text.size() > max_bytes ? out + "... (" + std::to_string(text.size()) + " bytes)" : out;
}

}  // namespace rayspec
