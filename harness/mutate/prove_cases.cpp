// `rayspec prove`: the proof of each case printed claim by claim.
#include "mutate/prove_cases.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "fault/planted_fault.h"
#include "fault/prove_case.h"
#include "library/case_discovery.h"
#include "mutate/fault_listing.h"
#include "mutate/prove_live.h"
#include "report/rule_catalog.h"

namespace rayspec {
namespace {

struct Tally {
  size_t cases = 0, claims = 0, proved = 0, not_checked = 0, not_proved = 0, unprovable_cases = 0;
  bool bad_input = false;
};

constexpr const char* kWhere =
    "Device: the model's exact tier stands for a device that passes; each fault of a claimed "
    "rule is planted in its results (record edits) or made by the model tracing the case as the "
    "faulty device sees it (case mutations). No Vulkan device is used, but with --device or "
    "--icd for the faults a live device alone shows, planted in real runs of a case whose claim "
    "the model's faults leave hollow.\n";

// A claim the model's faults leave hollow, tried with its rule's live
// faults on the device (--device, --icd), or those faults named.
bool provedLive(const ClaimProof& p, const Case& c, const CaseFile& f, const ProveOptions& opt) {
  const RuleFaults* rf = findRuleFaults(p.rule);
  if (claimHolds(p) || !rf || rf->live.empty()) return false;
  if (!opt.live) {
    std::printf(
        "    faults a live device alone shows: %s (rayspec run --case %s --plant-fault "
        "NAME, or rayspec prove --device NAME)\n",
        commaList(rf->live).c_str(), f.path.c_str());
    return false;
  }
  const LiveProof live = proveOnDevice(opt.run, c, *rf);
  for (const std::string& tried : live.tried)  // one finding of each
    std::printf("    on the device: %s\n", tried.c_str());
  if (live.fault.empty()) {
    std::printf("    on the device: %s\n", live.headline.c_str());
    return false;
  }
  std::printf("  %s: proved on the device by %s\n", p.rule.c_str(), live.fault.c_str());
  return true;
}

// One claim: the fault that proved it, or every fault tried and what each did.
void printClaim(const ClaimProof& p, const Case& c, const CaseFile& f, const ProveOptions& opt,
                Tally& t) {
  ++t.claims;
  const FaultOutcome* by = provingFault(p);
  if (by && !opt.verbose) {
    ++t.proved;
    // The finding naming the claim, not the verdict's worst; -v prints every fault's.
    std::printf("  %s: proved by %s: %s\n", p.rule.c_str(), by->fault.c_str(),
                by->claim_line.c_str());
    return;
  }
  if (p.result == ClaimResult::Proven && !opt.verbose) {
    ++t.proved;
    // A rule that only grants a freedom (R-ISECT-MULTI), or none of whose
    // breaks applies: a legal variation changed the results and still passes.
    std::printf("  %s: proved by a legal variation the case tolerates\n", p.rule.c_str());
    return;
  }
  std::printf("  %s%s\n", claimHolds(p) ? "" : "NOT PROVED ON THE MODEL: ", p.describe().c_str());
  const bool live = provedLive(p, c, f, opt);
  ++(p.result == ClaimResult::Proven || live ? t.proved
     : claimHolds(p)                         ? t.not_checked
                                             : t.not_proved);
}

// The case's proof, or why it cannot be proven (the model does not run or
// does not pass its own case, or the case depends on the candidate order).
void printProof(const CaseFile& f, const Case& c, const ProveOptions& opt, Tally& t) {
  const auto start = std::chrono::steady_clock::now();
  const CaseProof proof = proveCase(c, opt.threads);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++t.cases;
  const size_t not_proved = t.not_proved;
  std::printf("\n%s (%s), proved on the model in %.2f s\n", f.name.c_str(), f.path.c_str(),
              seconds);
  if (!proof.model.ok())
    std::printf("  CANNOT PROVE: the model does not run the case: %s\n",
                proof.model.statusText().c_str());
  else if (proof.clean.status != Status::Pass)
    std::printf("  CANNOT PROVE: the model as the device does not pass the case: %s\n",
                proof.clean.headline().c_str());
  for (const ClaimProof& p : proof.claims) printClaim(p, c, f, opt, t);
  if (proof.model.ok() && proof.clean.status == Status::Pass &&
      proof.reversed.status != Status::Pass)
    std::printf(
        "  NOT PORTABLE: a device finding candidates far to near (legal, R-ORDER-UNSPEC) "
        "gives %s\n",
        proof.reversed.headline().c_str());
  const bool judged = proof.model.ok() && proof.clean.status == Status::Pass;
  if (!judged || proof.reversed.status != Status::Pass || t.not_proved > not_proved)
    ++t.unprovable_cases;
}

// The cases of one command-line file (a sweep: each variant), parsed.
void proveFile(const std::string& path, const ProveOptions& opt,
               const std::vector<std::string>* catalog, Tally& t) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    std::fprintf(stderr, "rayspec prove: no such case file: '%s'\n", path.c_str());
    t.bad_input = true;
    return;
  }
  for (const CaseFile& f : caseFilesFor(path, opt.cases_dir)) {
    ParseResult parsed = loadCase(f, opt.cases_dir, catalog);
    for (const Error& e : parsed.errors) std::fprintf(stderr, "%s\n", e.format().c_str());
    if (!parsed.value) {
      t.bad_input = true;
      continue;
    }
    printProof(f, *parsed.value, opt, t);
  }
}

}  // namespace

int runProve(const ProveOptions& opt) {
  const Result<std::vector<Rule>> loaded = loadRuleCatalog(opt.rules_file);
  if (!loaded)
    std::fprintf(stderr, "rayspec prove: %s (rule labels not checked)\n",
                 loaded.error().format().c_str());
  const std::vector<std::string> labels = loaded ? ruleLabels(*loaded) : std::vector<std::string>{};
  std::printf("%s", kWhere);
  if (opt.live) {
    const Result<std::string> device = startLiveDevice(opt.run, {});
    if (!device) {
      std::fprintf(stderr, "rayspec prove: %s\n", device.error().format().c_str());
      return 2;
    }
    std::printf("Live device: %s\n", device->c_str());
  }
  Tally t;
  for (const std::string& path : opt.files) proveFile(path, opt, loaded ? &labels : nullptr, t);
  std::printf(
      "\n%zu cases, %zu claims: %zu proved, %zu not checked (R-UB), %zu not proved; %zu cases not "
      "proven\n",
      t.cases, t.claims, t.proved, t.not_checked, t.not_proved, t.unprovable_cases);
  if (t.bad_input) return 2;
  return t.unprovable_cases == 0 ? 0 : 1;
}

}  // namespace rayspec
