#include "reduce/failure_signature.h"

#include <algorithm>
#include <cctype>
#include <set>

namespace rayspec {
namespace {

bool isRuleLabel(const std::string& keep) {
  return keep.rfind("R-", 0) == 0;
}

FailureSignature signatureOf(const CaseOutcome& o, const Finding& f, bool any_kind) {
  FailureSignature s;
  s.status = o.status;
  s.finding = f.status;
  s.rule = f.rule;
  s.kind = any_kind ? "" : findingKind(f.message);
  s.message = f.message;
  s.undefined_allowed = !o.verdict.undefined.empty();
  return s;
}

bool ended(Status s) {
  return s == Status::Crash || s == Status::Timeout;
}

}  // namespace

bool ruleMatches(const Finding& f, const FailureSignature& s) {
  return s.rule_among_labels ? findingNames(f, s.rule) : f.rule == s.rule;
}

std::string findingKind(const std::string& message) {
  std::string out;
  for (size_t i = 0; i < message.size(); ++i) {
    if (std::isdigit(static_cast<unsigned char>(message[i]))) {
      if (out.empty() || out.back() != '#') out += '#';
    } else {
      out += message[i];
    }
  }
  // A list of numbers ("rays 3, 17") is one number's worth of kind.
  for (size_t at; (at = out.find("#, #")) != std::string::npos;) out.replace(at, 4, "#");
  return out;
}

std::optional<FailureSignature> failureToKeep(const CaseOutcome& o, const std::string& keep) {
  if (keep == "crash") {
    if (!ended(o.status)) return std::nullopt;
    for (const Finding& f : o.verdict.findings)
      if (f.status == o.status) return signatureOf(o, f, true);
    return std::nullopt;
  }
  if (keep.empty() && o.status != Status::Fail) return std::nullopt;
  if (o.status != Status::Fail && o.status != Status::QualityWarning) return std::nullopt;
  for (const Finding& f : o.verdict.findings) {
    if (f.status != Status::Fail && f.status != Status::QualityWarning) continue;
    if (keep.empty() && f.status == o.status) return signatureOf(o, f, false);
    if (!keep.empty() && isRuleLabel(keep) && findingNames(f, keep)) {
      FailureSignature s = signatureOf(o, f, true);
      s.rule = keep;
      s.rule_among_labels = true;
      return s;
    }
    if (!keep.empty() && !isRuleLabel(keep) && f.message.find(keep) != std::string::npos)
      return signatureOf(o, f, false);
  }
  return std::nullopt;
}

bool failsTheSameWay(const CaseOutcome& o, const FailureSignature& s) {
  if (o.status != s.status) return false;
  if (!s.undefined_allowed && !o.verdict.undefined.empty()) return false;
  for (const Finding& f : o.verdict.findings)
    if (f.status == s.finding && ruleMatches(f, s) &&
        (s.kind.empty() || findingKind(f.message) == s.kind))
      return true;
  return false;
}

std::vector<uint32_t> failingRays(const CaseOutcome& o, const FailureSignature& s) {
  std::set<uint32_t> rays;
  for (const Finding& f : o.verdict.findings)
    if (ruleMatches(f, s) && f.status == s.finding) rays.insert(f.rays.begin(), f.rays.end());
  return {rays.begin(), rays.end()};
}

}  // namespace rayspec
