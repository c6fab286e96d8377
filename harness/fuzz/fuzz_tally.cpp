#include "fuzz/fuzz_tally.h"

#include <cstdio>
#include <set>

#include "reduce/failure_signature.h"

namespace rayspec {
namespace {

// The findings by which the model's checks refuse a case: the case is at
// fault, not the device (cases/README.md, "How a case is judged").
bool refusingRule(const std::string& rule) {
  static const std::set<std::string> kRules = {"case-file",      "R-UB",      "R-AHIT-DUP",
                                               "R-ORDER-UNSPEC", "R-RQ-INIT", "not-portable"};
  return kRules.count(rule) != 0;
}

const Finding* worstFinding(const CaseOutcome& o) {
  for (const Finding& f : o.verdict.findings)
    if (f.status == o.status) return &f;
  return o.verdict.findings.empty() ? nullptr : &o.verdict.findings.front();
}

// Letters, digits, '-' and '_'; every other run of characters one '_'; at most 60.
std::string fileWord(const std::string& text) {
  std::string out;
  for (char c : text) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '-';
    if (keep)
      out += c;
    else if (!out.empty() && out.back() != '_')
      out += '_';
    if (out.size() >= 60) break;
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

}  // namespace

FuzzClass classify(const CaseOutcome& o) {
  const Finding* f = worstFinding(o);
  const std::string rule = f ? f->rule : "";
  const std::string message = f ? f->message : "";
  switch (o.status) {
    case Status::Pass:
      return FuzzClass::Pass;
    case Status::NotSupported:
      return FuzzClass::NotSupported;
    case Status::CaseError:
      return refusingRule(rule) ? FuzzClass::Refused : FuzzClass::RayspecDefect;
    case Status::Crash:
    case Status::Timeout:
      // The model's own crash or hang: nothing judged the device.
      return message.rfind("model", 0) == 0 ? FuzzClass::RayspecDefect : FuzzClass::Finding;
    case Status::Fail:
    case Status::QualityWarning:
      return FuzzClass::Finding;
  }
  return FuzzClass::Finding;
}

FuzzSignature signatureOf(const CaseOutcome& o) {
  const Finding* f = worstFinding(o);
  FuzzSignature s{statusName(o.status), f ? f->rule : "", f ? findingKind(f->message) : "", ""};
  // The kind is long: its first words and a hash of all of it.
  uint32_t h = 2166136261u;  // FNV-1a
  for (unsigned char c : s.kind) h = (h ^ c) * 16777619u;
  char hash[12];
  std::snprintf(hash, sizeof hash, "%08x", h);
  // The rule is left out: most findings carry the case's own claims.
  s.folder = fileWord(s.status + "_" + s.kind.substr(0, 48)) + "_" + hash;
  return s;
}

const FuzzTally::Group* FuzzTally::add(uint64_t seed, const CaseOutcome& o,
                                       const KnownClass* known) {
  ++run;
  ++statuses[statusName(o.status)];
  const FuzzClass c = classify(o);
  if (c == FuzzClass::Refused) {
    ++refused;
    ++refusals[signatureOf(o).rule];
  }
  if (c != FuzzClass::Finding && c != FuzzClass::RayspecDefect) return nullptr;
  FuzzSignature s = signatureOf(o);
  // A defect of ours is never a driver's known bug.
  // Grouped by the known class too: one signature may show two known bugs.
  if (known && c == FuzzClass::Finding) s.folder = "known_" + known->feature + "_" + s.folder;
  auto [it, opened] = findings.try_emplace(s.folder);
  Group& g = it->second;
  g.signature = s;
  g.rayspec_defect = c == FuzzClass::RayspecDefect;
  if (known && c == FuzzClass::Finding) g.known = known->feature + ": " + known->reason;
  g.seeds.push_back(seed);
  return opened ? &g : nullptr;
}

size_t FuzzTally::findingCases(bool known) const {
  size_t n = 0;
  for (const auto& [folder, g] : findings)
    if (g.known.empty() != known) n += g.seeds.size();
  return n;
}

std::string FuzzTally::text() const {
  std::string t = "rayspec fuzz: seeds " + std::to_string(first_seed) + " .. " +
                  std::to_string(first_seed + (generated ? generated - 1 : 0)) +
                  (variant.empty() ? "" : " (" + variant + ")") + "\n";
  char line[256];
  std::snprintf(line, sizeof line,
                "cases generated %zu, run %zu, refused by the checks %zu; %.1f s, %.1f cases a "
                "minute\n",
                generated, run, refused, seconds, seconds > 0 ? 60.0 * double(run) / seconds : 0.0);
  t += line;
  if (unjudged)
    t += "not judged: " + std::to_string(unjudged) +
         " seeds whose saved case is missing or not the text their bundle ran (stderr names "
         "each)\n";
  t += "statuses:";
  for (const auto& [name, n] : statuses) t += " " + name + " " + std::to_string(n);
  t += "\nrefused by rule:";
  for (const auto& [rule, n] : refusals) t += " " + rule + " " + std::to_string(n);
  t += "\nfindings: " + std::to_string(findingCases(false)) + " cases new, " +
       std::to_string(findingCases(true)) +
       " cases of known classes (their case holds a known bug's feature: a coarse match), " +
       std::to_string(findings.size()) + " signatures (OUT/findings/<signature>/)\n";
  for (const auto& [folder, g] : findings) {
    t += "  " + std::to_string(g.seeds.size()) + "  " + folder +
         (g.rayspec_defect ? "  [rayspec defect: a CaseError not of the checks, or the model's "
                             "crash: triage it as ours]"
                           : "") +
         (g.known.empty() ? "" : "  [known class: " + g.known + "]") + "\n      " +
         g.signature.status + " " + g.signature.rule + ": " + g.signature.kind.substr(0, 200) +
         "\n      seeds:";
    for (size_t i = 0; i < g.seeds.size() && i < 20; ++i) t += " " + std::to_string(g.seeds[i]);
    t += g.seeds.size() > 20 ? " ...\n" : "\n";
    if (!g.reduced.empty()) t += "      reduction: " + g.reduced + "\n";
  }
  return t;
}

}  // namespace rayspec
