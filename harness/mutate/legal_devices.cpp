#include "mutate/legal_devices.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string_view>

#include "compare/compare_results.h"
#include "fault/planted_fault.h"
#include "fault/record_edit.h"
#include "results/record_layout.h"
#include "results/tolerances.h"

namespace rayspec {
namespace {

// The most legal answers tried per ray: answer-1 .. answer-7.
constexpr uint32_t kMaxAnswers = 8;

using Variant = LegalVariant;

// A legal device made by the model, with whether it differs from `base`
// (the model's own answers as a device: perfectDevice).
Variant madeBy(const std::string& name, Results device, const Results& base,
               const std::string& what) {
  Variant v{name, std::move(device), false, what};
  if (!v.device.ok()) {
    v.what = "the model does not run so: " + v.device.statusText();
    return v;
  }
  v.applied = !sameOutput(v.device, base);
  if (!v.applied) v.what = "changes nothing here: " + what;
  return v;
}

// answer-<j>: every ambiguous ray takes its j-th legal answer.
std::vector<Variant> answerVariants(const Case& c, const Plan& plan, const Results& model,
                                    const Results& base, unsigned threads) {
  size_t answers = 0;
  for (const RayAmbiguity& a : model.ambiguous) answers = std::max(answers, a.candidates.size());
  std::vector<Variant> out;
  for (uint32_t j = 1; j < std::min<size_t>(answers, kMaxAnswers); ++j)
    out.push_back(madeBy("answer-" + std::to_string(j), legalAnswerDevice(c, plan, j, threads),
                         base,
                         "every ambiguous ray takes legal answer " + std::to_string(j) +
                             " (modulo its number of answers)"));
  return out;
}

// replay-<j>: every ambiguous ray takes its j-th replayed legal answer
// (RayAmbiguity::replays, modulo their number): its record as a whole, the
// images' pixels from it, and the counters as that answer moves them.
Results replayedAnswers(const Results& base, const Results& model, size_t j) {
  Results d = base;
  const uint32_t words = recordWords();
  for (const RayAmbiguity& a : model.ambiguous) {
    if (a.replays.empty() || a.replays[0].record.size() != words) continue;
    const LegalReplay& r = a.replays[j % a.replays.size()];
    std::copy(r.record.begin(), r.record.end(), &d.records[size_t{a.ray} * words]);
    for (Image& im : d.images) {
      const RecordField* f = findRecordField(im.field);
      if (!f) continue;
      for (uint32_t k = 0; k < im.channels; ++k)
        im.texels[size_t{a.ray} * im.channels + k] =
            k < f->words ? r.record[f->offset + k] : (k == 3 ? std::bit_cast<uint32_t>(1.0f) : 0u);
    }
    for (const auto& [name, move] : r.counter_moves)
      d.counters[name] = static_cast<uint64_t>(static_cast<int64_t>(d.counters[name]) + move);
  }
  return d;
}

std::vector<Variant> replayVariants(const Results& model, const Results& base) {
  size_t most = 0;
  for (const RayAmbiguity& a : model.ambiguous) most = std::max(most, a.replays.size());
  std::vector<Variant> out;
  for (size_t j = 1; j < std::min<size_t>(most, kMaxAnswers); ++j)
    out.push_back(madeBy("replay-" + std::to_string(j), replayedAnswers(base, model, j), base,
                         "every ambiguous ray leaves its legal answer " + std::to_string(j) +
                             " replayed through the launch ray (modulo their number)"));
  return out;
}

Variant passBetween(const Case& c, const Plan& plan, const Results& model, const Results& base,
                    unsigned threads) {
  const bool any = std::any_of(model.ambiguous.begin(), model.ambiguous.end(),
                               [](const RayAmbiguity& a) { return !a.leak_answers.empty(); });
  if (!any)
    return {"pass-between-edges", {}, false, "no ray where passing between changes the answer"};
  return madeBy("pass-between-edges", passBetweenEdgesDevice(c, plan, threads), base,
                "rays through a shared edge or vertex pass between its triangles");
}

bool hasBoxes(const Case& c) {
  bool boxes = false;
  for (const Blas& b : c.scene.blases)
    for (const Geometry& g : b.geometries) boxes = boxes || g.kind == Geometry::Kind::Aabbs;
  return boxes;
}

// aabb-neighbours: intersection programs run for the boxes beside the
// entered ones too (R-AABB-CONS).
Variant aabbNeighbours(const Case& c, const Plan& plan, const Results& base, unsigned threads) {
  if (!hasBoxes(c)) return {"aabb-neighbours", {}, false, "no AABB geometry"};
  return madeBy("aabb-neighbours", aabbNeighboursDevice(c, plan, threads), base,
                "intersection programs run for every box grown by its own extent on each side");
}

// aabb-near: intersection programs run for every box a ray passes within a
// device's error bound of, missed or not (R-AABB-CONS, R-PREC).
Variant aabbNear(const Case& c, const Plan& plan, const Results& base, unsigned threads) {
  if (!hasBoxes(c)) return {"aabb-near", {}, false, "no AABB geometry"};
  return madeBy("aabb-near", aabbNearDevice(c, plan, threads), base,
                "intersection programs run for every box a ray misses by no more than a "
                "device's error bound (the origin's magnitude's rounding)");
}

// Each planted fault the catalog calls legal, on the model's own answer.
std::vector<Variant> legalFaults(const Case& c, const Plan& plan, const Results& model,
                                 const Results& base) {
  std::vector<Variant> out;
  for (const FaultInfo& f : faultTable()) {
    if (f.breaks.rfind("legal:", 0) != 0) continue;
    Variant v{f.name, base, false, f.breaks};
    const FaultResult r = plantFault(f.name, c, plan, v.device, model);
    v.applied = r.applied && !sameOutput(v.device, base);
    v.what = r.applied ? f.breaks + " (" + r.what + ")" : r.what;
    out.push_back(std::move(v));
  }
  return out;
}

// The bound the model widens a field of one ray to (Results::t_bounds for
// hit_t, position_bounds for hit_position), 0 when none.
double modelBound(const Results& model, const char* field, uint32_t ray) {
  const std::vector<TBound>* bounds = std::string_view(field) == "hit_t" ? &model.t_bounds
                                      : std::string_view(field) == "hit_position"
                                          ? &model.position_bounds
                                          : nullptr;
  if (bounds)
    for (const TBound& b : *bounds)
      if (b.ray == ray) return b.bound;
  return 0;
}

// tolerance-bound: each written hit_t, hit_position and barycentric moved up
// by 0.9 of its allowed error, the model's bound of that ray included (a
// sphere root's t and the position it gives).
Variant toleranceBound(const Results& base, const Results& model) {
  Variant v{"tolerance-bound", base, false, ""};
  RecordEdit dev{v.device};
  size_t moved = 0;
  for (uint32_t ray = 0; ray < dev.rays(); ++ray)
    for (const auto& [field, words] : {std::pair<const char*, uint32_t>{"hit_t", 1u},
                                       std::pair<const char*, uint32_t>{"hit_position", 3u},
                                       std::pair<const char*, uint32_t>{"barycentrics", 2u}}) {
      if (!findRecordField(field) || findRecordField(field)->automatic || !dev.written(ray, field))
        continue;
      const Tolerance tol = toleranceFor(field);
      const double bound = modelBound(model, field, ray);
      for (uint32_t w = 0; w < words; ++w) {
        const float x = dev.getFloat(ray, field, w);
        if (!std::isfinite(x)) continue;
        const double own = tol.abs + tol.rel * std::max(std::fabs(double(x)), 1.0);
        dev.setFloat(ray, field, static_cast<float>(x + 0.9 * std::max(own, bound)), w);
        ++moved;
      }
    }
  v.applied = moved > 0;
  v.what = moved ? std::to_string(moved) +
                       " hit_t, hit_position and barycentric values moved by 0.9 of their "
                       "tolerance or the model's bound"
                 : "no hit_t, hit_position or barycentrics recorded";
  return v;
}

}  // namespace

LegalDevice judgeLegalVariant(const Case& c, const Plan& plan, const Results& model,
                              LegalVariant& v, Verdict* verdict_out) {
  LegalDevice d;
  d.name = v.name;
  d.applied = v.applied;
  d.what = v.what;
  if (!v.applied) return d;
  v.device.backend = "vulkan";
  const Verdict verdict = compareResults(c, plan, v.device, model);
  d.status = verdict.status;
  d.headline = verdict.headline();
  d.false_alarm = isFailing(verdict.status);
  for (const Finding& f : verdict.findings)
    if (d.false_alarm && d.rule.empty() && isFailing(f.status)) {
      d.rule = f.rule;
      if (!f.rays.empty()) d.ray = f.rays[0];
    }
  if (verdict_out) *verdict_out = verdict;
  return d;
}

std::vector<LegalVariant> legalVariants(const Case& c, const Plan& plan, const Results& model,
                                        unsigned threads) {
  const Results base = perfectDevice(c, model);
  std::vector<Variant> variants;
  if (!model.records.empty()) {
    variants = answerVariants(c, plan, model, base, threads);
    for (Variant& v : replayVariants(model, base)) variants.push_back(std::move(v));
    variants.push_back(passBetween(c, plan, model, base, threads));
    variants.push_back(aabbNeighbours(c, plan, base, threads));
    variants.push_back(aabbNear(c, plan, base, threads));
    for (NamedDevice& d : lastCandidateDevices(c, plan, threads))
      variants.push_back(madeBy(d.name, std::move(d.device), base,
                                "candidate " + d.name.substr(5) +
                                    " (instance.geometry.primitive) decided after every other, "
                                    "the rest near to far"));
    variants.push_back(toleranceBound(base, model));
  }
  for (Variant& v : legalFaults(c, plan, model, base)) variants.push_back(std::move(v));
  return variants;
}

std::vector<LegalDevice> judgeLegalDevices(const Case& c, const Plan& plan, const Results& model,
                                           unsigned threads) {
  std::vector<LegalDevice> out;
  for (LegalVariant& v : legalVariants(c, plan, model, threads))
    out.push_back(judgeLegalVariant(c, plan, model, v));
  return out;
}

}  // namespace rayspec
