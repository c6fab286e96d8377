#include "mutate/legal_survival.h"

#include <algorithm>
#include <map>
#include <set>

#include "compare/counter_modes.h"
#include "compare/trace_shape.h"
#include "fault/record_edit.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

bool everyRayUndefined(const MutantInput& in, const Mutation& m) {
  if (m.rays.empty()) return false;
  std::set<uint32_t> undefined;
  for (const UndefinedRay& u : in.model.undefined) undefined.insert(u.ray);
  return std::all_of(m.rays.begin(), m.rays.end(),
                     [&](uint32_t r) { return undefined.count(r) > 0; });
}

// Derived here, not from the comparison's own slack (compare/compare_counters):
// a counter that follows one stage's run count is pinned by the records; one
// that follows which programs run moves only with rays whose answers run
// other programs; one counted conditionally, with any ambiguous ray.
std::string counterReason(const MutantInput& in, const Mutation& m) {
  const auto modes = counterModes(in.c);
  const auto it = modes.find(m.counter);
  if (it == modes.end()) return "";
  if (!in.model.undefined.empty() && countersUndefinedRaysMayMove(in.c).count(m.counter))
    return "R-UB: rays with undefined behaviour may move counter '" + m.counter + "'";
  switch (it->second) {
    case CounterMode::Informational:
      return "counter '" + m.counter +
             "' is counted in any-hit or intersection: its total depends on traversal order and "
             "duplicate invocations (R-ORDER-UNSPEC, R-AHIT-DUP)";
    case CounterMode::AtLeast:
      return m.delta > 0 ? "counter '" + m.counter + "' is at_least: a device may run it more often"
                         : "";
    case CounterMode::AtMost:
      return m.delta < 0 ? "counter '" + m.counter + "' is at_most: a device may run it less often"
                         : "";
    case CounterMode::Exact:
      break;
  }
  if (counterSources(in.c).count(m.counter)) return "";  // pinned by the per-ray run counts
  if (countedByProgramsAlone(in.c, m.counter)) {
    const size_t rays = raysRunningOtherPrograms(in.model);
    return rays ? "counter '" + m.counter + "' follows which programs run, and " +
                      std::to_string(rays) +
                      " ambiguous rays have legal answers that run other programs"
                : "";
  }
  if (!in.model.ambiguous.empty())
    return "counter '" + m.counter +
           "' is counted conditionally (in an if, after a call by a computed index, ...), and " +
           std::to_string(in.model.ambiguous.size()) + " ambiguous rays have several legal answers";
  return "";
}

// A changed ray is ambiguous, and the identity the mutant gave it is one of
// its legal hits.
bool identityStaysLegal(const MutantInput& in, const Mutation& m, const Results& mutated) {
  static const std::set<std::string> identity = {"primitive_id", "instance_id", "geometry_index"};
  if (!identity.count(m.field) || m.rays.empty()) return false;
  const auto ambiguous = ambiguityByRay(in.model);
  const RecordView view{mutated};
  for (uint32_t r : m.rays) {
    const auto it = ambiguous.find(r);
    if (it == ambiguous.end()) return false;
    const uint32_t value = view.get(r, m.field);
    bool legal = false;
    for (const Candidate& k : it->second->candidates) {
      if (!k.hit) continue;
      const uint32_t own = m.field == "primitive_id"  ? k.primitive
                           : m.field == "instance_id" ? k.instance
                                                      : k.geometry;
      legal = legal || own == value;
    }
    if (!legal) return false;
  }
  return true;
}

// Both swapped rays are ambiguous, and the answer each got from the other
// (its identity, or a miss) is one of its own legal answers.
bool swappedAnswersStayLegal(const MutantInput& in, const Mutation& m, const Results& mutated) {
  if (m.rays.size() != 2) return false;
  const auto ambiguous = ambiguityByRay(in.model);
  const RecordView view{mutated};
  for (uint32_t r : m.rays) {
    const auto it = ambiguous.find(r);
    if (it == ambiguous.end()) return false;
    const bool hit = view.get(r, "closest_hit_runs") > 0;
    bool legal = false;
    for (const Candidate& k : it->second->candidates) {
      if (!hit) {
        legal = legal || !k.hit;
        continue;
      }
      legal = legal ||
              (k.hit &&
               (!view.written(r, "primitive_id") || view.get(r, "primitive_id") == k.primitive) &&
               (!view.written(r, "instance_id") || view.get(r, "instance_id") == k.instance) &&
               (!view.written(r, "geometry_index") || view.get(r, "geometry_index") == k.geometry));
    }
    if (!legal) return false;
  }
  return true;
}

