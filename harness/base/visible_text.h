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
// The same for one field of a line (the console, summary.txt, results.csv):
// a newline too written as \x0A, and a ':' the field begins with (after
// blanks) as \x3A, so that text from input never starts a line, nor begins
// one, that a CI log reads as a command ("::error file=...::...").
std::string visibleLine(const std::string& text);

}  // namespace rayspec
