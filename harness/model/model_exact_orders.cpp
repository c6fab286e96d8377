// The exact tier's candidate orders (R-ORDER-UNSPEC, R-TIE, R-TOFH,
// R-TERMINATE): which orders of a trace's candidates may change its answer,
// each tried in a sandboxed what-if run; every distinct answer is legal.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <string>

#include "model/order_dependence.h"
#include "model/trace_classifier.h"
#include "results/record_layout.h"

namespace rayspec {

using namespace trace_detail;

// R-TIE, R-ORDER-UNSPEC: candidates confirmed at the committed t (within the
// error bound) may end in any order; R-TOFH: any candidate may be confirmed
// first; R-ORDER-UNSPEC, R-TERMINATE: where an any-hit may terminate, the
// candidate a device meets first may end the traversal. Each is tried in a
// sandboxed what-if run (preferred in ties, or processed first, the rest in
// order); those runs' answers are legal.
void TraceClassifier::tryOrders(const std::vector<std::pair<size_t, double>>& reports) {
  const bool tofh = (tr_.flags & kRayTerminateOnFirstHit) != 0;
  const bool permuted = tryPermutations(reports);
  const bool terminates = !tofh && !permuted && m_.anyHitMayTerminate(tr_, cands_);
  std::vector<long> prefers, firsts, potential;
  std::set<std::array<uint32_t, 3>> tied;  // distinct keys confirmable at the committed t
  if ((tofh && !permuted) || terminates) {
    for (size_t k = 0; k < cands_.size(); ++k) {
      const ModelCandidate& cand = cands_[k];
      // A box the model's ray misses is offered in tryUnsure's runs alone.
      if ((cand.aabb && !cand.outside) ||
          (!cand.aabb && (cand.hit || cand.ambiguity != TriAmbiguity::None) && eligible(cand)))
        firsts.push_back(static_cast<long>(k));
    }
  }
  if (!tofh && tr_.best.valid) {
    tied.insert({tr_.best.instance, tr_.best.geometry, tr_.best.primitive});
    // Per box: 1 its intersection program ran, 2 it reported at the committed t.
    std::vector<uint8_t> boxes(cands_.size(), 0);
    for (const auto& [index, t] : reports) boxes[index] |= tr_.ties(t) ? 3 : 1;
    for (size_t k = 0; k < cands_.size(); ++k) {
      const ModelCandidate& cand = cands_[k];
      bool tie = false;
      if (cand.aabb) {
        tie = (boxes[k] & 2) != 0;
        // A box entered just past the committed t may still report at it.
        if (!boxes[k] && !cand.outside && tr_.ties(cand.t))
          potential.push_back(static_cast<long>(k));
      } else {
        tie = cand.hit && tr_.ties(cand.t) && eligible(cand);
      }
      if (!tie) continue;
      tied.insert({cand.instance, cand.geometry, cand.primitive});
      if (cand.instance != tr_.best.instance || cand.geometry != tr_.best.geometry ||
          cand.primitive != tr_.best.primitive)
        prefers.push_back(static_cast<long>(k));
    }
    if (tied.size() < 2) prefers.clear();
    prefers.insert(prefers.end(), potential.begin(), potential.end());
  }
  if (prefers.empty() && firsts.size() <= 1) return;
  const bool before = !amb_.candidates.empty();
  bool differs = false, differs_first = false;
  auto add_one = [&](const Committed& b, const WhatIf& how) {
    addCommitted(b, how);
    const bool d = b.valid != tr_.best.valid || (b.valid && (b.instance != tr_.best.instance ||
                                                             b.geometry != tr_.best.geometry ||
                                                             b.primitive != tr_.best.primitive));
    differs = differs || d;
    return d;
  };
  const size_t saved = amb_.candidates.size(), saved_replays = replay_hows_.size();
  add_one(tr_.best, actual());
  for (long k : prefers) {
    const WhatIf how{false, {}, k, -1, {}};
    add_one(m_.sandbox(tr_, cands_, how, payload_in_), how);
  }
  if (firsts.size() > 1)
    for (long k : firsts) {
      // An edge or vertex triangle the model left out may be the device's first hit.
      WhatIf how{false, std::vector<int8_t>(cands_.size(), -1), -1, k, {}};
      if (cands_[k].ambiguity != TriAmbiguity::None) how.force[k] = 1;
      differs_first = add_one(m_.sandbox(tr_, cands_, how, payload_in_), how) || differs_first;
    }
  const bool ambiguous_now = tofh ? differs : (differs || tied.size() >= 2);
  if (ambiguous_now && !reason_)
    reason_ = tofh            ? AmbiguityReason::FirstHit
              : differs_first ? AmbiguityReason::Order
                              : AmbiguityReason::TTie;
  if (!ambiguous_now && !before) {
    amb_.candidates.resize(saved);
    hows_.resize(saved);
    replay_hows_.resize(saved_replays);
    replay_effects_.resize(saved_replays);
  }
}

// Hit or unsure triangles in the interval, and boxes; but a box whose
// intersection program ran and reported nothing, where no intersection
// program reads ray_tmax: no order makes it report.
std::vector<uint32_t> TraceClassifier::orderedCandidates(
    const std::vector<std::pair<size_t, double>>& reports) const {
  std::vector<uint8_t> box(cands_.size(), 0);  // 1 ran, 2 reported
  if (!tr_.query && !m_.sh_.programs->reads(kBiTmax))
    for (const auto& [k, t] : reports) box[k] |= std::isnan(t) ? 1 : 2;
  std::vector<uint32_t> matter;
  for (size_t k = 0; k < cands_.size(); ++k) {
    const ModelCandidate& cand = cands_[k];
    if ((cand.aabb && !cand.outside && box[k] != 1) ||
        (!cand.aabb && (cand.hit || cand.ambiguity != TriAmbiguity::None) && eligible(cand)))
      matter.push_back(static_cast<uint32_t>(k));
  }
  return matter;
}

// R-TIE: two reports (of two boxes, or two of one box) at one t within the
// error bound: which stays depends on the order, and on whether a report at
// the committed t replaces it (both legal).
bool TraceClassifier::reportsTie(const std::vector<std::pair<size_t, double>>& reports) const {
  for (size_t a = 0; a < reports.size(); ++a)
    for (size_t b = a + 1; b < reports.size(); ++b) {
      const double ta = reports[a].second, tb = reports[b].second;
      if (!std::isnan(ta) && !std::isnan(tb) && std::fabs(ta - tb) <= tr_.tol(ta)) return true;
    }
  return false;
}

// The what-if runs of one order from one set of decisions (`force`: none,
// the model's own; or a legal what-if run's of the unsure candidates,
// noteUnsureForce): those decisions; and where an edge or vertex triangle
// they leave to the model (R-WATERTIGHT: a shared vertex of no closed fan,
// or any the model missed within rounding) is among the candidates, the
// first such in the order a hit there (a device may hit it after a farther
// candidate's any-hit ran: no ordering guarantee between candidates, Ray
// Intersection Candidate Determination); first in the order, only that run
// (missed, its place does not matter).
std::vector<WhatIf> TraceClassifier::orderRuns(const std::vector<uint32_t>& order,
                                               const std::vector<uint32_t>& matter, TieRule rule,
                                               const std::vector<int8_t>& force) const {
  std::vector<WhatIf> runs{{false, force, -1, -1, {}, order, rule}};
  for (size_t p = 0; p < matter.size(); ++p) {
    const uint32_t k = order[matter[p]];
    if (cands_[k].ambiguity == TriAmbiguity::None || (!force.empty() && force[k] >= 0)) continue;
    WhatIf forced = runs[0];
    if (forced.force.empty()) forced.force.assign(cands_.size(), -1);
    forced.force[k] = 1;
    if (p == 0) runs.clear();
    runs.push_back(std::move(forced));
    break;
  }
  return runs;
}

// R-TIE: what the order runs try with a candidate at the committed t, where
// two triangles tie or a report is made: the model's rule; the candidate
// kept out before its any-hit; or confirmed and replacing or dropped
// (legal_replays: each is a legal answer). A ray query's candidates tie as
// its blocks decide.
std::vector<TieRule> TraceClassifier::tieRules(const std::vector<uint32_t>& matter,
                                               bool reported) const {
  bool triangles = false;
  for (size_t a = 0; a < matter.size() && !triangles; ++a)
    for (size_t b = a + 1; b < matter.size() && !triangles; ++b) {
      const ModelCandidate &x = cands_[matter[a]], &y = cands_[matter[b]];
      triangles = !x.aabb && !y.aabb && std::fabs(x.t - y.t) <= tr_.tol(x.t);
    }
  if (tr_.query) return {TieRule::Model};
  if (triangles || reported)
    return {TieRule::Model, TieRule::Keep, TieRule::Replace, TieRule::ConfirmDrop};
  return {TieRule::Model};
}

OrderOutcome TraceClassifier::actualOutcome() const {
  OrderOutcome o;
  o.best = tr_.best;
  if (m_.st_.rec) o.record.assign(m_.st_.rec, m_.st_.rec + recordWords());
  if (tr_.payload) o.payload = *tr_.payload;
  if (tr_.query) o.frame = saveQueryFrame(*tr_.query);
  return o;
}

// Past a bound the model cannot list every answer the orders leave: the
// case is not portable (CaseError, compare/order_dependent_verdict.h), named
// by the block, `what` saying why for the launch ray now.
void TraceClassifier::orderDependentPastBound(const std::string& what) {
  const OrderDependence d = tr_.query ? queryOrderDependence(*tr_.query->stmt)
                                      : pipelineOrderDependence(*m_.sh_.programs);
  const CStmt* where = d.where ? d.where : tr_.query ? tr_.query->stmt : nullptr;
  std::string place = tr_.query
                          ? "the candidate blocks of the ray_query at " + statementPlace(where)
                          : "the any-hit or intersection program at " + statementPlace(where);
  if (!d.why.empty()) place += " (" + d.why + ")";
  m_.st_.orderDependent(place, ": launch ray " + std::to_string(m_.st_.index) + " " + what);
}

namespace {

// The candidates whose order may matter under a set of decisions: those of
// `matter` it does not force to be no hit (one forced out does nothing
// wherever it comes), and those it forces in that the model's own run
// leaves out (a box its ray misses, offered), in index order.
std::vector<uint32_t> inPlay(const std::vector<uint32_t>& matter,
                             const std::vector<int8_t>& force) {
  if (force.empty()) return matter;
  std::vector<uint32_t> in;
  for (uint32_t k = 0; k < force.size(); ++k)
    if (force[k] == 1 || (force[k] < 0 && std::binary_search(matter.begin(), matter.end(), k)))
      in.push_back(k);
  return in;
}

// How many orders of `m` candidates tryOrdersFrom tries (everyOrder, or
// past kMaxOrderedCandidates sampleOrders).
size_t orderCount(size_t m) {
  if (m > kMaxOrderedCandidates) return 2 * m + kSampledOrders;
  size_t n = 1;
  for (size_t k = 2; k <= m; ++k) n *= k;
  return n;
}

}  // namespace

// The sets of decisions the orders combine with beyond the model's own:
// each legal what-if run's of the unsure candidates (an edge or vertex
// triangle missed or hit, a grazed box offered or not: tryUnsure), each
// with every order (a device may both miss a lone vertex and meet a farther
// candidate first: fuzz seed 150215 on Mesa 26.2.6). Past
// kMaxCombinedOrderRuns none, and the case is a CaseError saying so: a
// combination left untried may be the device's.
std::vector<std::vector<int8_t>> TraceClassifier::combinedBases(const std::vector<uint32_t>& matter,
                                                                bool reported) {
  size_t runs = 0;
  for (const std::vector<int8_t>& force : unsure_forces_) {
    const std::vector<uint32_t> in_play = inPlay(matter, force);
    runs += orderCount(in_play.size()) * tieRules(in_play, reported).size();
  }
  if (runs <= kMaxCombinedOrderRuns) return unsure_forces_;
  orderDependentPastBound("meets " + std::to_string(matter.size()) +
                          " candidates whose order may matter and " +
                          std::to_string(unsure_forces_.size()) +
                          " legal decisions of its unsure candidates (edge, vertex, interval "
                          "end, box face): their combinations make " +
                          std::to_string(runs) + " what-if runs, more than the " +
                          std::to_string(kMaxCombinedOrderRuns) +
                          " the model makes, and each may leave another answer");
  return {};
}

// Every order (a stated sample past kMaxOrderedCandidates) of the candidates
// that matter and `force` leaves in play, under each tie rule they call
// for, from the decisions `force`: each outcome not seen yet joins `runs`.
// True when the orders were a sample and their outcomes differ (from the
// trace's actual one, from the model's own decisions; else from the first
// run's), where that makes the case an error (past the bound, but where
// only tied reports may differ): then it is one.
bool TraceClassifier::tryOrdersFrom(const std::vector<int8_t>& force,
                                    const std::vector<uint32_t>& matter, bool reported,
                                    OrderRunsSeen& runs) {
  const std::vector<uint32_t> in_play = inPlay(matter, force);
  const bool sample = in_play.size() > kMaxOrderedCandidates;
  const std::vector<std::vector<uint32_t>> orders =
      sample ? sampleOrders(cands_.size(), in_play) : everyOrder(cands_.size(), in_play);
  std::optional<OrderOutcome> first;
  if (force.empty()) first = runs.outcomes[0];
  bool differs = false;
  for (const std::vector<uint32_t>& order : orders)
    for (const TieRule rule : tieRules(in_play, reported))
      for (WhatIf& how : orderRuns(order, in_play, rule, force)) {
        OrderOutcome o;
        m_.sandbox(tr_, cands_, how, payload_in_, &o);
        const double tol = tr_.tol(o.best.t);
        if (!first) first = o;
        differs = differs || !sameOutcome(*first, o, tol);
        const bool known =
            std::any_of(runs.outcomes.begin(), runs.outcomes.end(),
                        [&](const OrderOutcome& s) { return sameOutcome(s, o, tol); });
        if (known) continue;
        runs.outcomes.push_back(std::move(o));
        runs.hows.push_back(std::move(how));
      }
  if (!sample || !differs || (!tr_.query && m_.sh_.programs->order_ties_only)) return false;
  orderDependentPastBound("meets " + std::to_string(in_play.size()) + " candidates" +
                          (force.empty() ? "" : " under a legal decision of its unsure ones") +
                          ", more than the " + std::to_string(kMaxOrderedCandidates) +
                          " whose every order the model tries, and the orders it tried leave "
                          "different answers behind");
  return true;
}

// R-ORDER-UNSPEC, R-TOFH, R-TIE: candidates arrive in any order (and a report
// at the committed t may keep or replace it). Where that may change what a
// trace leaves behind, each order of the candidates that matter runs in a
// sandboxed what-if run; each distinct outcome (the committed hit, or the
// record, payload or query frame) is a legal answer.
bool TraceClassifier::tryPermutations(const std::vector<std::pair<size_t, double>>& reports) {
  const bool tofh = (tr_.flags & kRayTerminateOnFirstHit) != 0;
  const bool dependent =
      tr_.query ? tr_.query->stmt->order_dependent : m_.sh_.programs->order_dependent;
  const bool ties = reportsTie(reports);
  if (!tofh && !dependent && !ties) return false;
  const std::vector<uint32_t> matter = orderedCandidates(reports);
  const bool reported = std::any_of(reports.begin(), reports.end(),
                                    [](const auto& r) { return !std::isnan(r.second); });
  // One candidate has no other order: only its own tied reports matter.
  if (matter.size() <= 1 && !ties) return true;
  OrderRunsSeen runs{{actualOutcome()}, {actual()}};
  // The model's own decisions in every order, then (unless that made the
  // case an error) each legal set of the unsure candidates' in every order.
  if (!tryOrdersFrom({}, matter, reported, runs))
    for (const std::vector<int8_t>& force : combinedBases(matter, reported))
      if (tryOrdersFrom(force, matter, reported, runs)) break;
  if (runs.outcomes.size() < 2) return true;
  for (size_t k = 0; k < runs.outcomes.size(); ++k)
    addCommitted(runs.outcomes[k].best, runs.hows[k]);
  // A tie alone names the reason only if nothing else does (a sphere's two
  // roots at tangency tie because of its arithmetic: shader-arith).
  if (!tofh && !dependent)
    tie_reason_ = AmbiguityReason::TTie;
  else if (!reason_)
    reason_ = tofh   ? AmbiguityReason::FirstHit
              : ties ? AmbiguityReason::TTie
                     : AmbiguityReason::Order;
  return true;
}

}  // namespace rayspec
