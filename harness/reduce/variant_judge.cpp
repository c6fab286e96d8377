#include "reduce/variant_judge.h"

#include <chrono>
#include <filesystem>

#include "base/whole_file.h"
#include "reduce/device_command.h"
#include "report/outcome_json.h"

namespace rayspec {
namespace {

RunOptions withoutFault(RunOptions run) {
  run.plant_fault.clear();
  return run;
}

}  // namespace

VariantJudge::VariantJudge(const RunOptions& run, std::string name, std::vector<std::string> labels,
                           FailureSignature signature, size_t max_attempts,
                           std::string device_command)
    : run_(run),
      name_(std::move(name)),
      labels_(std::move(labels)),
      signature_(std::move(signature)),
      max_attempts_(max_attempts),
      runner_(run, nullptr, nullptr),
      clean_run_(withoutFault(run)),
      clean_runner_(clean_run_, nullptr, nullptr),
      device_command_(std::move(device_command)) {}

CaseOutcome VariantJudge::judgeByCommand(const std::string& text, const Case& c,
                                         bool* interrupted) const {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::absolute(fs::path(run_.out) / ("variant-" + std::to_string(++commands_run_)));
  const fs::path cases = dir / "cases", device = dir / "device";
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories((cases / name_).parent_path(), ec);
  if (Result<void> written = writeWholeFile((cases / (name_ + ".yaml")).string(), text); !written)
    return caseErrorOutcome(name_, c.rules, "harness", written.error().format());
  // The paths reach the command as variables only: no shell line holds them.
  const DeviceCommand command{device_command_,
                              {{"RAYSPEC_VARIANT_CASES", cases.string()},
                               {"RAYSPEC_VARIANT_NAME", name_},
                               {"RAYSPEC_VARIANT_OUT", device.string()}},
                              (dir / "command.log").string(),
                              run_.timeout};
  const ChildEnd end = runDeviceCommand(command);
  if (end.how == ChildEnd::How::Interrupted) {
    *interrupted = true;
    return caseErrorOutcome(name_, c.rules, "harness", "the device command was stopped");
  }
  const Result<SavedRun> ran = readSavedRun(device.string());
  if (ran) last_device_ = {ran->info.device, ran->info.icd};
  // Ran out of time, or ended badly leaving nothing to judge: the command is
  // no use, and the reduction stops (runReduce: exit 2).
  if (end.how == ChildEnd::How::TimedOut || (!end.ok() && !ran)) {
    command_failure_ = deviceCommandFailure(command, end);
    return caseErrorOutcome(name_, c.rules, "harness", command_failure_);
  }
  RunOptions saved = run_;
  saved.device_results = device.string();
  saved.out = (dir / "judged").string();
  const CaseRunner runner(saved, nullptr, nullptr);
  return guardCase(c.name, c.rules, [&] { return runner.run(c, interrupted); });
}

ParseResult VariantJudge::parse(const std::string& text, CaseOutcome* error) const {
  ParseResult parsed =
      parseCaseText(text, "reduced.yaml", name_, labels_.empty() ? nullptr : &labels_);
  if ((!parsed.value || !parsed.errors.empty()) && error) {
    std::string message = parsed.errors.empty() ? "cannot read the case" : "";
    for (const Error& e : parsed.errors) message += (message.empty() ? "" : "; ") + e.format();
    *error = caseErrorOutcome(name_, {}, "case-file", message);
  }
  return parsed;
}

CaseOutcome VariantJudge::judgeParsed(const std::string& text, const Case& c,
                                      bool* interrupted) const {
  if (!device_command_.empty()) return judgeByCommand(text, c, interrupted);
  return guardCase(c.name, c.rules, [&] { return runner_.run(c, interrupted); });
}

CaseOutcome VariantJudge::judge(const std::string& text, bool* interrupted) const {
  *interrupted = false;
  CaseOutcome error;
  const ParseResult parsed = parse(text, &error);
  if (!parsed.value || !parsed.errors.empty()) return error;
  return judgeParsed(text, *parsed.value, interrupted);
}

std::string VariantJudge::failureWithoutTheFault(const Case& c, bool* interrupted) const {
  if (run_.plant_fault.empty()) return "";
  const CaseOutcome clean =
      guardCase(c.name, c.rules, [&] { return clean_runner_.run(c, interrupted); });
  return isFailing(clean.status) ? "fails without the fault too: " + clean.headline : "";
}

bool VariantJudge::fails(const std::string& text, const std::string& what) {
  if (const auto it = seen_.find(text); it != seen_.end()) return it->second;
  if (stopped_) return false;
  if (attempts_.size() >= max_attempts_) {
    stopped_ = true;
    return false;
  }
  const auto start = std::chrono::steady_clock::now();
  bool interrupted = false;
  CaseOutcome out;
  const ParseResult parsed_case = parse(text, &out);
  const bool parsed = parsed_case.value && parsed_case.errors.empty();
  if (parsed) out = judgeParsed(text, *parsed_case.value, &interrupted);
  Attempt a;
  a.what = what;
  a.ran = parsed;
  a.kept = !interrupted && failsTheSameWay(out, signature_);
  // With a planted fault, the failure must be the fault's alone.
  const std::string clean_failure =
      a.kept ? failureWithoutTheFault(*parsed_case.value, &interrupted) : "";
  a.kept = a.kept && clean_failure.empty();
  // A step must keep the case portable: a correct device still passes it.
  const std::string not_portable = a.kept && !interrupted && portability_
                                       ? portability_->whyNotPortable(*parsed_case.value)
                                       : "";
  a.kept = a.kept && not_portable.empty();
  a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (interrupted || !command_failure_.empty()) {
    stopped_ = true;
    a.kept = false;
    a.verdict = interrupted ? "interrupted" : command_failure_;
    attempts_.push_back(a);
    return false;
  }
  // The headline's first finding says enough for the log.
  const std::string headline =
      out.headline.size() > 200 ? out.headline.substr(0, 200) + " ..." : out.headline;
  const std::string why_not = !clean_failure.empty()  ? clean_failure
                              : !not_portable.empty() ? not_portable
                                                      : headline;
  a.verdict = a.kept
                  ? "kept: " + headline
                  : (parsed ? "rejected: " : "rejected, does not parse: ") + why_not.substr(0, 200);
  attempts_.push_back(a);
  seen_[text] = a.kept;
  if (a.kept) {
    kept_[text] = out;
    kept_device_ = last_device_;
  }
  return a.kept;
}

const CaseOutcome* VariantJudge::keptOutcome(const std::string& text) const {
  const auto it = kept_.find(text);
  return it == kept_.end() ? nullptr : &it->second;
}

}  // namespace rayspec
