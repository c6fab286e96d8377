#include "run/case_as_run.h"

#include <charconv>

#include "metamorphic/feature_path.h"
#include "metamorphic/motion_spec.h"
#include "metamorphic/permute_case.h"

namespace rayspec {
namespace {

// A case the variant does not run: NotSupported, saying why (its verdict
// under the variant is unknown, never a pass), skipped by the baseline (its
// expectation is neither met nor broken).
CaseOutcome notRunOutcome(const std::string& name, const std::string& rule,
                          const std::string& message, const std::string& note) {
  CaseOutcome o;
  o.name = name;
  o.verdict.add({Status::NotSupported, rule, message, {}, 0});
  o.deriveFromVerdict();
  o.baseline = BaselineMatch::Skipped;
  o.baseline_note = note;
  return o;
}

// One part of a variant ("permute 7") into opt.
Result<void> variantPart(const std::string& part, RunOptions& opt) {
  const size_t space = part.find(' ');
  const std::string key = part.substr(0, space);
  const std::string value = space == std::string::npos ? "" : part.substr(space + 1);
  if (key == "through") {
    opt.through = featurePathFromName(value);
    if (!opt.through) return errorMessage("'" + part + "': no feature path '" + value + "'");
  } else if (key == "permute") {
    uint64_t seed = 0;
    const char* end = value.data() + value.size();
    const std::from_chars_result read = std::from_chars(value.data(), end, seed);
    if (value.empty() || read.ec != std::errc() || read.ptr != end)
      return errorMessage("'" + part + "': the seed is no unsigned integer");
    opt.permute = seed;
  } else if (key == "move") {
    Result<RigidMotion> motion = parseMotionSpec(value);
    if (!motion) return errorMessage("'" + part + "': " + motion.error().message);
    opt.move = *motion;
  } else {
    return errorMessage("'" + part + "' is none of through, permute, move");
  }
  return {};
}

// The case permuted as --permute asks; in place of it, when the permutation
// moves nothing and no other part of the variant changes the case, the
// NotSupported outcome saying so: the run would repeat the plain run's, and
// its verdict cannot move (builtins/launch-wide: one triangle, 4M ids).
CaseAsRun permutedCase(const Case& parsed, const RunOptions& opt) {
  CaseAsRun out;
  CasePermutation p = permuteCase(parsed, *opt.permute);
  if (p.movedAnything() || opt.move || opt.through) {
    out.runs = std::move(p.permuted);
    return out;
  }
  out.not_run = notRunOutcome(
      parsed.name, "permute",
      "not run: --permute " + std::to_string(*opt.permute) +
          " moves nothing in this case (each geometry's primitives, its vertices and the "
          "instances keep their order: one of each, ids its programs observe exactly, or the "
          "seed's shuffle leaves them), so the permuted case is the case as written",
      "not run under --permute: nothing to permute");
  return out;
}

}  // namespace

CaseAsRun caseAsRun(const Case& parsed, const RunOptions& opt) {
  CaseAsRun out;
  if (opt.permute) {
    out = permutedCase(parsed, opt);
    if (out.not_run) return out;
  }
  Case c = opt.permute ? std::move(*out.runs) : parsed;
  if (opt.move) {
    Result<Case> moved = moveCase(c, *opt.move, MoveScope::Verdict);
    if (!moved) {
      out.not_run =
          notRunOutcome(parsed.name, "move",
                        "not run: --move cannot move this case exactly: " + moved.error().message,
                        "not run under --move");
      return out;
    }
    c = std::move(*moved);
  }
  if (opt.through) {
    Result<Case> through = throughPath(c, *opt.through);
    if (!through) {
      out.not_run =
          notRunOutcome(parsed.name, "through",
                        std::string("not run: --through ") + featurePathName(*opt.through) + ": " +
                            through.error().message,
                        "not run under --through");
      return out;
    }
    c = std::move(*through);
  }
  out.runs = std::move(c);
  return out;
}

Result<void> variantOptions(const std::string& variant, RunOptions& opt) {
  opt.through.reset();
  opt.permute.reset();
  opt.move.reset();
  for (size_t at = 0; at < variant.size();) {
    const size_t end = variant.find("; ", at);
    RAYSPEC_TRY_VOID(variantPart(variant.substr(at, end - at), opt));
    at = end == std::string::npos ? variant.size() : end + 2;
  }
  // Each part once, in runVariant's order and form.
  if (runVariant(opt) != variant)
    return errorMessage("'" + variant + "' is not a variant as rayspec writes it ('" +
                        runVariant(opt) + "')");
  return {};
}

}  // namespace rayspec
