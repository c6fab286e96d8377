#include "mutate/generic_mutant.h"

#include <algorithm>
#include <bit>
#include <optional>
#include <utility>

#include "fault/record_edit.h"
#include "results/record_layout.h"
#include "results/tolerances.h"

namespace rayspec {
namespace {

// The automatic run counts perturbed like a recorded field; what depends on
// traversal order (any-hit and intersection runs) has mutants of its own
// (extra, skipped).
bool perturbedAsField(const RecordField& f) {
  return !traversalDependent(f);
}

std::string raysText(size_t n) {
  return std::to_string(n) + (n == 1 ? " ray" : " rays");
}

Mutation notApplied(const std::string& why) {
  Mutation m;
  m.what = why;
  return m;
}

Mutation nullDevice(const MutantInput&, const std::string&, Results& d) {
  Mutation m;
  m.applied = true;
  m.what = "every counter, record word and texel 0, no shader rejected";
  std::fill(d.records.begin(), d.records.end(), 0u);
  d.rejected.clear();  // a case that expects rejections (R-STAGE-INTERFACE)
  for (auto& [name, value] : d.counters) value = 0;
  for (Image& im : d.images) std::fill(im.texels.begin(), im.texels.end(), 0u);
  const uint32_t rays = static_cast<uint32_t>(d.records.size() / recordWords());
  for (uint32_t r = 0; r < rays; ++r) m.rays.push_back(r);
  return m;
}

// uint + 1, float * 1.001 + 1e-3, on every ray that wrote the field.
Mutation perturbField(const MutantInput&, const std::string& field, Results& d) {
  RecordEdit e(d);
  const RecordField* f = findRecordField(field);
  Mutation m;
  m.field = field;
  for (uint32_t r = 0; r < e.rays(); ++r) {
    if (!e.written(r, field)) continue;
    for (uint32_t w = 0; w < f->words; ++w) {
      if (f->type == FieldType::Uint)
        e.set(r, field, e.get(r, field, w) + 1, w);
      else
        e.setFloat(r, field, e.getFloat(r, field, w) * 1.001f + 1e-3f, w);
    }
    m.rays.push_back(r);
  }
  if (m.rays.empty()) return notApplied("no ray wrote " + field);
  m.applied = true;
  m.what = field + (f->type == FieldType::Uint ? " + 1" : " * 1.001 + 1e-3") + " on " +
           raysText(m.rays.size());
  return m;
}

Mutation moveCounter(const std::string& counter, int delta, Results& d) {
  auto it = d.counters.find(counter);
  if (it == d.counters.end()) return notApplied("no counter " + counter);
  if (delta < 0 && it->second == 0) return notApplied("counter " + counter + " is 0");
  it->second = static_cast<uint64_t>(static_cast<int64_t>(it->second) + delta);
  Mutation m;
  m.applied = true;
  m.counter = counter;
  m.delta = delta;
  m.what = "counter " + counter + (delta > 0 ? " + 1" : " - 1");
  return m;
}
Mutation counterUp(const MutantInput&, const std::string& c, Results& d) {
  return moveCounter(c, 1, d);
}
Mutation counterDown(const MutantInput&, const std::string& c, Results& d) {
  return moveCounter(c, -1, d);
}

// The records of two rays differ where some rule looks: in what they wrote,
// or in a field beyond its tolerance (not in the any-hit and intersection run
// counts, which depend on traversal order).
bool recordsDiffer(const Results& d, uint32_t a, uint32_t b) {
  const uint32_t words = recordWords();
  const uint32_t* ra = &d.records[a * words];
  const uint32_t* rb = &d.records[b * words];
  if (!sameWrittenMask(ra, rb)) return true;
  for (const RecordField& f : recordFields()) {
    if (!perturbedAsField(f)) continue;
    const Tolerance tol = toleranceFor(f.name);
    for (uint32_t k = 0; k < f.words; ++k) {
      const uint32_t x = ra[f.offset + k], y = rb[f.offset + k];
      if (f.type == FieldType::Uint
              ? x != y
              : !tol.matches(std::bit_cast<float>(x), std::bit_cast<float>(y)))
        return true;
    }
  }
  return false;
}

// The first eligible ray and the first eligible ray after it whose records
// differ from its. When none does, every eligible ray matches the first
// (within the fields' tolerances) and there is nothing worth swapping. Linear:
// a launch of 20,000 rays with one answer (cts-amber/basic2) is no quadratic
// search.
std::optional<std::pair<uint32_t, uint32_t>> firstDifferingPair(const Results& d,
                                                                const std::vector<bool>& eligible) {
  const auto first = std::find(eligible.begin(), eligible.end(), true);
  if (first == eligible.end()) return std::nullopt;
  const uint32_t a = static_cast<uint32_t>(first - eligible.begin());
  for (uint32_t b = a + 1; b < eligible.size(); ++b)
    if (eligible[b] && recordsDiffer(d, a, b)) return std::make_pair(a, b);
  return std::nullopt;
}

// Records (and pixels) of the first two rays that differ, clear rays first.
Mutation swapRays(const MutantInput& in, const std::string&, Results& d) {
  const uint32_t words = recordWords();
  const uint32_t rays = static_cast<uint32_t>(d.records.size() / words);
  std::vector<bool> clear(rays, true);
  for (const RayAmbiguity& a : in.model.ambiguous)
    if (a.ray < rays) clear[a.ray] = false;
  for (const UndefinedRay& u : in.model.undefined)
    if (u.ray < rays) clear[u.ray] = false;
  auto pair = firstDifferingPair(d, clear);
  if (!pair) pair = firstDifferingPair(d, std::vector<bool>(rays, true));
  if (!pair) return notApplied("no two rays with different records");
  const auto [a, b] = *pair;
  std::swap_ranges(d.records.begin() + a * words, d.records.begin() + (a + 1) * words,
                   d.records.begin() + b * words);
  for (Image& im : d.images) {
    if (static_cast<size_t>(b) >= static_cast<size_t>(im.width) * im.height) continue;
    std::swap_ranges(im.texels.begin() + a * im.channels, im.texels.begin() + (a + 1) * im.channels,
                     im.texels.begin() + b * im.channels);
  }
  Mutation m;
  m.applied = true;
  m.rays = {a, b};
  m.what = "records of rays " + std::to_string(a) + " and " + std::to_string(b) + " swapped";
  return m;
}

// Every ray that ran one of miss and closest-hit runs the other too.
Mutation missAndClosestHit(const MutantInput&, const std::string&, Results& d) {
  RecordEdit e(d);
  Mutation m;
  for (uint32_t r = 0; r < e.rays(); ++r) {
    const uint32_t miss = e.get(r, "miss_runs"), chit = e.get(r, "closest_hit_runs");
    if ((miss == 0) == (chit == 0)) continue;
    e.set(r, miss ? "closest_hit_runs" : "miss_runs", 1);
    m.rays.push_back(r);
  }
  if (m.rays.empty()) return notApplied("no ray ran exactly one of miss and closest-hit");
  m.applied = true;
  m.what = "miss and closest-hit both ran on " + raysText(m.rays.size());
  return m;
}

Mutation anyHitSkipped(const MutantInput&, const std::string&, Results& d) {
  RecordEdit e(d);
  Mutation m;
  for (uint32_t r = 0; r < e.rays(); ++r) {
    if (e.get(r, "any_hit_runs") == 0) continue;
    e.set(r, "any_hit_runs", 0);
    e.set(r, "any_hit_slots", 0);
    e.set(r, "any_hit_repeats", 0);
    m.rays.push_back(r);
  }
  if (m.rays.empty()) return notApplied("no ray ran any-hit");
  m.applied = true;
  m.what = "any_hit_runs 0 on the " + raysText(m.rays.size()) + " that ran any-hit";
  return m;
}

// Any-hit once more on a primitive it already ran on (the lowest slot).
Mutation anyHitExtra(const MutantInput&, const std::string&, Results& d) {
  RecordEdit e(d);
  Mutation m;
  for (uint32_t r = 0; r < e.rays(); ++r) {
    if (e.get(r, "any_hit_runs") == 0) continue;
    e.set(r, "any_hit_runs", e.get(r, "any_hit_runs") + 1);
    const uint32_t slots = e.get(r, "any_hit_slots");
    e.set(r, "any_hit_repeats", e.get(r, "any_hit_repeats") | (slots & (~slots + 1)));
    m.rays.push_back(r);
  }
  if (m.rays.empty()) return notApplied("no ray ran any-hit");
  m.applied = true;
  m.what = "any_hit_runs + 1 on the " + raysText(m.rays.size()) + " that ran any-hit";
  return m;
}

Mutation hitKindFlipped(const MutantInput&, const std::string&, Results& d) {
  RecordEdit e(d);
  Mutation m;
  m.field = "hit_kind";
  for (uint32_t r = 0; r < e.rays(); ++r) {
    if (!e.written(r, "hit_kind")) continue;
    e.set(r, "hit_kind", e.get(r, "hit_kind") ^ 1u);  // 0xFE <-> 0xFF
    m.rays.push_back(r);
  }
  if (m.rays.empty()) return notApplied("no ray wrote hit_kind");
  m.applied = true;
  m.what = "hit_kind ^ 1 (front <-> back face) on " + raysText(m.rays.size());
  return m;
}

Mutation imagesZeroed(const MutantInput&, const std::string&, Results& d) {
  bool any = false;
  for (Image& im : d.images) {
    any = any || std::any_of(im.texels.begin(), im.texels.end(), [](uint32_t t) { return t != 0; });
    std::fill(im.texels.begin(), im.texels.end(), 0u);
  }
  if (!any) return notApplied("no image has a texel that is not 0");
  Mutation m;
  m.applied = true;
  m.what = "every texel of " + std::to_string(d.images.size()) + " image(s) 0";
  return m;
}

}  // namespace

const std::vector<std::string>& mutantKinds() {
  static const std::vector<std::string> kinds = {"null-device",      "field",
                                                 "counter+1",        "counter-1",
                                                 "swap-rays",        "miss-and-closest-hit",
                                                 "any-hit-skipped",  "any-hit-extra",
                                                 "hit-kind-flipped", "images-zeroed"};
  return kinds;
}

std::vector<GenericMutant> genericMutants(const Case&, const Results& device) {
  std::vector<GenericMutant> out;
  out.push_back({"null-device", "null-device", nullDevice, ""});
  for (const RecordField& f : recordFields())
    if (perturbedAsField(f))
      out.push_back({"field", std::string("field:") + f.name, perturbField, f.name});
  for (const auto& [name, value] : device.counters) {
    out.push_back({"counter+1", "counter:" + name + "+1", counterUp, name});
    out.push_back({"counter-1", "counter:" + name + "-1", counterDown, name});
  }
  out.push_back({"swap-rays", "swap-rays", swapRays, ""});
  out.push_back({"miss-and-closest-hit", "miss-and-closest-hit", missAndClosestHit, ""});
  out.push_back({"any-hit-skipped", "any-hit-skipped", anyHitSkipped, ""});
  out.push_back({"any-hit-extra", "any-hit-extra", anyHitExtra, ""});
  out.push_back({"hit-kind-flipped", "hit-kind-flipped", hitKindFlipped, ""});
  out.push_back({"images-zeroed", "images-zeroed", imagesZeroed, ""});
  return out;
}

}  // namespace rayspec
