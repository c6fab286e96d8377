#include "report/case_journal.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "base/whole_file.h"
#include "report/json_text.h"
#include "report/outcome_json.h"

namespace rayspec {
namespace {

std::string journalPath(const std::string& dir) {
  return dir + "/" + kJournalFile;
}

}  // namespace

Result<void> startJournal(const std::string& dir) {
  std::ofstream out(journalPath(dir), std::ios::trunc);
  if (!out) return errorOf(ErrorKind::Harness, "cannot write " + journalPath(dir));
  return {};
}

Result<void> appendJournal(const CaseOutcome& outcome, const std::string& dir) {
  RAYSPEC_TRY(std::string line, jsonText(outcomeJson(outcome)));
  line += '\n';  // the line whole in one write
  std::ofstream out(journalPath(dir), std::ios::app);
  out << line;
  out.flush();
  if (!out) return errorOf(ErrorKind::Harness, "cannot append to " + journalPath(dir));
  return {};
}

namespace {

// One line of the journal, with what nlohmann-json throws made an Error.
Result<CaseOutcome> journalLine(const std::string& line) {
  try {
    return outcomeFromJson(nlohmann::json::parse(line));
  } catch (const std::exception& e) {
    return errorMessage(e.what());
  }
}

}  // namespace

Result<std::optional<std::vector<CaseOutcome>>> readJournal(const std::string& dir) {
  std::vector<CaseOutcome> out;
  std::error_code ec;
  if (!std::filesystem::exists(journalPath(dir), ec))
    return std::optional<std::vector<CaseOutcome>>();
  const Result<std::string> text = readWholeFile(journalPath(dir), kMaxJournalBytes);
  if (!text) return inOneMessage(text.error());
  std::istringstream in(*text);
  std::map<std::string, size_t> at;  // case name -> its place in out
  std::string line;
  for (size_t number = 1; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const bool last = in.peek() == std::char_traits<char>::eof();
    Result<CaseOutcome> o = journalLine(line);
    if (!o) {
      if (last) break;  // the line a kill cut short
      return Error{SourceLoc{journalPath(dir), static_cast<int>(number), 1, ""}, o.error().message};
    }
    if (auto it = at.find(o->name); it != at.end())
      out[it->second] = std::move(*o);
    else {
      at[o->name] = out.size();
      out.push_back(std::move(*o));
    }
  }
  return std::optional<std::vector<CaseOutcome>>(std::move(out));
}

}  // namespace rayspec
