// The model's fault-injection hook (test only). Planted faults (harness/fault/)
// run the model as a device that breaks one rule; they reach the model through
// ModelOptions::faults and nothing else. A product run leaves it at its
// defaults, which are the model's own behaviour. docs/layout-and-conventions.md,
// "The fault seam", lists every such hook.
#pragma once

namespace rayspec {

// One interval rule broken the way a faulty device would:
//   ClosedTriangleInterval: a triangle at exactly the ray's tmin or tmax is a
//     candidate (R-CAND-TRI-OPEN broken).
//   OpenAabbInterval: reportIntersectionEXT at exactly tmin or the current
//     tmax returns false (R-CAND-AABB-CLOSED broken).
enum class ModelDeviation { None, ClosedTriangleInterval, OpenAabbInterval };

// The order the model decides a trace's candidates in (R-ORDER-UNSPEC).
// Distance is the model's own (near to far); the others stand for devices
// that traverse otherwise: far to near, the order of the build (instance,
// geometry, primitive), a fixed shuffle of the candidates whatever their
// t (ModelFaults::order_seed; boxes entered at one t reordered too), and near
// to far but one candidate last (ModelFaults::order_last: a device may meet
// the candidate whose any-hit terminates after every other).
enum class CandidateOrder { Distance, ReverseDistance, BuildOrder, Permuted, OneLast };

// Hit objects (GL_NV_shader_invocation_reorder) broken, one getter family
// each (R-HIT-OBJECT): StateWrong: is_miss and is_empty each read the other;
// IdsSwapped: instance_id and instance_custom_index each read the other, so
// do primitive_id and geometry_index, and hit_kind its other face's;
// TInitial: t reads the tmax the trace started with, not the hit's;
// ObjectRayWorld: the object-space ray reads the world ray; MatricesSwapped:
// object_to_world and world_to_object each read the other; AttributesLost:
// attributes read zero; SbtIndexOfInstance: sbt_record_index reads the hit
// instance's SBT offset alone (no geometry or trace offset), a miss's 0.
enum class HitObjectGetterFault : uint8_t {
  None,
  StateWrong,
  IdsSwapped,
  TInitial,
  ObjectRayWorld,
  MatricesSwapped,
  AttributesLost,
  SbtIndexOfInstance
};

// Hits recorded by hand and the hit object's shader record broken, one each
// (R-HIT-OBJECT-RECORD): SbtNoInstanceOffset: hitObjectRecordHitNV's record
// leaves out the instance's SBT offset; IndexPlusInstanceOffset:
// hitObjectRecordHitWithIndexNV adds the instance's SBT offset to the index
// given; CustomIndexIsId: a recorded hit's custom index is its instance id
// (nothing read from the instance); HandleOwn:
// hitObjectGetShaderRecordBufferHandleNV addresses the calling stage's own
// record.
enum class HitObjectRecordFault : uint8_t {
  None,
  SbtNoInstanceOffset,
  IndexPlusInstanceOffset,
  CustomIndexIsId,
  HandleOwn
};

struct ModelFaults {
  ModelDeviation deviation = ModelDeviation::None;
  CandidateOrder order = CandidateOrder::Distance;
  uint32_t order_seed = 0;  // CandidateOrder::Permuted: which shuffle
  // CandidateOrder::OneLast: the key (instance, geometry, primitive) decided last.
  uint32_t last_instance = 0, last_geometry = 0, last_primitive = 0;
  // R-STACK broken: the stack size a case sets is ignored, so a callable
  // nested deeper than the default stack's kDefaultCallableDepth frames does
  // nothing (its caller's data stays as it was).
  bool stack_size_ignored = false;
  // R-POSITION-FETCH broken: vertex_position<i> reads the vertex in world
  // space (through the instance transform) instead of object space.
  bool position_fetch_world_space = false;
  // Live state broken: a shader's local variables read zero after a trace,
  // a callable call or a report (a driver that spills and restores them wrongly).
  bool locals_lost_across_calls = false;
  // Live state broken for the sized scalars only: after a trace, a callable
  // call or a report, a local of a sized type (program/sized_types.h) comes
  // back through a slot half its width: only the upper half of its bits (of
  // a float's encoding) kept (a driver that spills narrow and wide registers
  // wrongly).
  bool sized_locals_halved = false;
  // The pipeline interface broken for the sized members
  // (pipeline.payloads[].sized, callable_data[].sized, hit_attribute.sized):
  // each comes back through a slot half its width (only the upper half of
  // its bits kept), a payload's at the trace's return, callable data's at
  // the call's return, a hit attribute's from the report to the candidate
  // (a driver that lays out or spills narrow and wide interface members
  // wrongly).
  bool sized_payload_halved = false;
  bool sized_call_data_halved = false;
  bool sized_attribute_halved = false;
  // Live state broken for the sized vectors only: after a trace, a callable
  // call or a report, a sized vector local (i8vec2 .. f64vec4) comes back
  // with its components rotated (x takes y's, .., the last takes x's: a
  // driver that spills a vector's lanes to the wrong slots).
  bool sized_vectors_rotated = false;
  // Zero-initialised sized arrays broken: a sized array's elements start as
  // one (1 or 1.0 in each lane) instead of zero (a driver that drops the
  // OpConstantNull the declaration is initialised from).
  bool sized_null_not_zero = false;
  // R-BUILTIN broken: gl_ObjectToWorldEXT and gl_WorldToObjectEXT (and their
  // 3x4 forms) each read the other matrix.
  bool transform_builtins_swapped = false;
  // R-BUILTIN and R-RQ-EQUIV broken: after a nested trace that hits, the
  // closest-hit that made it reads the nested hit's built-ins (a device
  // whose nested query shares its caller's query, or lavapipe 25's pipeline:
  // references/driver-reports/lavapipe-builtins-after-nested-trace.md).
  bool nested_trace_clobbers_hit = false;
  // Legal devices (rayspec mutate): every ambiguous trace takes the answer of
  // this index among its legal answers (modulo their number; 0: the model's
  // own), with its shaders run as that answer makes them run.
  uint32_t legal_answer = 0;
  // Ray queries (ray_query statements), each rule broken as a faulty device would:
  //   rq_init_keeps_committed: rayQueryInitializeEXT keeps the committed
  //     intersection of the launch ray's previous query (R-RQ-INIT);
  //   rq_opaque_offered: opaque triangles are returned as candidates, and
  //     committed only if confirmed (R-RQ-CANDIDATES);
  //   rq_confirm_ignored: rayQueryConfirmIntersectionEXT commits nothing (R-RQ-COMMIT);
  //   rq_generate_ignored: rayQueryGenerateIntersectionEXT commits nothing (R-RQ-COMMIT);
  //   rq_terminate_ignored: neither rayQueryTerminateEXT nor a commit under
  //     TerminateOnFirstHit ends traversal (R-RQ-TERMINATE);
  //   rq_committed_reads_candidate: the committed getters read the current
  //     candidate while there is one (R-RQ-VALUES);
  //   rq_custom_index_is_instance_id: the instance custom index getters read
  //     the instance id (R-RQ-VALUES);
  //   rq_commit_keeps_interval: a commit does not shrink the query's interval:
  //     triangles beyond the committed t are still offered, and a confirm of
  //     one (or a generate beyond the committed t) replaces the closer
  //     commit (R-RQ-COMMIT: the closest commit stays);
  //   rq_confirm_only_first: rayQueryConfirmIntersectionEXT commits nothing
  //     once something is committed: the second of two confirmed candidates
  //     is dropped (R-RQ-COMMIT);
  //   rq_candidate_type_swapped: the candidate type reads AABB for a triangle
  //     and triangle for an AABB, so each candidate runs the other block
  //     (R-RQ-VALUES);
  //   rq_front_face_inverted: the front face getters of a triangle
  //     intersection read the other face; culling is not changed (R-RQ-VALUES);
  //   rq_break_loses_commit: a query whose loop a break leaves before
  //     rayQueryProceedEXT returns false has nothing committed (R-RQ-COMMIT:
  //     a device that commits only when traversal completes);
  //   rq_function_gets_copy: a function taking a query (query: true) gets a
  //     copy: its confirm, generate and terminate_query reach nothing (R-RQ-COMMIT);
  //   rq_restart_keeps_committed: rayQueryInitializeEXT of a query in
  //     traversal (restart_query) keeps what is committed (R-RQ-INIT: it
  //     discards all previous state);
  //   rq_step_wrong_query: stepping an array of queries (ray_queries)
  //     proceeds the next element: each query's blocks decide the next
  //     query's candidates (the next one's ray; R-RQ-INIT);
  //   rq_object_ray_world: a ray query's candidate object-space ray getters
  //     read the world-space ray (the instance transform not applied), and
  //     so does what its aabb block computes of the crossing (sphere_*;
  //     R-RQ-VALUES).
  // On a trace that a --through ray-query* run inlines as a query loop, each
  // breaks that loop where it has a meaning there (ModelFaultSeam::inlinedQuery).
  bool rq_init_keeps_committed = false;
  bool rq_opaque_offered = false;
  bool rq_confirm_ignored = false;
  bool rq_generate_ignored = false;
  bool rq_terminate_ignored = false;
  bool rq_committed_reads_candidate = false;
  bool rq_custom_index_is_instance_id = false;
  bool rq_commit_keeps_interval = false;
  bool rq_confirm_only_first = false;
  bool rq_candidate_type_swapped = false;
  bool rq_front_face_inverted = false;
  bool rq_break_loses_commit = false;
  bool rq_function_gets_copy = false;
  bool rq_restart_keeps_committed = false;
  bool rq_step_wrong_query = false;
  bool rq_object_ray_world = false;
  // R-RQ-CANDIDATES broken: the query's interval shrinks to each candidate it
  // returns, committed or not, so candidates beyond it are never returned.
  bool rq_candidate_shrinks_interval = false;
  // R-IGNORE broken: an any-hit that ignores its candidate loses what it
  // wrote before the ignore (counters, records), as if ignoreIntersectionEXT
  // discarded the invocation as a fragment's discard may.
  bool ignore_discards_writes = false;
  // R-WATERTIGHT not met (a "should"): every trace through a shared edge or
  // vertex passes between its triangles, where that changes the answer.
  bool pass_between_edges = false;
  // R-AABB-CONS used to the full (legal): every box is tested as if grown by
  // its own extent on each side, so intersection programs also run for the
  // boxes beside the ones a ray enters (as NVIDIA's runs its neighbours'):
  // a case whose intersection program reports without testing its box then
  // answers otherwise.
  bool aabb_neighbours_run = false;
  // R-AABB-CONS and R-PREC, legal: every box a ray passes within a device's
  // error bound of (model/box_bound.h) is offered, its intersection program
  // run, though the model's own ray misses it (far ray origins: whole units).
  bool aabb_near_offered = false;
  // R-HIT-OBJECT-DEFERRED broken: hitObjectTraceRayNV runs closest-hit or
  // miss as traceRayEXT does (and executing the hit object runs it again).
  bool hit_object_trace_shades = false;
  HitObjectGetterFault hit_object_getter = HitObjectGetterFault::None;
  HitObjectRecordFault hit_object_record = HitObjectRecordFault::None;
};

}  // namespace rayspec
