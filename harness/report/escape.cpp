#include "report/escape.h"

#include <regex>

namespace rayspec {

std::string xmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

const char* const kCsvFieldPattern = R"("(?:[^"]|"")*"|[^,"]*)";

std::string csvFieldText(const std::string& field) {
  if (field.size() < 2 || field.front() != '"' || field.back() != '"') return field;
  static const std::regex doubled("\"\"");
  return std::regex_replace(field.substr(1, field.size() - 2), doubled, "\"");
}

}  // namespace rayspec