bool anyAabbs(const Case& c) {
  for (const Blas& b : c.scene.blases)
    for (const Geometry& g : b.geometries)
      if (g.kind != Geometry::Kind::Triangles) return true;
  return false;
}

// Every changed ray is ambiguous among several hits, and only closest-hit
// programs write the field: its value follows the hit taken, and the model
// does not work out each legal hit's value (only its identity).
bool valueOfAnotherLegalHit(const MutantInput& in, const Mutation& m) {
  if (m.field.empty() || m.rays.empty()) return false;
  const auto ambiguous = ambiguityByRay(in.model);
  for (uint32_t r : m.rays) {
    const auto it = ambiguous.find(r);
    if (it == ambiguous.end()) return false;
    size_t hits = 0;
    for (const Candidate& k : it->second->candidates) hits += k.hit;
    if (hits < 2) return false;
  }
  bool elsewhere = false;
  for (const FieldWrite& w : fieldWrites(in.c))
    elsewhere = elsewhere || (w.field == m.field && w.stage != Stage::ClosestHit);
  return !elsewhere;
}

bool everyGeometryNoDuplicate(const Case& c) {
  for (const Blas& b : c.scene.blases)
    for (const Geometry& g : b.geometries)
      if (!(g.flags & kGeometryNoDuplicateAnyHit)) return false;
  return true;
}

// R-AHIT-DUP: every record word and image texel in which `mutated` differs
// from the model lies in a field the model found any-hit repetition may
// change on that ray (Results::repeat_dependent): the comparison leaves
// exactly those out.
bool onlyRepeatDependentChanged(const MutantInput& in, const Results& mutated) {
  if (in.model.repeat_dependent.empty()) return false;
  std::map<uint32_t, FieldMask> masks;
  for (const RepeatDependentRay& d : in.model.repeat_dependent) masks[d.ray] = d.fields;
  const auto dependent = [&masks](uint32_t ray, uint32_t index) {
    const auto it = masks.find(ray);
    return it != masks.end() && (it->second & fieldBit(index));
  };
  const uint32_t words = recordWords();
  if (mutated.records.size() != in.model.records.size()) return false;
  for (size_t ray = 0; ray < mutated.records.size() / words; ++ray)
    for (const RecordField& f : recordFields()) {
      const uint32_t* a = &mutated.records[ray * words + f.offset];
      const uint32_t* b = &in.model.records[ray * words + f.offset];
      if (!traversalDependent(f) && !std::equal(a, a + f.words, b) &&
          !dependent(static_cast<uint32_t>(ray), f.index))
        return false;
    }
  for (const Image& im : mutated.images)
    for (const Image& model_image : in.model.images) {
      if (model_image.name != im.name || model_image.texels.size() != im.texels.size()) continue;
      const int index = recordFieldIndex(im.field);
      for (size_t t = 0; t < im.texels.size(); ++t)
        if (im.texels[t] != model_image.texels[t] &&
            (index < 0 || !dependent(static_cast<uint32_t>(t / im.channels), index)))
          return false;
    }
  return true;
}

}  // namespace

std::string legalSurvival(const MutantInput& in, const GenericMutant& g, const Mutation& m,
                          const Results& mutated) {
  if (!m.counter.empty()) return counterReason(in, m);
  if (!m.field.empty() && identityStaysLegal(in, m, mutated))
    return "every changed ray is ambiguous and its new " + m.field + " is one of its legal hits";
  if (everyRayUndefined(in, m)) return "R-UB: every changed ray has undefined behaviour";
  if (!m.field.empty() && valueOfAnotherLegalHit(in, m))
    return "every changed ray is ambiguous among several legal hits and closest-hit computes " +
           m.field +
           " from the hit taken: the model lists each legal hit, not the value it would give";
  if (g.kind == "swap-rays" && swappedAnswersStayLegal(in, m, mutated))
    return "both swapped rays are ambiguous, and the answer each took from the other is one of its "
           "own legal answers";
  if (g.kind == "any-hit-skipped" && anyAabbs(in.c))
    return "R-ORDER-UNSPEC: the scene has AABBs, whose intersection programs may report beyond a "
           "nearer hit another order finds first: the model's any-hit count is no minimum there";
  if (m.counter.empty() && onlyRepeatDependentChanged(in, mutated))
    return "R-AHIT-DUP: it changed only what a device running any-hit more than once for a "
           "primitive may change (the model's repeat-dependent fields), which is not compared";
  if (g.kind == "any-hit-extra" && !everyGeometryNoDuplicate(in.c))
    return "R-AHIT-DUP: without NO_DUPLICATE_ANY_HIT_INVOCATION any-hit may run again on a "
           "primitive";
  return "";
}

}  // namespace rayspec
