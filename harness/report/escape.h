// Escaping text for XML, HTML and CSV reports.
#pragma once

#include <string>

namespace rayspec {

std::string xmlEscape(const std::string& text);  // & < > " '
// A CSV field (RFC 4180): quoted, with inner quotes doubled, when it holds
// a comma, a quote or a line break; as it is otherwise.
std::string csvField(const std::string& text);

}  // namespace rayspec
