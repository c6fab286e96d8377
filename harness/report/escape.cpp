#include "report/escape.h"

#include "base/visible_text.h"

namespace rayspec {

std::string xmlEscape(const std::string& raw) {
  // XML 1.0 allows no control byte but tab, newline and carriage return, and
  // only well-formed UTF-8: a saved message's other bytes are shown as \xNN.
  const std::string text = visibleText(raw);
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
  std::string out;
  for (size_t i = 1; i + 1 < field.size(); ++i) {
    out += field[i];
    if (field[i] == '"' && field[i + 1] == '"' && i + 2 < field.size()) ++i;  // "" is one "
  }
  return out;
}

}  // namespace rayspec
