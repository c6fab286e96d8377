#include "reduce/variant_judge.h"

#include <chrono>

namespace rayspec {

VariantJudge::VariantJudge(const RunOptions& run, std::string name, std::vector<std::string> labels,
                           FailureSignature signature, size_t max_attempts)
    : run_(run),
      name_(std::move(name)),
      labels_(std::move(labels)),
      signature_(std::move(signature)),
      max_attempts_(max_attempts),
      runner_(run, nullptr, nullptr) {}

CaseOutcome VariantJudge::judge(const std::string& text, bool* interrupted) const {
  *interrupted = false;
  const ParseResult parsed =
      parseCaseText(text, "reduced.yaml", name_, labels_.empty() ? nullptr : &labels_);
  if (!parsed.value || !parsed.errors.empty()) {
    std::string message = parsed.errors.empty() ? "cannot read the case" : "";
    for (const Error& e : parsed.errors) message += (message.empty() ? "" : "; ") + e.format();
    return caseErrorOutcome(name_, {}, "case-file", message);
  }
  const Case& c = *parsed.value;
  return guardCase(c.name, c.rules, [&] { return runner_.run(c, interrupted); });
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
  const CaseOutcome out = judge(text, &interrupted);
  Attempt a;
  a.what = what;
  a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (interrupted) {
    stopped_ = true;
    a.verdict = "interrupted";
    attempts_.push_back(a);
    return false;
  }
  const bool parsed = !(out.status == Status::CaseError && !out.verdict.findings.empty() &&
                        out.verdict.findings.front().rule == "case-file");
  a.ran = parsed;
  a.kept = failsTheSameWay(out, signature_);
  // The headline's first finding says enough for the log.
  const std::string headline =
      out.headline.size() > 200 ? out.headline.substr(0, 200) + " ..." : out.headline;
  a.verdict = a.kept ? "kept: " + headline
                     : (parsed ? "rejected: " : "rejected, does not parse: ") + headline;
  attempts_.push_back(a);
  seen_[text] = a.kept;
  if (a.kept) kept_[text] = out;
  return a.kept;
}

const CaseOutcome* VariantJudge::keptOutcome(const std::string& text) const {
  const auto it = kept_.find(text);
  return it == kept_.end() ? nullptr : &it->second;
}

}  // namespace rayspec
