#include "export/c_text.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace rayspec {
namespace {

std::string hexWord(uint32_t w) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08xu", w);
  return buf;
}

// The elements of an array, `per_line` a line, indented.
template <typename T, typename Format>
std::string arrayBody(const std::vector<T>& values, size_t per_line, Format format) {
  std::string out;
  if (values.empty()) return "  0\n";
  for (size_t i = 0; i < values.size(); ++i) {
    out += (i % per_line == 0 ? "  " : " ") + format(values[i]) + ",";
    if (i % per_line == per_line - 1 || i + 1 == values.size()) out += "\n";
  }
  return out;
}

}  // namespace

std::string cWordArray(const std::string& name, const std::vector<uint32_t>& words) {
  return "static const uint32_t " + name + "[] = {\n" + arrayBody(words, 8, hexWord) + "};\n";
}

std::string cByteArray(const std::string& name, const std::vector<uint8_t>& bytes) {
  const auto hex = [](uint8_t b) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02x", b);
    return std::string(buf);
  };
  return "static const uint8_t " + name + "[] = {\n" + arrayBody(bytes, 16, hex) + "};\n";
}

std::string cFloat(float f) {
  if (std::isnan(f)) return "NAN";
  if (std::isinf(f)) return f > 0 ? "INFINITY" : "-INFINITY";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%af", static_cast<double>(f));
  return buf;
}

std::string cString(const std::string& text) {
  std::string out = "\"";
  for (const unsigned char ch : text) {
    if (ch == '\\' || ch == '"') {
      out += '\\';
      out += static_cast<char>(ch);
    } else if (ch < 0x20 || ch >= 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\%03o", ch);
      out += buf;
    } else {
      out += static_cast<char>(ch);
    }
  }
  return out + "\"";
}

std::string cComment(const std::string& text) {
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line)) {
    // A comment line ending in a backslash would swallow the next line.
    if (!line.empty() && line.back() == '\\') line += " (line continues)";
    out += line.empty() ? "//\n" : "// " + line + "\n";
  }
  return out;
}

}  // namespace rayspec
