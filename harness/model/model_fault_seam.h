// The one place the model reads its planted faults (ModelFaults,
// model/model_faults.h; test only). Every other model file asks this seam
// a question named for the rule it decides, and style/fault-seam
// (tools/check-fault-seam.sh) fails when another model file reads a knob.
// A product run builds it from ModelOptions left at their defaults: each
// answer is then the model's own behaviour.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

#include "model/model_faults.h"

namespace rayspec {

struct ModelOptions;
struct Pipeline;

class ModelFaultSeam {
 public:
  ModelFaultSeam() = default;
  // `inlining`: the pipeline whose traces a --through ray-query* run may
  // inline as ray query loops (inlinedQuery); none: no trace is a query.
  explicit ModelFaultSeam(const ModelOptions& opt, const Pipeline* inlining = nullptr);

  // R-CAND-TRI-OPEN broken: a triangle at exactly tmin or tmax is a candidate.
  bool closedTriangleInterval() const {
    return f_.deviation == ModelDeviation::ClosedTriangleInterval;
  }
  // R-CAND-AABB-CLOSED broken: a report at exactly tmin or tmax is refused.
  bool openAabbInterval() const { return f_.deviation == ModelDeviation::OpenAabbInterval; }
  // R-ORDER-UNSPEC: candidates decided near to far, the model's own order
  // (only then may a trace take Embree's own closest hit).
  bool distanceOrder() const { return f_.order == CandidateOrder::Distance; }
  // Whether candidate a (at t_a, with the key (instance, geometry,
  // primitive) smaller than b's: key_less) is decided before b (at t_b).
  bool decidedBefore(double t_a, double t_b, bool key_less) const {
    if (f_.order == CandidateOrder::BuildOrder || t_a == t_b) return key_less;
    return f_.order == CandidateOrder::ReverseDistance ? t_a > t_b : t_a < t_b;
  }
  // A legal device deciding candidates in a fixed shuffle (CandidateOrder::
  // Permuted): whether it does, and a candidate's place in it, by its key.
  bool permutedOrder() const { return f_.order == CandidateOrder::Permuted; }
  uint64_t permutedRank(uint32_t instance, uint32_t geometry, uint32_t primitive) const;
  // A legal device deciding one candidate after every other (CandidateOrder::
  // OneLast), the rest near to far: whether this key is that candidate.
  bool decidedLast(uint32_t instance, uint32_t geometry, uint32_t primitive) const {
    return f_.order == CandidateOrder::OneLast && instance == f_.last_instance &&
           geometry == f_.last_geometry && primitive == f_.last_primitive;
  }
  // R-STACK broken: a callable nested past the default stack does nothing.
  bool stackSizeIgnored() const { return f_.stack_size_ignored; }
  // R-POSITION-FETCH broken: vertex_position<i> in world space.
  bool positionFetchWorldSpace() const { return f_.position_fetch_world_space; }
  // R-BUILTIN broken: object_to_world and world_to_object swapped.
  bool transformBuiltinsSwapped() const { return f_.transform_builtins_swapped; }
  bool hitObjectTraceShades() const { return f_.hit_object_trace_shades; }  // R-HIT-OBJECT-DEFERRED
  // R-HIT-OBJECT: one family of the hit object's getters read wrong (HitObjectGetterFault).
  bool hitObjectStateWrong() const { return getter(HitObjectGetterFault::StateWrong); }
  bool hitObjectIdsSwapped() const { return getter(HitObjectGetterFault::IdsSwapped); }
  bool hitObjectTInitial() const { return getter(HitObjectGetterFault::TInitial); }
  bool hitObjectObjectRayWorld() const { return getter(HitObjectGetterFault::ObjectRayWorld); }
  bool hitObjectMatricesSwapped() const { return getter(HitObjectGetterFault::MatricesSwapped); }
  bool hitObjectAttributesLost() const { return getter(HitObjectGetterFault::AttributesLost); }
  bool hitObjectSbtIndexOfInstance() const {
    return getter(HitObjectGetterFault::SbtIndexOfInstance);
  }
  // R-HIT-OBJECT-RECORD: a hit recorded by hand, or the record handle, wrong.
  bool hitObjectRecord(HitObjectRecordFault f) const { return f_.hit_object_record == f; }
  // R-BUILTIN, R-RQ-EQUIV broken: a nested hit's built-ins replace its caller's.
  bool nestedTraceClobbersHit() const { return f_.nested_trace_clobbers_hit; }
  // Live state broken: locals read zero after a trace, call or report.
  bool localsLostAcrossCalls() const { return f_.locals_lost_across_calls; }
  // Live state broken for sized scalars: they come back with half their bits.
  bool sizedLocalsHalvedAcrossCalls() const { return f_.sized_locals_halved; }
  // Sized payload, callable data and hit attribute members come back with
  // half their bits: from a trace, from a call, from a report.
  bool sizedPayloadHalvedAcrossTrace() const { return f_.sized_payload_halved; }
  bool sizedCallDataHalvedAcrossCall() const { return f_.sized_call_data_halved; }
  bool sizedAttributeHalvedToCandidate() const { return f_.sized_attribute_halved; }
  // ... sized vectors come back with their components rotated.
  bool sizedVectorsRotatedAcrossCalls() const { return f_.sized_vectors_rotated; }
  // Zero-initialised sized arrays start as one.
  bool sizedNullNotZero() const { return f_.sized_null_not_zero; }
  // Ray queries: the rule each question stands for broken (ModelFaults' rq_*).
  bool queryInitKeepsCommitted() const { return f_.rq_init_keeps_committed; }  // R-RQ-INIT
  bool queryOffersOpaque() const { return f_.rq_opaque_offered; }              // R-RQ-CANDIDATES
  bool queryConfirmIgnored() const { return f_.rq_confirm_ignored; }           // R-RQ-COMMIT
  bool queryGenerateIgnored() const { return f_.rq_generate_ignored; }         // R-RQ-COMMIT
  bool queryTerminateIgnored() const { return f_.rq_terminate_ignored; }       // R-RQ-TERMINATE
  bool queryCommittedReadsCandidate() const { return f_.rq_committed_reads_candidate; }
  bool queryCustomIndexIsInstanceId() const {  // R-RQ-VALUES
    return f_.rq_custom_index_is_instance_id;
  }
  bool queryCommitKeepsInterval() const { return f_.rq_commit_keeps_interval; }    // R-RQ-COMMIT
  bool queryConfirmOnlyFirst() const { return f_.rq_confirm_only_first; }          // R-RQ-COMMIT
  bool queryCandidateTypeSwapped() const { return f_.rq_candidate_type_swapped; }  // R-RQ-VALUES
  bool queryFrontFaceInverted() const { return f_.rq_front_face_inverted; }        // R-RQ-VALUES
  bool queryCandidateShrinksInterval() const {  // R-RQ-CANDIDATES
    return f_.rq_candidate_shrinks_interval;
  }
  bool ignoreDiscardsWrites() const { return f_.ignore_discards_writes; }            // R-IGNORE
  bool queryBreakLosesCommit() const { return f_.rq_break_loses_commit; }            // R-RQ-COMMIT
  bool queryFunctionGetsCopy() const { return f_.rq_function_gets_copy; }            // R-RQ-COMMIT
  bool queryRestartKeepsCommitted() const { return f_.rq_restart_keeps_committed; }  // R-RQ-INIT
  bool queryStepWrongQuery() const { return f_.rq_step_wrong_query; }                // R-RQ-INIT
  bool queryObjectRayWorld() const { return f_.rq_object_ray_world; }                // R-RQ-VALUES
  // A trace that a --through ray-query* run inlines as a ray query loop
  // (glsl/emit_ray_query.h: every trace under Pipeline::ray_query, those of
  // closest-hit and miss, depth 2 on, under ray_query_in_hit): the query
  // faults planted, as that loop breaks them. All false for a trace at
  // `depth` that is no query loop. The faults that have no meaning on such a
  // loop are not here: it never breaks out of its loop nor passes its query
  // to a function; during a candidate it reads only the committed t, which
  // a box candidate (the one that reads it) does not define; and its query
  // restarting from the last commit is left to the case's own queries.
  struct InlinedQuery {
    bool opaque_offered = false;          // an opaque triangle runs the any-hit, confirmed or not
    bool confirm_ignored = false;         // a non-opaque triangle's accepted hit is not committed
    bool confirm_only_first = false;      // nor is it once something is committed
    bool generate_ignored = false;        // a report accepted (true), its commit lost
    bool terminate_ignored = false;       // terminateRay, TerminateOnFirstHit end no traversal
    bool commit_keeps_interval = false;   // a triangle's commit leaves tmax where it was
    bool candidate_type_swapped = false;  // a triangle runs no intersection, a box no program
    bool front_face_inverted = false;     // a triangle's hit_kind is its other face's
    bool custom_index_is_instance_id = false;  // instance_custom_index reads the instance id
    bool any() const {
      return opaque_offered || confirm_ignored || confirm_only_first || generate_ignored ||
             terminate_ignored || commit_keeps_interval || candidate_type_swapped ||
             front_face_inverted || custom_index_is_instance_id;
    }
  };
  InlinedQuery inlinedQuery(uint32_t depth) const;
  // Some trace's inlined query breaks a planted fault: every trace decides
  // its candidates (no direct hit).
  bool inlinedQueryFaulty() const { return inlinedQuery(UINT32_MAX).any(); }
  // A legal device (rayspec mutate) or one passing between shared edges:
  // an ambiguous trace is replayed as another of its answers.
  bool answersOtherwise() const { return f_.legal_answer != 0 || f_.pass_between_edges; }
  // Which of an ambiguous trace's answers such a device takes: the first of
  // its `leaks` answers passing between shared edges (R-WATERTIGHT not met)
  // when there is one, else the legal answer of ModelFaults::legal_answer
  // among `legal`; none: the model's own.
  struct Answer {
    bool leak = false;
    size_t index = 0;
  };
  std::optional<Answer> answerTaken(size_t legal, size_t leaks) const;
  // A legal device (rayspec mutate, R-AABB-CONS): every box tested as if grown
  // by its own extent on each side, so its neighbours' intersection programs run.
  bool aabbNeighboursRun() const { return f_.aabb_neighbours_run; }
  // A legal device (rayspec mutate, R-AABB-CONS, R-PREC): every box the ray
  // misses by no more than a device's error bound is offered all the same.
  bool nearBoxesOffered() const { return f_.aabb_near_offered; }

 private:
  bool getter(HitObjectGetterFault family) const { return f_.hit_object_getter == family; }
  ModelFaults f_;
  uint32_t inlined_from_depth_ = 0;  // the first trace depth inlined as a query loop (0: none)
};

}  // namespace rayspec
