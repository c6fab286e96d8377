#include "base/visible_text.h"

#include <cstdio>
#include <string>

namespace rayspec {
namespace {

std::string visible(const std::string& text, bool keep_newline) {
  std::string out;
  for (unsigned char ch : text) {
    if ((ch >= 0x20 && ch < 0x7F) || (ch == '\n' && keep_newline) || ch == '\t') {
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
  return visible(text, true);
}

std::string visibleText(const std::string& text, size_t max_bytes) {
  const std::string out = visibleText(text.substr(0, max_bytes));
  return text.size() > max_bytes ? out + "... (" + std::to_string(text.size()) + " bytes)" : out;
}

std::string visibleLine(const std::string& text) {
  const std::string out = visible(text, false);
  const size_t first = out.find_first_not_of(" \t");
  if (first == std::string::npos || out[first] != ':') return out;
  return out.substr(0, first) + "\\x3A" + out.substr(first + 1);
}

}  // namespace rayspec
