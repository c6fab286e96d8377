#include "report/case_journal.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <map>
#include <sstream>
#include <system_error>

#include "base/whole_file.h"
#include "report/json_text.h"
#include "report/outcome_json.h"

namespace rayspec {
namespace {

std::string journalPath(const std::string& dir) {
  return dir + "/" + kJournalFile;
}

Error journalError(const std::string& what, int error) {
  return errorOf(ErrorKind::Harness,
                 what + ": " + std::error_code(error, std::generic_category()).message());
}

// The journal's length up to and with its last newline (0: it has none); what
// follows it is a line a kill (or a full disk) cut short. -1: errno says why.
off_t completeLength(int fd, off_t size) {
  char block[4096];
  for (off_t end = size; end > 0;) {
    const off_t start = end > off_t(sizeof block) ? end - off_t(sizeof block) : 0;
    const ssize_t n = ::pread(fd, block, static_cast<size_t>(end - start), start);
    if (n < 0) return -1;
    if (n != end - start) {  // the file shrank under us
      errno = EIO;
      return -1;
    }
    for (off_t i = end - start; i > 0; --i)
      if (block[i - 1] == '\n') return start + i;
    end = start;
  }
  return 0;
}

// Appends text to fd whole, after cutting off a line left cut short; a write
// that fails (a full disk) leaves the journal as it was. 0, or errno.
int appendWhole(int fd, const std::string& text) {
  struct stat st;
  if (::fstat(fd, &st) != 0) return errno;
  off_t size = st.st_size;
  if (size > 0) {
    const off_t complete = completeLength(fd, size);
    if (complete < 0) return errno;
    if (complete != size && ::ftruncate(fd, complete) != 0) return errno;
    size = complete;
  }
  for (size_t done = 0; done < text.size();) {
    const ssize_t n = ::pwrite(fd, text.data() + done, text.size() - done, size + off_t(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : EIO;
      (void)::ftruncate(fd, size);
      return error;
    }
    done += static_cast<size_t>(n);
  }
  return 0;
}

}  // namespace

Result<void> startJournal(const std::string& dir) {
  const int fd = ::open(journalPath(dir).c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) return journalError("cannot write " + journalPath(dir), errno);
  ::close(fd);
  return {};
}

Result<void> appendJournal(const CaseOutcome& outcome, const std::string& dir) {
  RAYSPEC_TRY(std::string line, jsonText(outcomeJson(outcome)));
  line += '\n';
  const int fd = ::open(journalPath(dir).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (fd < 0) return journalError("cannot append to " + journalPath(dir), errno);
  int error = appendWhole(fd, line);
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error) return journalError("cannot append to " + journalPath(dir), error);
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
  Result<std::string> text = readWholeFile(journalPath(dir), kMaxJournalBytes);
  if (!text) return inOneMessage(text.error());
  text->resize(text->rfind('\n') + 1);  // after the last newline: a line cut short (npos + 1 == 0)
  std::istringstream in(*text);
  std::map<std::string, size_t> at;  // case name -> its place in out
  std::string line;
  for (size_t number = 1; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    Result<CaseOutcome> o = journalLine(line);
    if (!o)
      return Error{SourceLoc{journalPath(dir), static_cast<int>(number), 1, ""}, o.error().message};
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
