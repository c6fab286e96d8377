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

}  // namespace rayspec
