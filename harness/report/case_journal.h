// The journal of a run: one line of JSON per case (report/outcome_json.h) in
// <out>/outcomes.jsonl, appended as each case ends. The reports are written
// in full at the start (empty, marked interrupted), now and then while the
// run goes, and at its end; a run killed before its end leaves the journal,
// from which `--resume` (and `rayspec merge`) take every case that ended.
#pragma once

#include <optional>

#include "base/result.h"

#include <cstdint>
#include <string>
#include <vector>

#include "report/case_outcome.h"

namespace rayspec {

inline constexpr const char* kJournalFile = "outcomes.jsonl";

// Empties the journal of `dir` (a run that starts anew); the error:
// ErrorKind::Harness, the file not written.
Result<void> startJournal(const std::string& dir);
// Appends the outcome as one whole line: a line left cut short at the end (a
// run killed mid-write, a disk that was full) is cut off first, and a write
// that fails leaves the journal as it was, so that a resumed run never writes
// after half a line. The error: ErrorKind::Harness, "cannot append to PATH:
// WHY", nothing appended; ErrorKind::Input, a case whose details JSON cannot
// hold (text that is not UTF-8, report/json_text.h), nothing appended.
Result<void> appendJournal(const CaseOutcome& outcome, const std::string& dir);
// The outcomes the journal holds (nullopt: `dir` has no journal), a case that
// ended twice (a resumed run) by its last line; what follows the last newline
// (a line cut short) is left out. The error: a whole line that is not an
// outcome (names the file and line), or a journal of more than
// kMaxJournalBytes.
Result<std::optional<std::vector<CaseOutcome>>> readJournal(const std::string& dir);
constexpr uint64_t kMaxJournalBytes = 256ull << 20;  // as summary.json's

}  // namespace rayspec
