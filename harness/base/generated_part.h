// A document's generated part: the text between two marker lines (HTML
// comments in a Markdown page) that a command writes from the one
// definition of what it lists (docs/cts-map.md's tables, the planted faults
// of docs/wrong-devices.md), so the page cannot fall behind its source: a
// unit test compares the committed page with what the command makes.
#pragma once

#include <string>

#include "base/result.h"

namespace rayspec {

// `doc` with the text between `begin` and the first `end` after it replaced
// by "\n" + part; an error names the markers when the doc lacks either.
Result<std::string> withGeneratedPart(const std::string& doc, const std::string& begin,
                                      const std::string& end, const std::string& part);

}  // namespace rayspec
