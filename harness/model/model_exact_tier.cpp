// The exact tier: is a trace's answer numerically clear? Candidates within
// the error bound of an edge, a vertex, an interval end, a tie or an AABB face,
// and intersection-program decisions within rounding, are tried the other way
// in sandboxed what-if runs; a ray whose answers differ is ambiguous and
// lists them all (results/results.h, RayAmbiguity).
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <type_traits>

#include "case/share_frame.h"
#include "model/closed_fan.h"
#include "model/model_tracer.h"
#include "model/sphere_error.h"
#include "model/trace_classifier.h"
#include "model/traversal.h"
#include "results/record_layout.h"
#include "results/tolerances.h"

namespace rayspec {

using namespace trace_detail;

// A triangle candidate that a device may see as a hit in the interval.
bool TraceClassifier::eligible(const ModelCandidate& cand) const {
  const TraceRay& r = tr_.ray;
  const ModelInstance& mi = scene_.instances[cand.instance];
  const ModelGeometry& g = scene_.blases[mi.blas].geometries[cand.geometry];
  const bool opaque = resolveOpaque(g.flags, mi.src->flags, tr_.flags);
  if (((tr_.flags & kRayCullOpaque) && opaque) || ((tr_.flags & kRayCullNoOpaque) && !opaque))
    return false;
  if (facing(scene_, cand, r, tr_.flags).culled) return false;
  // R-CAND-TRI-OPEN: at or beyond an end every device judges exactly.
  if ((cand.exact_tmin && cand.t <= r.tmin) || (cand.exact_tmax && cand.t >= r.tmax)) return false;
  const double tl = tr_.endTol(cand);
  return !(cand.t < r.tmin - tl || cand.t > r.tmax + tl);
}

namespace {

// The share frame of a triangle candidate (case/share_frame.h); boxes all
// in one.
ShareFrame candidateFrame(const ModelScene& scene, const ModelCandidate& c) {
  if (c.aabb) return {};
  const ModelInstance& mi = scene.instances[c.instance];
  return shareFrame(*mi.src, c.instance, scene.blases[mi.blas].geometries[c.geometry].transform);
}

Candidate answerOf(const Committed& b) {
  if (!b.valid) return {};
  return {true, b.instance, b.geometry, b.primitive, b.t};
}

bool sameAnswer(const Candidate& a, const Candidate& b) {
  return a.hit == b.hit && (!a.hit || (a.instance == b.instance && a.geometry == b.geometry &&
                                       a.primitive == b.primitive));
}

bool listed(const std::vector<Candidate>& list, const Candidate& k) {
  return std::any_of(list.begin(), list.end(),
                     [&](const Candidate& l) { return sameAnswer(l, k); });
}

}  // namespace

void TraceClassifier::addCommitted(const Committed& b, const WhatIf& how) {
  // A legal answer's t (a sphere root) a device may round further than
  // hit_t's tolerance: its bound, as boundT gives the model's own.
  if (!how.actual && b.valid && b.t_err > 0) boundTOf(b.t, b.t_err);
  noteRootTFree(b);
  // The actual run's effect is the launch state's now, before any what-if.
  const uint64_t effect = how.actual ? m_.effectOf(tr_.best, *tr_.payload, tr_.query) : b.effect;
  if (std::find(replay_effects_.begin(), replay_effects_.end(), effect) == replay_effects_.end()) {
    replay_effects_.push_back(effect);
    replay_hows_.push_back(how);
  }
  const Candidate k = answerOf(b);
  for (Candidate& l : amb_.candidates)
    if (sameAnswer(l, k)) {
      // One primitive committed at two t (a box's reports): its t is not one.
      if (k.hit && !(std::fabs(l.t - k.t) <= tr_.tol(k.t))) l.t = NAN;
      return;
    }
  amb_.candidates.push_back(k);
  hows_.push_back(how);
}

void TraceClassifier::addLeak(const Committed& b, const WhatIf& how) {
  const Candidate k = answerOf(b);
  if (listed(amb_.leak_answers, k)) return;
  amb_.leak_answers.push_back(k);
  leak_hows_.push_back(how);
}

void TraceClassifier::findUnsure(const std::vector<std::pair<size_t, double>>& reports,
                                 double final_t) {
  unsure_.clear();
  faces_ = false;
  // R-ISECT-REPORT: a box's intersection program reports anywhere in the
  // interval, before its slab entry too: a box it ran on is unsure wherever
  // the committed t lies.
  std::vector<bool> ran(cands_.size(), false);
  for (const auto& [index, t] : reports) ran[index] = true;
  // After the others, each a what-if group of its own (whatIf): boxes the
  // model's ray misses, triangles it runs in the plane of.
  std::vector<size_t> alone;
  for (size_t k = 0; k < cands_.size(); ++k) {
    const ModelCandidate& cand = cands_[k];
    if (cand.aabb) {
      // A grazed box matters only if its what-if runs change the answer (tryUnsure).
      if (cand.near_face && (ran[k] || cand.t <= final_t + tr_.tol(cand.t))) {
        (cand.outside ? alone : unsure_).push_back(k);
        faces_ = true;
      }
      continue;
    }
    if (!eligible(cand)) continue;
    const double tl = tr_.tol(cand.t);
    const bool near_edge = cand.ambiguity != TriAmbiguity::None && cand.t <= final_t + tl;
    std::optional<AmbiguityReason> why;
    if (cand.in_plane && cand.t - cand.t_err <= final_t + tl) why = AmbiguityReason::InPlane;
    // R-CAND-TRI-OPEN: an interval end is a tie only where a device's t may
    // round across it (model/exact_interval.h). It outranks an edge or
    // vertex there: a device may find none of the triangles around it, a
    // miss that is no leak (whatIf).
    else if ((cand.hit || near_edge) && tr_.nearTmin(cand))
      why = AmbiguityReason::TminTie;
    else if ((cand.hit || near_edge) && tr_.nearTmax(cand))
      why = AmbiguityReason::TmaxTie;
    else if (near_edge)
      why =
          cand.ambiguity == TriAmbiguity::Vertex ? AmbiguityReason::Vertex : AmbiguityReason::Edge;
    if (!why) continue;
    // The first reason found, except that a vertex outranks an edge met at
    // the same t (the triangles around a vertex include ones that see only
    // one of its edges within the bound).
    if (!reason_ || (*reason_ == AmbiguityReason::Edge && *why == AmbiguityReason::Vertex &&
                     std::fabs(cand.t - reason_t_) <= tl)) {
      reason_ = why;
      reason_t_ = cand.t;
    }
    (cand.in_plane ? alone : unsure_).push_back(k);
  }
  unsure_.insert(unsure_.end(), alone.begin(), alone.end());
}

void TraceClassifier::findSharedTriangles() {
  if (reason_ != AmbiguityReason::Edge && reason_ != AmbiguityReason::Vertex) return;
  // The triangles of one frame (case/share_frame.h) within the bound of the
  // same shared edge or vertex (same t), each with the model's own decision
  // (one of them where the mesh is closed around the ray: watertight.cpp): a
  // watertight device finds one of them, so a double hit shows as extra
  // any-hit runs.
  const ModelCandidate* first = nullptr;
  for (const ModelCandidate& cand : cands_) {
    if (cand.aabb || cand.in_plane || cand.ambiguity == TriAmbiguity::None || !eligible(cand))
      continue;
    if (!first) first = &cand;
    if (candidateFrame(scene_, cand) == candidateFrame(scene_, *first) &&
        std::fabs(cand.t - first->t) <= tr_.tol(first->t)) {
      amb_.shared_triangles.push_back({cand.hit, cand.instance, cand.geometry, cand.primitive});
      shared_group_.push_back(static_cast<size_t>(&cand - cands_.data()));
    }
  }
}

bool TraceClassifier::sameAsCommitted(const Committed& b) const {
  const Committed& best = tr_.best;
  return b.valid == best.valid &&
         (!b.valid || (b.instance == best.instance && b.geometry == best.geometry &&
                       b.primitive == best.primitive && b.kind == best.kind &&
                       std::fabs(b.t - best.t) <= tr_.tol(b.t)));
}

void TraceClassifier::findUnsure(const std::vector<std::pair<size_t, double>>& reports) {
  reports_ = &reports;
  findUnsure(reports, tr_.best.valid ? tr_.best.t : INFINITY);
}

namespace {

// The farthest t a legal or leak answer commits (a miss: infinity).
double farthestCommit(const std::vector<WhatIfAnswer>& answers,
                      const std::vector<WhatIfAnswer>& leaks, double t) {
  for (const auto* list : {&answers, &leaks})
    for (const WhatIfAnswer& a : *list) t = std::max(t, a.best.valid ? a.best.t : INFINITY);
  return t;
}

}  // namespace

// The what-if runs where the unsure candidates decide otherwise (whatIf).
// A legal or leak answer that passes the committed hit reaches candidates
// behind it: those unsure there (a shared edge behind a border edge or
// behind a shared edge leaked through) join, and the runs are made again
// with them, until no answer reaches farther.
std::vector<WhatIfAnswer> TraceClassifier::unsureAnswers(std::vector<WhatIfAnswer>& leaks) {
  double reach = tr_.best.valid ? tr_.best.t : INFINITY;
  std::vector<WhatIfAnswer> answers = m_.whatIf(tr_, cands_, unsure_, payload_in_, &leaks);
  for (;;) {
    const double further = farthestCommit(answers, leaks, reach);
    if (!(further > reach + tr_.tol(reach))) return answers;
    const size_t before = unsure_.size();
    findUnsure(*reports_, further);
    if (unsure_.size() == before) return answers;
    reach = further;
    leaks.clear();
    answers = m_.whatIf(tr_, cands_, unsure_, payload_in_, &leaks);
  }
}

void TraceClassifier::tryUnsure() {
  if (!reason_ && !faces_) return;
  // The legal answers: this run's, and those of the what-if runs.
  addCommitted(tr_.best, actual());
  std::vector<WhatIfAnswer> leaks;
  for (const WhatIfAnswer& a : unsureAnswers(leaks)) {
    noteUnsureForce(a.how.force);
    if (!sameAsCommitted(a.best) && !reason_) reason_ = AmbiguityReason::AabbFace;
    // A tied candidate preferred (withTies) answers a t-tie, not a box face.
    for (const WhatIfAnswer& b : withTies(a)) {
      if (!sameAsCommitted(b.best) && !reason_) reason_ = AmbiguityReason::TTie;
      addCommitted(b.best, b.how);
    }
  }
  for (const WhatIfAnswer& a : leaks)
    for (const WhatIfAnswer& b : withTies(a)) addLeak(b.best, b.how);
}

// The candidates a what-if run's committed hit ties with (within the error
// bound, another primitive): triangles it made a hit, boxes that reported
// at that t in the run.
std::vector<long> TraceClassifier::tiedWith(const WhatIfAnswer& a) const {
  std::vector<long> tied;
  const Committed& b = a.best;
  if (!b.valid) return tied;
  const double tol = tr_.tol(b.t);
  for (size_t k = 0; k < cands_.size(); ++k) {
    const ModelCandidate& c = cands_[k];
    if (c.instance == b.instance && c.geometry == b.geometry && c.primitive == b.primitive)
      continue;
    bool tie = false;
    if (c.aabb) {
      tie = std::any_of(a.reports.begin(), a.reports.end(), [&](const auto& r) {
        return r.first == k && !std::isnan(r.second) && std::fabs(r.second - b.t) <= tol;
      });
    } else {
      const int8_t f = a.how.force.empty() ? int8_t{-1} : a.how.force[k];
      tie =
          (f == 1 || (f < 0 && c.hit)) && !c.in_plane && eligible(c) && std::fabs(c.t - b.t) <= tol;
    }
    if (tie) tied.push_back(static_cast<long>(k));
  }
  return tied;
}

// R-TIE at a what-if run's committed t, as tryOrders at the actual run's: a
// leak or an unsure group's other choice reaches a hit behind that ties
// with another (fuzz seed 160964 on NVIDIA: two coincident triangles of
// opposite winding behind a border vertex), or an offered box reports at
// the committed t (160921: two boxes' sphere roots from a far origin). The
// run, then each tied candidate preferred in a run of its own.
std::vector<WhatIfAnswer> TraceClassifier::withTies(const WhatIfAnswer& a) {
  std::vector<WhatIfAnswer> out{a};
  for (long k : tiedWith(a)) {
    WhatIf how = a.how;
    how.prefer = k;
    out.push_back({m_.sandbox(tr_, cands_, how, payload_in_), how, {}});
  }
  return out;
}

// Whether forcing candidate k to be a hit (or not) decides it as the
// model's own run does in every order: a triangle the model's ray misses
// forced out, or one it hits strictly inside the interval (not in its
// plane, not a ray query's) forced in; a box the model's ray misses forced
// out (no legal device offering near boxes), or one it enters forced in.
bool TraceClassifier::forcedAsOwn(size_t k, bool hit) const {
  const ModelCandidate& cand = cands_[k];
  if (cand.aabb) return hit ? !cand.outside : cand.outside && !m_.sh_.fault_seam.nearBoxesOffered();
  if (!hit) return !cand.hit;
  return cand.hit && !cand.in_plane && !tr_.query && cand.t > tr_.tmin && cand.t < tr_.ray.tmax;
}

// A legal what-if run's decisions, kept for the candidate orders
// (tryPermutations combines each with every order): those it makes as the
// model's own run does left to the model, kept where some decision is left
// that is not kept already.
void TraceClassifier::noteUnsureForce(std::vector<int8_t> force) {
  bool otherwise = false;
  for (size_t k = 0; k < force.size(); ++k) {
    if (force[k] >= 0 && forcedAsOwn(k, force[k] == 1)) force[k] = -1;
    otherwise = otherwise || force[k] >= 0;
  }
  if (otherwise &&
      std::find(unsure_forces_.begin(), unsure_forces_.end(), force) == unsure_forces_.end())
    unsure_forces_.push_back(std::move(force));
}

// R-PREC on a box the model's ray misses (ModelCandidate::outside): offered
// in a what-if run, its intersection program's decisions within rounding
// (a sphere test from a far origin) are noted there and each flipped in a
// run of its own, the box offered (flipNoted: with the decisions its flip
// leaves within rounding).
void TraceClassifier::tryNearBoxDecisions() {
  if (!m_.sh_.programs->reads_sphere) return;
  bool any = false;
  for (size_t k : unsure_) {
    if (!cands_[k].outside) continue;
    WhatIf offered{false, std::vector<int8_t>(cands_.size(), -1), -1, -1, {}};
    offered.force[k] = 1;
    std::vector<ShaderDecision> noted;
    m_.sandbox(tr_, cands_, offered, payload_in_, nullptr, &noted);
    std::erase_if(noted, [&](const ShaderDecision& d) { return d.cand != k; });
    any = flipNoted(offered, noted, kShaderFlipDepth) || any;
  }
  if (any && !reason_) reason_ = AmbiguityReason::ShaderArith;
}

// R-PREC: an intersection program's decision that rounding may flip (sphere
// discriminant or root near an end): each flipped in a what-if run, with
// the decisions its flip leaves within rounding (flipNoted); the ray is
// ambiguous, as the device's counters may differ.
void TraceClassifier::tryShaderDecisions(const std::vector<ShaderDecision>& shader_unsure) {
  if (shader_unsure.empty()) return;
  addCommitted(tr_.best, actual());
  flipNoted(WhatIf{false, {}, -1, -1, {}}, shader_unsure, kShaderFlipDepth);
  if (!reason_) reason_ = AmbiguityReason::ShaderArith;
}

// Each decision of `noted` (those a what-if run `base` left within rounding)
// flipped in a run of its own, base's flips kept; then, `depth` - 1 deep,
// those that run leaves within rounding. A device rounds every decision of
// a trace, not one: from a far origin (fuzz seeds 120524, 120641 on
// NVIDIA) one box's sphere test misses while another's hits, or a box's
// root passes the committed one's, both within rounding. False when none.
bool TraceClassifier::flipNoted(const WhatIf& base, const std::vector<ShaderDecision>& noted,
                                size_t depth) {
  for (const ShaderDecision& d : noted) {
    WhatIf flipped = base;
    flipped.shaders.push_back(d);
    flipped.shaders.back().value = !d.value;
    std::vector<ShaderDecision> further;
    addCommitted(
        m_.sandbox(tr_, cands_, flipped, payload_in_, nullptr, depth > 1 ? &further : nullptr),
        flipped);
    if (depth > 1) flipNoted(flipped, further, depth - 1);
  }
  return !noted.empty();
}

// R-PREC: the committed t is a root whose rounding on a device may exceed
// the comparison's tolerance for hit_t: the answer is sure, its t is checked
// against this wider bound. hit_position (origin + t x direction) carries
// the same error, each component scaled by the direction's: its bound is t's
// times the direction's largest component.
// An unsure triangle the ray runs in the plane of is hit anywhere across it
// on a device: its t within t_err of cand.t (ModelCandidate::in_plane).
void TraceClassifier::boundT() {
  for (size_t k : unsure_)
    if (cands_[k].in_plane) boundTOf(cands_[k].t, cands_[k].t_err);
  if (tr_.best.valid && tr_.best.t_err > 0) boundTOf(tr_.best.t, tr_.best.t_err);
  noteRootTFree(tr_.best);
}

// A legal hit on a box at a sphere root a device may round past hit_t's
// tolerance, where the programs read the t into a value of their own (a
// colour of hit_t or hit_position): a replay pins that value, a device's
// lies anywhere in the bound (fuzz seeds 120121, 120641, 120778 on
// NVIDIA): the ray keeps no replays (LaunchState::ray_t_free). Not for a ray
// query's commits: its records are held to their replays (without them the
// planted query-commit-beyond-committed-t survived ray-query/sphere-crossing).
void TraceClassifier::noteRootTFree(const Committed& b) {
  if (!b.valid || tr_.query || !m_.sh_.programs->reads_root_t_free) return;
  const ModelInstance& mi = scene_.instances[b.instance];
  if (scene_.blases[mi.blas].geometries[b.geometry].kind != Geometry::Kind::Aabbs) return;
  const Tolerance tol = toleranceFor("hit_t");
  if (b.t_err > tol.abs + tol.rel * std::max(std::fabs(b.t), 1.0)) m_.st_.ray_t_free = true;
}

void TraceClassifier::boundTOf(double t, double t_err) {
  const Tolerance tol = toleranceFor("hit_t");
  if (t_err > tol.abs + tol.rel * std::max(std::fabs(t), 1.0))
    m_.st_.t_bounds.push_back({m_.st_.index, static_cast<float>(t_err)});
  const Vec3& o = tr_.ray.origin;
  const Vec3& d = tr_.ray.direction;
  double scale = 0, position = 1;
  for (int k = 0; k < 3; ++k) {
    scale = std::max(scale, std::fabs(static_cast<double>(d[k])));
    position = std::max(position, std::fabs(o[k] + t * static_cast<double>(d[k])));
  }
  const Tolerance ptol = toleranceFor("hit_position");
  if (t_err * scale > ptol.abs + ptol.rel * position)
    m_.st_.position_bounds.push_back({m_.st_.index, static_cast<float>(t_err * scale)});
}

// A replay hits an in-plane triangle (candidate u) at the middle of its
// span; a device anywhere across it. Its record differs from the replay's
// only in hit_t, ray_tmax and hit_position (each within the ray's t bound,
// boundT) where the programs read nothing else of the hit that the span
// leaves free (CPipeline::reads_in_plane_free) and no other candidate of the
// trace may lie within the span (then the order of the hits, and which one a
// committed t culls, is the same for every t across it; an intersection
// program may report any t): else the t matters.
bool TraceClassifier::inPlaneTMatters(size_t u) const {
  if (m_.sh_.programs->reads_in_plane_free) return true;
  const ModelCandidate& c = cands_[u];
  const double lo = c.t - c.t_err - tr_.tol(c.t), hi = c.t + c.t_err + tr_.tol(c.t);
  for (size_t k = 0; k < cands_.size(); ++k) {
    const ModelCandidate& o = cands_[k];
    if (k == u || o.nan_triangle ||
        (!o.aabb && !o.hit && !o.in_plane && o.ambiguity == TriAmbiguity::None))
      continue;
    if (o.aabb || (o.t + o.t_err >= lo && o.t - o.t_err <= hi)) return true;
  }
  return false;
}

std::optional<WhatIf> TraceClassifier::finish() {
  if (!reason_) reason_ = tie_reason_;
  dropLegalLeaks();
  ReplayScript* script = m_.st_.replay;
  std::vector<WhatIf> answers = reason_ ? replay_hows_ : std::vector<WhatIf>{};
  if (script && script->leaks && reason_)
    answers.insert(answers.end(), leak_hows_.begin(), leak_hows_.end());
  if (script && script->doubles && reason_)
    answers.insert(answers.end(), double_hows_.begin(), double_hows_.end());
  if (script && reason_ && !double_hows_.empty()) script->has_doubles = true;
  if (script) script->classified(answers, reason_ ? replay_hows_.size() : 0);
  if (!reason_) return std::nullopt;
  amb_.reason = *reason_;
  // A legal hit on a triangle the ray runs in the plane of, at no one t:
  // where its t may matter beyond the fields the t bound widens, the ray's
  // replays would pin it (legal_replays.cpp).
  for (const Candidate& k : amb_.candidates)
    for (size_t u : unsure_)
      if (k.hit && cands_[u].in_plane && cands_[u].instance == k.instance &&
          cands_[u].geometry == k.geometry && cands_[u].primitive == k.primitive &&
          inPlaneTMatters(u))
        m_.st_.ray_t_free = true;
  std::optional<WhatIf> chosen;
  if (script && (!script->own || m_.st_.ray_ambiguous)) {
    // A legal replay (legal_replays.cpp), or a later ambiguous trace of the
    // model's own run: this trace takes the answer its script chooses; the
    // ray's ambiguity is its first ambiguous trace's, kept already; the own
    // run counts its ambiguous traces there.
    if (script->own && !m_.st_.ambiguous.empty() && m_.st_.ambiguous.back().ray == amb_.ray)
      ++m_.st_.ambiguous.back().traces;
    chosen = answers[script->choose(answers.size())];
    m_.st_.ray_ambiguous = true;
    return chosen;
  }
  if (script) script->choose(answers.size());  // the own run's first: its actual answer
  if (const auto taken = m_.sh_.fault_seam.answerTaken(hows_.size(), leak_hows_.size()))
    chosen = taken->leak ? leak_hows_[taken->index] : hows_[taken->index];
  m_.st_.ambiguous.push_back(std::move(amb_));
  m_.st_.ray_ambiguous = true;
  return chosen;
}

// A leak answer that is also a legal one is legal.
void TraceClassifier::dropLegalLeaks() {
  for (size_t k = amb_.leak_answers.size(); k-- > 0;)
    if (listed(amb_.candidates, amb_.leak_answers[k])) {
      amb_.leak_answers.erase(amb_.leak_answers.begin() + static_cast<long>(k));
      leak_hows_.erase(leak_hows_.begin() + static_cast<long>(k));
    }
}

bool ModelTracer::replayKnownTrace(std::optional<WhatIf>& chosen) {
  ReplayScript* script = st_.replay;
  const std::vector<WhatIf>* known = script ? script->knownAnswers() : nullptr;
  if (!known) return false;
  script->classified(*known, script->known_legal[script->traces]);
  chosen.reset();
  if (known->empty()) return true;
  chosen = (*known)[script->choose(known->size())];
  st_.ray_ambiguous = true;
  return true;
}

std::optional<WhatIf> ModelTracer::classifyTrace(
    Traversal& tr, const std::vector<ModelCandidate>& candidates,
    const std::vector<std::pair<size_t, double>>& reports,
    const std::vector<ShaderDecision>& shader_unsure, const Payload& payload_in) {
  TraceClassifier c(*this, tr, candidates, payload_in);
  c.findUnsure(reports);
  c.findSharedTriangles();
  c.tryUnsure();
  c.tryDoubleHits();
  c.tryNearBoxDecisions();
  c.tryOrders(reports);
  c.tryShaderDecisions(shader_unsure);
  c.boundT();
  return c.finish();
}

// R-ORDER-UNSPEC: an any-hit that may terminate runs on one of the candidates
// (a box, or a non-opaque triangle in the interval): the order decides.
bool ModelTracer::anyHitMayTerminate(const Traversal& tr,
                                     const std::vector<ModelCandidate>& cands) const {
  if (tr.query) return tr.query->may_terminate;  // R-RQ-TERMINATE: its blocks may end it
  if (!sh_.programs->any_hit_terminates) return false;
  const ModelScene& scene = *sh_.scene;
  for (const ModelCandidate& cand : cands) {
    if (cand.outside || (!cand.aabb && !cand.hit && cand.ambiguity == TriAmbiguity::None)) continue;
    const ModelInstance& mi = scene.instances[cand.instance];
    const ModelGeometry& g = scene.blases[mi.blas].geometries[cand.geometry];
    if (resolveOpaque(g.flags, mi.src->flags, tr.flags)) continue;
    const CHitGroup* grp = groupOf(*sh_.programs, sbt_.hit(cand.instance, cand.geometry, tr.ray));
    if (grp && grp->any_hit_terminates) return true;
  }
  return false;
}

Committed ModelTracer::decideAs(const Traversal& actual, const std::vector<ModelCandidate>& cands,
                                const WhatIf& how, Payload& payload,
                                std::vector<ShaderDecision>* noted,
                                std::vector<std::pair<size_t, double>>* reports) {
  Traversal v(actual.ray);
  v.flags = actual.flags;
  v.depth = actual.depth;
  v.tmin = actual.tmin;
  v.tmax_cur = actual.ray.tmax;
  v.exact = actual.exact;
  v.startQuery(actual.query);
  v.inlined = actual.inlined;
  v.prefer = how.prefer;
  v.first = how.first;
  v.shader_force = how.shaders.empty() ? nullptr : &how.shaders;
  v.order = how.order.empty() ? nullptr : &how.order;
  v.tie = how.tie;
  v.shader_unsure = noted;
  v.reports = reports;
  if (how.prefer >= 0) {
    const ModelCandidate& p = cands[static_cast<size_t>(how.prefer)];
    v.prefer_key[0] = p.instance;
    v.prefer_key[1] = p.geometry;
    v.prefer_key[2] = p.primitive;
  }
  v.payload = &payload;
  decide(v, cands, how.force.empty() ? nullptr : how.force.data(), payload);
  return v.best;
}

// One what-if run of the decision in a sandbox: counters, record and error
// are restored afterwards, the payload is a copy of the trace's incoming one.
Committed ModelTracer::sandbox(const Traversal& actual, const std::vector<ModelCandidate>& cands,
                               const WhatIf& how, const Payload& payload_in, OrderOutcome* left,
                               std::vector<ShaderDecision>* noted,
                               std::vector<std::pair<size_t, double>>* reports) {
  const LaunchState::Saved saved = st_.save();
  // A query's blocks change the frame of the stage that runs it: the what-if
  // run starts from the frame as traversal began, and is undone.
  std::optional<QueryFrameSaved> frame;
  if (actual.query) {
    frame = saveQueryFrame(*actual.query);
    restoreQueryFrame(*actual.query, actual.query->frame_before);
  }
  Payload p = payload_in;
  Committed best = decideAs(actual, cands, how, p, noted, reports);
  best.effect = effectOf(best, p, actual.query);
  if (left) {  // what this run leaves behind (tryPermutations)
    left->best = best;
    if (st_.rec) left->record.assign(st_.rec, st_.rec + recordWords());
    left->payload = p;
    if (actual.query) left->frame = saveQueryFrame(*actual.query);
  }
  st_.restore(saved);
  if (frame) restoreQueryFrame(*actual.query, *frame);
  return best;
}

namespace {

// FNV-1a, 64 bits, over the bytes of values without padding.
struct Digest {
  uint64_t h = 14695981039346656037ull;
  template <typename T>
  void add(const T& v) {
    static_assert(std::has_unique_object_representations_v<T> || std::is_floating_point_v<T>);
    const auto* p = reinterpret_cast<const unsigned char*>(&v);
    for (size_t i = 0; i < sizeof(T); ++i) h = (h ^ p[i]) * 1099511628211ull;
  }
  template <typename T, size_t N>
  void add(const std::array<T, N>& a) {
    for (const T& v : a) add(v);
  }
  void add(const Payload& p) {
    add(p.color);
    add(p.value);
    add(p.depth);
    add(p.location);
    add(p.words);
    add(p.sized);
  }
  void add(const SizedSlots& s) {
    for (const auto& [type, lanes] : s.members) {
      add(static_cast<uint8_t>(type));
      add(lanes);
    }
  }
  void add(const CallData& k) {
    add(k.color);
    add(k.position);
    add(k.normal);
    add(k.value);
    add(k.location);
    add(k.words);
    add(k.sized);
  }
  void add(const Val& v) {
    add(v.f);
    add(v.u);
    add(static_cast<uint8_t>(v.b));
  }
};

}  // namespace

uint64_t ModelTracer::effectOf(const Committed& b, const Payload& payload,
                               const QueryRun* query) const {
  Digest d;
  d.add(static_cast<uint8_t>(b.valid));
  if (b.valid) {
    d.add(b.t);
    d.add(b.instance);
    d.add(b.geometry);
    d.add(b.primitive);
    d.add(b.kind);
    d.add(b.b1);
    d.add(b.b2);
    d.add(b.words);
    d.add(b.sized);
  }
  d.add(payload);
  if (st_.rec)
    for (uint32_t i = 0, n = recordWords(); i < n; ++i) d.add(st_.rec[i]);
  for (uint64_t c : st_.counters) d.add(c);
  if (query && query->env) {
    for (const Val& v : query->env->locals) d.add(v);
    d.add(query->env->child);
    d.add(query->env->callee);
    // A restart goes on with its ray (and what it keeps committed).
    d.add(query->restarts);
    if (const std::optional<QueryRestart>& r = query->restart) {
      const TraceRay& ray = r->ray;
      d.add(ray.origin);
      d.add(ray.direction);
      d.add(ray.tmin);
      d.add(ray.tmax);
      d.add(ray.flags);
      d.add(ray.cull_mask);
      d.add(ray.tlas);
      d.add(static_cast<uint8_t>(r->keep.valid));
      if (r->keep.valid) {
        d.add(r->keep.instance);
        d.add(r->keep.geometry);
        d.add(r->keep.primitive);
      }
    }
  }
  return d.h;
}

namespace {

// `unsure` with the candidates of each run met at one distance put in order
// of their share frames (stable): triangles of different frames decide apart
// (a device's object rays round apart there: one of each frame's may be hit,
// several in all), so unsureGroups makes each frame a group of its own.
std::vector<size_t> byFrame(const ModelScene& scene, const Traversal& actual,
                            const std::vector<ModelCandidate>& cands,
                            const std::vector<size_t>& unsure) {
  std::vector<size_t> out = unsure;
  size_t g0 = 0;
  while (g0 < out.size()) {
    size_t g1 = g0 + 1;
    while (g1 < out.size() &&
           std::fabs(cands[out[g1]].t - cands[out[g1 - 1]].t) <= actual.tol(cands[out[g1]].t))
      ++g1;
    std::stable_sort(out.begin() + static_cast<long>(g0), out.begin() + static_cast<long>(g1),
                     [&](size_t a, size_t b) {
                       return candidateFrame(scene, cands[a]) < candidateFrame(scene, cands[b]);
                     });
    g0 = g1;
  }
  return out;
}

// The unsure candidates grouped by distance and share frame, each group
// [first, last) in `unsure` (byFrame's order): a group crosses one edge or
// vertex, shared or not; a triangle the ray runs in the plane of, or a box
// its ray misses, is a group of its own.
std::vector<std::pair<size_t, size_t>> unsureGroups(const ModelScene& scene,
                                                    const Traversal& actual,
                                                    const std::vector<ModelCandidate>& cands,
                                                    const std::vector<size_t>& unsure) {
  auto alone = [&](size_t u) {
    return cands[unsure[u]].in_plane || cands[unsure[u]].outside;
  };
  std::vector<std::pair<size_t, size_t>> groups;
  size_t g0 = 0;
  while (g0 < unsure.size()) {
    size_t g1 = g0 + 1;
    while (g1 < unsure.size() && !alone(g0) && !alone(g1) &&
           std::fabs(cands[unsure[g1]].t - cands[unsure[g1 - 1]].t) <=
               actual.tol(cands[unsure[g1]].t) &&
           candidateFrame(scene, cands[unsure[g1]]) == candidateFrame(scene, cands[unsure[g0]]))
      ++g1;
    groups.emplace_back(g0, g1);
    g0 = g1;
  }
  return groups;
}

// What one group's choice forces: kOwn leaves its candidates to the model,
// a choice below the group's size makes that one alone a hit, kNone makes
// none of them one.
constexpr size_t kOwn = ~size_t{0}, kNone = kOwn - 1;

void forceGroup(WhatIf& how, const std::vector<size_t>& unsure, std::pair<size_t, size_t> g,
                size_t choice) {
  for (size_t b = g.first; b < g.second; ++b)
    how.force[unsure[b]] = choice == kOwn ? -1 : static_cast<int8_t>(choice == b - g.first ? 1 : 0);
}

// Every combination of the groups' choices, each group's kOwn among them,
// but all kOwn (the actual run): visit(pick), pick[g] group g's choice.
template <typename Visit>
void forEachCombination(const std::vector<std::vector<size_t>>& choices, Visit visit) {
  std::vector<size_t> at(choices.size(), 0);  // 0: kOwn, j > 0: choices[g][j - 1]
  std::vector<size_t> pick(choices.size(), kOwn);
  for (;;) {
    size_t g = 0;
    while (g < at.size() && at[g] == choices[g].size()) at[g++] = 0;
    if (g == at.size()) return;
    ++at[g];
    for (size_t h = 0; h < at.size(); ++h) pick[h] = at[h] == 0 ? kOwn : choices[h][at[h] - 1];
    visit(pick);
  }
}

}  // namespace

// The most what-if runs of one trace's combined groups (ModelTracer::whatIf).
constexpr size_t kMaxWhatIfCombinations = 256;

// What-if runs of the decision for an ambiguous trace: within a group of
// unsure candidates (unsureGroups: one distance, one share frame, so the
// triangles of instances moved apart decide apart and several of them may be
// hit) each candidate alone is a hit (watertight:
// at least one of a shared edge's triangles is hit); a group that does not
// close around the ray may also be no hit, and one that closes (a shared
// edge, a closed fan: closed_fan.h) no hit only as a leak. A ray may meet
// several groups one behind the other (a border edge or a leaked shared
// edge in front of a shared edge): every combination of the groups'
// choices is an answer, each group also left to the model, up to
// kMaxWhatIfCombinations runs; a combination where a closing group is no
// hit goes to `leaks`. Past the bound, each group's choices are tried with
// the others left to the model (stated: a device combining them is then
// judged on what the answers share). Stage programs run again, in a
// sandbox: their counters, record and payload effects are undone.
std::vector<WhatIfAnswer> ModelTracer::whatIf(const Traversal& actual,
                                              const std::vector<ModelCandidate>& cands,
                                              const std::vector<size_t>& unsure_found,
                                              const Payload& payload_in,
                                              std::vector<WhatIfAnswer>* leaks) {
  std::vector<WhatIfAnswer> out;
  if (unsure_found.empty()) return out;
  const std::vector<size_t> unsure = byFrame(*sh_.scene, actual, cands, unsure_found);
  const std::vector<std::pair<size_t, size_t>> groups =
      unsureGroups(*sh_.scene, actual, cands, unsure);
  // Each group's choices: its candidates alone, then none.
  std::vector<std::vector<size_t>> choices(groups.size());
  std::vector<bool> closes(groups.size());
  size_t combinations = 1;
  for (size_t g = 0; g < groups.size(); ++g) {
    const auto [g0, g1] = groups[g];
    for (size_t a = 0; a < g1 - g0; ++a) choices[g].push_back(a);
    choices[g].push_back(kNone);
    const std::vector<size_t> members(unsure.begin() + static_cast<long>(g0),
                                      unsure.begin() + static_cast<long>(g1));
    // At an interval end a device may find none of them (nearTmin): no leak.
    closes[g] = closesAroundRay(*sh_.scene, cands, members, actual.ray, actual.flags) &&
                std::none_of(members.begin(), members.end(), [&](size_t k) {
                  return actual.nearTmin(cands[k]) || actual.nearTmax(cands[k]);
                });
    combinations = std::min(combinations * (choices[g].size() + 1), kMaxWhatIfCombinations + 1);
  }
  WhatIf how{false, std::vector<int8_t>(cands.size(), -1), -1, -1, {}};
  auto run = [&](const std::vector<size_t>& pick) {
    bool leak = false;
    for (size_t g = 0; g < groups.size(); ++g) {
      forceGroup(how, unsure, groups[g], pick[g]);
      leak = leak || (closes[g] && pick[g] == kNone);
    }
    WhatIfAnswer a{{}, how, {}};
    a.best = sandbox(actual, cands, how, payload_in, nullptr, nullptr, &a.reports);
    (leak ? *leaks : out).push_back(std::move(a));
  };
  if (combinations <= kMaxWhatIfCombinations) {
    forEachCombination(choices, run);
    return out;
  }
  std::vector<size_t> pick(groups.size(), kOwn);
  for (size_t g = 0; g < groups.size(); ++g) {
    for (size_t c : choices[g]) {
      pick[g] = c;
      run(pick);
    }
    pick[g] = kOwn;
  }
  return out;
}

}  // namespace rayspec
