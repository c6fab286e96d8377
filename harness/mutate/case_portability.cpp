#include "mutate/case_portability.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "case/huge_rays.h"
#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "model/model_engine.h"
#include "plan/plan.h"

namespace rayspec {
namespace {

bool sameDeclaration(const NotPortable& a, const NotPortable& b) {
  return a.declaration.file == b.declaration.file && a.declaration.line == b.declaration.line &&
         a.declaration.column == b.declaration.column && a.change == b.change;
}

// A cause joins the problem of the same declaration (as one more device), or
// is a problem of its own.
void addCause(std::vector<NotPortable>& problems, NotPortable cause) {
  for (NotPortable& p : problems)
    if (sameDeclaration(p, cause)) {
      if (p.device != cause.device &&
          std::find(p.also.begin(), p.also.end(), cause.device) == p.also.end())
        p.also.push_back(cause.device);
      return;
    }
  problems.push_back(std::move(cause));
}

// Each legal device judged; those the judge fails diagnosed.
void judgeDevices(const Case& c, const Plan& plan, const Results& model, const Results& base,
                  unsigned threads, CasePortability& out) {
  std::vector<LegalVariant> variants = legalVariants(c, plan, model, threads);
  out.devices = variants.size();
  for (LegalVariant& v : variants) {
    Verdict verdict;
    const LegalDevice d = judgeLegalVariant(c, plan, model, v, &verdict);
    out.applied += d.applied;
    if (!d.false_alarm) continue;
    for (NotPortable& cause : notPortableCauses(c, plan, model, base, v, verdict))
      addCause(out.problems, std::move(cause));
  }
}

// A huge ray at a sphere-testing box (case/huge_rays.h): no legal set lists
// what a device's one rounding of its object-space ray leaves, so no legal
// device stands for it; the case is not portable by that definition.
NotPortable hugeRayProblem(const Case& c, const HugeSphereRay& h) {
  char distance[32];
  std::snprintf(distance, sizeof distance, "%.3g", h.distance);
  NotPortable p;
  p.device = "object-ray-rounding";
  p.what = "rounds the ray's object-space origin once, in float, as every device does";
  p.ray = int64_t(h.ray);
  const std::string tester =
      h.hit_group ? "whose intersection program (hit group " + std::to_string(*h.hit_group) + ")"
                  : "where a ray query's aabb block";
  p.finding =
      "R-PREC: its object-space origin lies " + std::string(distance) + " from box " +
      std::to_string(h.primitive) + " of geometry " + std::to_string(h.geometry) + " of instance " +
      std::to_string(h.instance) + ", " + tester +
      " tests the sphere inscribed in the box: that far away one rounding of the origin flips "
      "several of the program's decisions together and moves its roots beyond R-PREC's "
      "bound, and no legal set of answers can list them";
  p.declaration = h.ray < c.rays.list_locs.size() ? c.rays.list_locs[h.ray] : c.rays.defaults_loc;
  p.change = "start the ray nearer the boxes (under " + std::to_string(int(kHugeRayDistance)) +
             " in their object space) or test them without sphere_hit, sphere_near and "
             "sphere_far (case/huge_rays.h)";
  return p;
}

}  // namespace

CasePortability checkPortability(const Case& c, unsigned threads, Results* model_out) {
  CasePortability out;
  if (!modelInThisBuild()) {
    out.not_checked = "this run-only build has no model to check by";
    return out;
  }
  const auto start = std::chrono::steady_clock::now();
  const Plan plan = derivePlan(c);
  ModelOptions mo;
  mo.tier = ModelTier::Exact;
  mo.threads = threads;
  const Results model = runOnModel(c, plan, mo);
  if (model_out) *model_out = model;
  if (!model.ok()) {
    out.not_checked = "the model did not run it: " + model.statusText();
    return out;
  }
  out.checked = true;
  if (const std::optional<HugeSphereRay> huge = hugeRayAtSphereBox(c))
    out.problems.push_back(hugeRayProblem(c, *huge));
  // The model's own answers must pass first: a case the model finds at
  // fault fails every device alike.
  Results base = perfectDevice(c, model);
  base.backend = "vulkan";
  if (const Verdict own = compareResults(c, plan, base, model); isFailing(own.status)) {
    out.own_answers = own.headline();
    out.own_status = own.status;
  } else {
    judgeDevices(c, plan, model, base, threads, out);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::string notPortableText(const CasePortability& p) {
  // A Fail of the model against itself: every device that answers as the
  // model does would fail, the judge or the case is at fault, not the device.
  if (!p.own_answers.empty() && p.own_status != Status::CaseError)
    return "the model's own answers, as a device, do not pass the case (the judge or the case "
           "is at fault, not the device): " +
           p.own_answers;
  std::string out;
  for (const NotPortable& problem : p.problems)
    out += (out.empty() ? "" : "\n  ") + notPortableMessage(problem);
  return out;
}

}  // namespace rayspec
