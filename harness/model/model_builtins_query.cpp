// The ray query getters (program/builtin_table.h: candidate.*, committed.*,
// query.*), read from the innermost query running (model/query_run.h):
// what the matching ray tracing built-ins would hold for that hit (R-RQ-VALUES).
#include <string>

#include "model/model_builtins.h"
#include "model/traversal.h"

namespace rayspec {

using namespace trace_detail;

// Row `row` of the hit getters (t .. world_to_object3) on the view of a hit.
Val ModelBuiltins::queryHit(int row, const HitView& hv) const {
  switch (row) {
    case 0:
      return fromFloat(hv.t);
    case 1:  // the planted fault rq_custom_index_is_instance_id reads the id
      return fromUint(sh_.fault_seam.queryCustomIndexIsInstanceId() ? hv.instance
                                                                    : hv.custom_index);
    case 2:
      return fromUint(hv.instance);
    case 3:  // the instance's SBT record offset (24 bits)
      return fromUint(hv.instance < sh_.c->scene.instances.size()
                          ? sh_.c->scene.instances[hv.instance].sbt_offset & kInstanceFieldMask
                          : 0u);
    case 4:
      return fromUint(hv.geometry);
    case 5:
      return fromUint(hv.primitive);
    case 6: {
      Val v;
      v.f = {hv.b1, hv.b2, 0, 0};
      return v;
    }
    case 7: {  // the planted fault rq_front_face_inverted reads a triangle's other face
      const bool inverted = hv.vertices && sh_.fault_seam.queryFrontFaceInverted();
      return fromUint((hv.hit_kind == 0xFEu) != inverted ? 1u : 0u);
    }
    case 8:
      return fromVec3(hv.object_origin);
    case 9:
      return fromVec3(hv.object_direction);
    case 18:
    case 19:
    case 20:
      return queryVertexPosition(hv, row - 18);
    default:  // object_to_world0..3, then world_to_object0..3
      return transformBuiltin(hv, row < 14 ? row - 10 : 7 + (row - 14));
  }
}

// vertex_position<i> of the candidate or committed intersection
// (rayQueryGetIntersectionTriangleVertexPositionsEXT): a triangle's only. A
// box's has no positions to fetch: R-UB, which the parser cannot tell where
// the intersection read is the committed one.
Val ModelBuiltins::queryVertexPosition(const HitView& hv, int i) const {
  if (!hv.vertices && !st_.ray_undefined)
    st_.markUndefined(
        UndefinedReason::QueryPositionsOfBox,
        "a ray query's vertex_position" + std::to_string(i) + " read of an AABB intersection");
  return vertexPosition(hv, i);
}

Val ModelBuiltins::queryBuiltin(const CExpr& e, const StageEnv& env) const {
  const QueryRun* q = env.query;
  if (!q) return Val{};
  const Committed& best = q->tr ? q->tr->best : q->committed;
  const ModelScene& scene = *sh_.scene;
  switch (e.builtin) {
    case kBiQTmin:
      return fromFloat(q->ray.tmin);
    case kBiQFlags:
      return fromUint(q->ray.flags);
    case kBiQWorldOrigin:
      return fromVec3(q->ray.origin);
    case kBiQWorldDirection:
      return fromVec3(q->ray.direction);
    case kBiQCandType:  // rq_candidate_type_swapped reads the other kind
      return fromUint(
          q->cand && (q->cand->aabb != sh_.fault_seam.queryCandidateTypeSwapped()) ? 1u : 0u);
    case kBiQCandAabbOpaque:
      return fromUint(q->cand_opaque ? 1u : 0u);
    case kBiQCommittedType: {
      if (!best.valid) return fromUint(0);
      const ModelInstance& mi = scene.instances[best.instance];
      const bool box =
          scene.blases[mi.blas].geometries[best.geometry].kind == Geometry::Kind::Aabbs;
      return fromUint(box ? 2u : 1u);
    }
    default:
      break;
  }
  const bool committed = e.builtin >= kBiQCommittedT;
  const int row = e.builtin - (committed ? kBiQCommittedT : kBiQCandT);
  // The planted fault rq_committed_reads_candidate: the committed getters
  // read the candidate while one is offered.
  if (!committed || (q->cand && sh_.fault_seam.queryCommittedReadsCandidate())) {
    if (row == 8) noteObjectOriginBound(q->cand_view, q->ray.origin);
    return queryHit(row, q->cand_view);
  }
  if (!best.valid) {
    // R-RQ-VALUES, R-UB: no committed intersection to read (a device may
    // even crash: lavapipe does); the parser cannot tell, the model marks it.
    const std::string what = e.src ? e.src->name : std::string("a committed value");
    const std::string field = e.src && !e.src->loc.field.empty() ? e.src->loc.field : what;
    if (!st_.ray_undefined)
      st_.markUndefined(UndefinedReason::QueryNothingCommitted,
                        field + ": " + what + " read with nothing committed");
    return Val{};
  }
  HitView hv = viewOf(scene, *sh_.c, q->ray, best.instance, best.geometry, best.primitive);
  setHit(hv, static_cast<float>(best.t), best.kind, best.b1, best.b2);
  if (row == 8) noteObjectOriginBound(hv, q->ray.origin);
  return queryHit(row, hv);
}

}  // namespace rayspec
