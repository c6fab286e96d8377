// Escaping text for XML, HTML and CSV reports.
#pragma once

#include <string>

namespace rayspec {

// & < > " ' escaped; control bytes (but tab, newline) and non-ASCII bytes
// as \xNN (base/visible_text.h), so the document stays well-formed XML.
std::string xmlEscape(const std::string& text);
// A CSV field (RFC 4180): quoted, with inner quotes doubled, when it holds
// a comma, a quote or a line break; as it is otherwise.
std::string csvField(const std::string& text);
// The other way: a regular expression (ECMAScript) matching one CSV field as
// csvField writes it, and the field's text from such a match.
extern const char* const kCsvFieldPattern;
std::string csvFieldText(const std::string& field);

}  // namespace rayspec
