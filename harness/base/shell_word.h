// A word of a POSIX sh command line shown to people (a reproduction in
// report.md, the options `rayspec devices` says select a device): what sh
// reads back as exactly this text.
#pragma once

#include <string>

namespace rayspec {

// The word as it is when it holds only letters, digits and ._/- (and is not
// empty); else in single quotes, each ' in it written '\''. Nothing in it
// is expanded or run by sh ($, `, ;, a newline: all literal).
std::string shellWord(const std::string& text);

}  // namespace rayspec
