// R-WATERTIGHT, a "should": the double hits of a trace through a shared edge
// or vertex (TraceClassifier::tryDoubleHits).
#include <algorithm>
#include <numeric>

#include "model/closed_fan.h"
#include "model/trace_classifier.h"

namespace rayspec {

using namespace trace_detail;

namespace {

// One run of the search: the group's triangles it hits, in the order it
// meets them, and the effect it leaves (Committed::effect).
struct DoubleRun {
  std::vector<size_t> hits;  // indices into the group
  uint64_t effect = 0;
};

uint64_t maskOf(const std::vector<size_t>& hits) {
  uint64_t mask = 0;
  for (size_t h : hits) mask |= uint64_t{1} << h;
  return mask;
}

}  // namespace

// Whether a device runs any-hit on some triangle of the group: a double hit
// shows only there (an opaque one commits as one of the legal answers).
bool TraceClassifier::anyHitRunsOn(const std::vector<size_t>& group) const {
  const ModelScene& scene = *m_.sh_.scene;
  return std::any_of(group.begin(), group.end(), [&](size_t k) {
    const ModelCandidate& cand = cands_[k];
    const ModelInstance& mi = scene.instances[cand.instance];
    const ModelGeometry& g = scene.blases[mi.blas].geometries[cand.geometry];
    const CHitGroup* grp =
        groupOf(*m_.sh_.programs, m_.sbt_.hit(cand.instance, cand.geometry, tr_.ray));
    return !resolveOpaque(g.flags, mi.src->flags, tr_.flags) && grp && grp->any_hit;
  });
}

// The what-if run that hits the group's triangles `hits` (indices into
// `group`) in that order and no other triangle of the group: the model's
// own order, the group's places in it taken by `hits` first.
WhatIf TraceClassifier::doubleHit(const std::vector<size_t>& group,
                                  const std::vector<size_t>& hits) const {
  WhatIf how{false, std::vector<int8_t>(cands_.size(), -1), -1, -1, {}};
  std::vector<size_t> members;
  for (size_t h : hits) members.push_back(group[h]);
  for (size_t k : group)
    if (std::find(members.begin(), members.end(), k) == members.end()) members.push_back(k);
  for (size_t p = 0; p < members.size(); ++p) how.force[members[p]] = p < hits.size() ? 1 : 0;
  how.order.resize(cands_.size());
  std::iota(how.order.begin(), how.order.end(), 0u);
  std::vector<size_t> places = group;
  std::sort(places.begin(), places.end());
  for (size_t p = 0; p < places.size(); ++p)
    how.order[places[p]] = static_cast<uint32_t>(members[p]);
  return how;
}

// Whether the trace meets a group of two or more triangles that closes
// around the ray (closed_fan.h) at a shared edge or vertex, away from the
// interval's ends, and some of them run any-hit.
bool TraceClassifier::doubleHitsShow() const {
  const std::vector<size_t>& group = shared_group_;
  return !tr_.query && group.size() >= 2 && group.size() <= 64 && anyHitRunsOn(group) &&
         closesAroundRay(scene_, cands_, group, tr_.ray, tr_.flags) &&
         std::none_of(group.begin(), group.end(),
                      [&](size_t k) { return tr_.nearTmin(cands_[k]) || tr_.nearTmax(cands_[k]); });
}

// A device that is not watertight may hit two or more of the triangles that
// close around the ray at a shared edge or vertex (lavapipe 25.0.7 ran
// any-hit on three of a closed fan of six and ignored each: fuzz seed
// 170852), in any order. Each such set, in each order whose effect differs,
// is a sandboxed what-if run, kept in double_hows_ (the replays' double
// pass, legal_replays.h): a run is extended by each triangle it has not
// hit, and runs with the same triangles and the same effect are extended
// once; where the candidate programs cannot depend on the order
// (order_dependence.h), one order a set. Up to kMaxDoubleHitRuns runs; past
// it none is kept (such a record is judged as before, against the legal
// answers). Not for a ray query's candidates.
void TraceClassifier::tryDoubleHits() {
  if (!doubleHitsShow()) return;
  const std::vector<size_t>& group = shared_group_;
  const bool ordered = m_.sh_.programs->order_dependent;
  std::vector<DoubleRun> level;
  for (size_t h = 0; h < group.size(); ++h)
    level.push_back({{h}, m_.sandbox(tr_, cands_, doubleHit(group, {h}), payload_in_).effect});
  std::vector<std::pair<uint64_t, uint64_t>> seen;  // (triangles, effect) of each run kept
  std::vector<WhatIf> found;
  size_t runs = level.size();
  while (!level.empty()) {
    std::vector<DoubleRun> next;
    for (const DoubleRun& r : level)
      for (size_t h = ordered ? 0 : r.hits.back() + 1; h < group.size(); ++h) {
        if (std::count(r.hits.begin(), r.hits.end(), h)) continue;
        if (++runs > kMaxDoubleHitRuns) return;
        DoubleRun e{r.hits, 0};
        e.hits.push_back(h);
        WhatIf how = doubleHit(group, e.hits);
        e.effect = m_.sandbox(tr_, cands_, how, payload_in_).effect;
        const std::pair<uint64_t, uint64_t> key{maskOf(e.hits), e.effect};
        if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
        seen.push_back(key);
        found.push_back(std::move(how));
        next.push_back(std::move(e));
      }
    level = std::move(next);
  }
  double_hows_ = std::move(found);
}

}  // namespace rayspec
