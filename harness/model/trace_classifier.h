// The exact tier's classifier of one trace (trace_classifier.cpp: the unsure
// candidates and the answer; model_exact_orders.cpp: the candidate orders;
// double_hits.cpp: the double hits).
// Internal to the model.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "case/share_frame.h"
#include "model/candidate_orders.h"
#include "model/model_tracer.h"
#include "model/traversal.h"

namespace rayspec {

// The steps of ModelTracer::classifyTrace over one trace: which candidates are
// unsure, the answers the what-if runs give, the reason the ray is
// ambiguous (the first found), and the answers it may legally have.
class TraceClassifier {
 public:
  TraceClassifier(ModelTracer& m, Traversal& tr, const std::vector<ModelCandidate>& cands,
                  const Payload& payload_in)
      : m_(m), tr_(tr), cands_(cands), payload_in_(payload_in), scene_(*m.sh_.scene) {
    amb_.ray = m.st_.index;
    amb_.from_query = tr.query != nullptr;
  }

  // Triangles near an edge, vertex or interval end, and grazed boxes, up to
  // the committed hit (tryUnsure reaches farther where a legal answer does).
  void findUnsure(const std::vector<std::pair<size_t, double>>& reports);
  // The triangles around the shared edge or vertex a ray meets.
  void findSharedTriangles();
  // The what-if runs where the unsure candidates decide otherwise.
  void tryUnsure();
  // R-WATERTIGHT: the double hits, where two or more triangles that close
  // around the ray may be hit (double_hits.cpp).
  void tryDoubleHits();
  // The most what-if runs tryDoubleHits makes for one trace.
  static constexpr size_t kMaxDoubleHitRuns = 256;
  // The decisions within rounding of the intersection programs of boxes the
  // model's ray misses but a device may offer, each flipped.
  void tryNearBoxDecisions();
  // Ties at the committed t, and the first candidate under TerminateOnFirstHit
  // or a terminating any-hit.
  void tryOrders(const std::vector<std::pair<size_t, double>>& reports);
  // Every order of the candidates that matter (a stated sample past
  // kMaxOrderedCandidates) where the candidate programs may depend on it,
  // under TerminateOnFirstHit, or where reports tie: false when none applies.
  bool tryPermutations(const std::vector<std::pair<size_t, double>>& reports);
  // Intersection-program decisions within rounding.
  void tryShaderDecisions(const std::vector<ShaderDecision>& shader_unsure);
  // How many of them one what-if run flips at most (flipNoted).
  static constexpr size_t kShaderFlipDepth = 2;
  // A committed t whose rounding may exceed hit_t's tolerance, and the span
  // of an unsure in-plane triangle: their bounds.
  void boundT();
  // Marks the ray ambiguous with its legal answers, if a reason was found;
  // how to decide as the legal device the fault seam asks for, if any.
  std::optional<WhatIf> finish();

 private:
  bool eligible(const ModelCandidate& cand) const;
  // tryDoubleHits' steps: whether a double hit may show in this trace, some
  // triangle of `group` running any-hit, and the run hitting `hits` of it.
  bool doubleHitsShow() const;
  bool anyHitRunsOn(const std::vector<size_t>& group) const;
  WhatIf doubleHit(const std::vector<size_t>& group, const std::vector<size_t>& hits) const;
  // findUnsure up to final_t; tryUnsure's answers, reaching as far as they do.
  void findUnsure(const std::vector<std::pair<size_t, double>>& reports, double final_t);
  std::vector<WhatIfAnswer> unsureAnswers(std::vector<WhatIfAnswer>& leaks);
  // A what-if answer and those of its committed hit's ties (R-TIE), each
  // tied candidate preferred.
  std::vector<long> tiedWith(const WhatIfAnswer& a) const;
  std::vector<WhatIfAnswer> withTies(const WhatIfAnswer& a);
  bool flipNoted(const WhatIf& base, const std::vector<ShaderDecision>& noted, size_t depth);
  void addCommitted(const Committed& b, const WhatIf& how);
  void addLeak(const Committed& b, const WhatIf& how);
  // Drops the leak answers that are legal answers too.
  void dropLegalLeaks();
  static WhatIf actual() { return {true, {}, -1, -1, {}}; }
  bool sameAsCommitted(const Committed& b) const;
  void boundTOf(double t, double t_err);
  void noteRootTFree(const Committed& b);
  bool inPlaneTMatters(size_t u) const;
  // tryPermutations' steps: the candidates whose order may matter, whether
  // two reports tie, what the actual run left behind, and a case error
  // where a sample of the orders past the bound answers otherwise.
  std::vector<uint32_t> orderedCandidates(
      const std::vector<std::pair<size_t, double>>& reports) const;
  bool reportsTie(const std::vector<std::pair<size_t, double>>& reports) const;
  std::vector<TieRule> tieRules(const std::vector<uint32_t>& matter, bool reported) const;
  std::vector<WhatIf> orderRuns(const std::vector<uint32_t>& order,
                                const std::vector<uint32_t>& matter, TieRule rule,
                                const std::vector<int8_t>& force) const;
  OrderOutcome actualOutcome() const;
  void orderDependentPastBound(const std::string& what);
  // The orders combined with the unsure candidates' legal decisions: the
  // decisions each set of order runs starts from, and one set's runs.
  struct OrderRunsSeen {
    std::vector<OrderOutcome> outcomes;  // each distinct outcome once, the actual first
    std::vector<WhatIf> hows;            // how each was reached
  };
  std::vector<std::vector<int8_t>> combinedBases(const std::vector<uint32_t>& matter,
                                                 bool reported);
  bool tryOrdersFrom(const std::vector<int8_t>& force, const std::vector<uint32_t>& matter,
                     bool reported, OrderRunsSeen& runs);
  // A legal what-if run's decisions of the unsure candidates, kept where
  // they differ from the model's own (tryUnsure, for tryPermutations).
  void noteUnsureForce(std::vector<int8_t> force);
  bool forcedAsOwn(size_t k, bool hit) const;

  ModelTracer& m_;
  Traversal& tr_;
  const std::vector<ModelCandidate>& cands_;
  const Payload& payload_in_;
  const ModelScene& scene_;
  RayAmbiguity amb_;
  std::vector<WhatIf> hows_;  // how each of amb_.candidates is reached
  // Every legal answer with a distinct effect (Committed::effect), the
  // actual run's first: each a legal replay's choice here (legal_replays.cpp).
  std::vector<WhatIf> replay_hows_;
  std::vector<uint64_t> replay_effects_;
  std::vector<WhatIf> leak_hows_;              // how each of amb_.leak_answers is reached
  std::vector<WhatIf> double_hows_;            // how each double hit is reached (tryDoubleHits)
  std::vector<size_t> shared_group_;           // amb_.shared_triangles' candidates
  std::optional<AmbiguityReason> reason_;      // the first reason found
  std::optional<AmbiguityReason> tie_reason_;  // reports tie (tryPermutations), if nothing else
  double reason_t_ = 0;                        // the t of the candidate that gave it
  std::vector<size_t> unsure_;                 // candidates whose decision could flip
  // The decisions (WhatIf::force) of tryUnsure's legal answers that decide
  // some candidate otherwise than the model, each once.
  std::vector<std::vector<int8_t>> unsure_forces_;
  const std::vector<std::pair<size_t, double>>* reports_ = nullptr;  // findUnsure's
  bool faces_ = false;                                               // a grazed box among them
};

// The share frame of a triangle candidate (case/share_frame.h); boxes all
// in one.
ShareFrame candidateFrame(const ModelScene& scene, const ModelCandidate& c);

}  // namespace rayspec
