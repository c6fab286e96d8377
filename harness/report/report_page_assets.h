// The style and scripts embedded in report.html: no network fetch, so the
// page works offline from file:// and as a CI artifact.
#pragma once

namespace rayspec {

// The page's style sheet.
extern const char* const kReportStyle;
// Runs first, in <head>: counts script errors into data-script-errors on
// <body>, which a headless browser reads back.
extern const char* const kReportCheckScript;
// Runs last, at the end of <body>: the filter (status, family, rule, search;
// also from the address's "#filter?status=Fail&family=anyhit&rule=R-X&q=text"),
// the per-ray tables' "every field" switch, and the self-check on load
// (data-images, data-broken-images, data-checked on <body>; data-shown once
// the filter has run).
extern const char* const kReportScript;

}  // namespace rayspec
