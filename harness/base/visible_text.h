// Text from input as a message may quote it: bytes a terminal would not show
// (control bytes other than newline and tab, a BOM's, any non-ASCII byte; the
// harness's own messages are ASCII) written as \xNN.
#pragma once

#include <cstddef>
#include <string>

namespace rayspec {

std::string visibleText(const std::string& text);
// At most max_bytes of it, then "... (N bytes)" when it is longer.
std::string visibleText(const std::string& text, size_t max_bytes);
// visibleText on one line: newline and tab written as \xNN too (a note that
// becomes one line of failures.csv or of the console: a newline in it would
// start a line of its own, saying what the text pleases).
std::string visibleLine(const std::string& text);

}  // namespace rayspec
