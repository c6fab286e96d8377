// Text from input as a message may quote it: bytes a terminal would not show
// (control bytes other than newline and tab, a BOM's, any non-ASCII byte; the
// harness's own messages are ASCII) written as \xNN.
#pragma once

#include <string>

namespace rayspec {

std::string visibleText(const std::string& text);

}  // namespace rayspec
