// Escaping text for XML and HTML reports.
#pragma once

#include <string>

namespace rayspec {

std::string xmlEscape(const std::string& text);  // & < > " '

}  // namespace rayspec
