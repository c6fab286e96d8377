// Text from input that a terminal or a CI log would obey: escape sequences
// (OSC 52 sets the clipboard, OSC 0 the window title, ESC[2J clears the
// screen) and a line break followed by a GitHub Actions command, and the
// check that an output shows none of it as such.
#pragma once

#include <sstream>
#include <string>

namespace rayspec::testing_support {

inline const std::string kHostileText =
    "dev\x1b]52;c;cHduZWQ=\x07\x1b]0;title\x07\x1b[2J\r\n::error file=x::forged";

// What in `text` a terminal or a CI log would obey: "" when nothing; else
// the first control byte (but newline and tab) or the first line whose text
// (after blanks) begins "::" (a workflow command), with its line number.
inline std::string obeyedText(const std::string& text) {
  std::istringstream lines(text);
  int n = 0;
  for (std::string line; std::getline(lines, line);) {
    ++n;
    for (unsigned char ch : line)
      if ((ch < 0x20 && ch != '\t') || ch == 0x7F)
        return "line " + std::to_string(n) + " holds byte " + std::to_string(ch) + ": " + line;
    const size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, 2, "::") == 0)
      return "line " + std::to_string(n) + " is a workflow command: " + line;
  }
  return "";
}

}  // namespace rayspec::testing_support
