#include "run/case_check.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "run/case_steps.h"
#include "run/child_process.h"

namespace rayspec {
namespace {

// The check's message, run in a child process; the error: why it did not finish.
Result<std::string> runCheckIsolated(const CaseCheck& check, const Case& c, const RunOptions& opt) {
  const ChildLimits limits{opt.timeout, opt.memory_limit};
  const ChildEnd end = runChild(
      [&](std::string& message) {
        message = check(c);
        return 0;
      },
      limits);
  if (end.ok()) return end.message;
  return errorMessage(describeChildEnd(end, "the check", limits));
}

}  // namespace

bool insideFolder(const std::string& path, const std::string& folder) {
  std::error_code ec;
  const std::filesystem::path file = std::filesystem::weakly_canonical(path, ec);
  if (ec) return false;
  const std::filesystem::path dir = std::filesystem::weakly_canonical(folder, ec);
  if (ec) return false;
  const std::filesystem::path rel = file.lexically_relative(dir);
  return !rel.empty() && *rel.begin() != ".." && rel != ".";
}

bool checksCase(const RunOptions& opt, const CaseFile& file) {
  if (opt.check_case) return *opt.check_case;
  return !insideFolder(file.path, kLibraryCasesDir);
}

CheckedCase checkedCase(const CaseCheck& check, const Case& c, const RunOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  Result<std::string> message =
      opt.no_isolation ? Result<std::string>(check(c)) : runCheckIsolated(check, c, opt);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool passed = message && message->empty();
  if (!opt.brief || !passed)
    std::printf("        %s: checked against the devices the specification allows: %s (%.1f s)\n",
                c.name.c_str(),
                passed    ? "portable"
                : message ? "not portable"
                          : "not finished, the case runs unchecked",
                seconds);
  CheckedCase out;
  if (!message)
    out.not_checked =
        "not checked against the devices the specification allows: " + message.error().message +
        " (`rayspec check` has no time limit)";
  else if (!passed)
    out.refused = caseErrorOutcome(c.name, c.rules, "not-portable", *message);
  return out;
}

}  // namespace rayspec
