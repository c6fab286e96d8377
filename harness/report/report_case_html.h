// One case in report.html. A failing case (or a case error) is a block: its
// findings shown, its images, undefined rays and per-ray table folded in a
// <details>, the per-ray rows whose device and model agree hidden until
// asked for. Any other case is one row of a table. Either is an element with
// data-s (status) and data-f (family) and its rules in a ".r" element, which
// the page's filter reads (report/report_page_assets.h).
#pragma once

#include <ostream>
#include <string>

#include "report/case_outcome.h"

namespace rayspec {

// dir: the run folder, where the images are looked for (an image not there
// is left out).
void writeCaseBlock(std::ostream& out, const CaseOutcome& outcome, const std::string& dir);
// The header of the table writeCaseRow's rows go in.
void writeCaseRowHeader(std::ostream& out);
void writeCaseRow(std::ostream& out, const CaseOutcome& outcome, const std::string& dir);

}  // namespace rayspec
