// The model's meaning of every built-in (program/builtins.h): the launch,
// the hit or candidate, the ray, the instance matrices, vertex positions,
// and the payload and callable data a stage reads.
#include "model/model_builtins.h"

#include <algorithm>
#include <cmath>

#include "results/tolerances.h"

namespace rayspec {

// The payload and callable data a stage reads (payload.*, child.*, call.*, callee.*).
Val ModelBuiltins::dataBuiltin(const CExpr& e, StageEnv& env) const {
  static const Payload kNoPayload;
  static const CallData kNoCall;
  const Payload* pl = env.payload ? env.payload : &kNoPayload;
  const CallData* cd = env.call ? env.call : &kNoCall;
  switch (e.builtin) {
    case kBiPayloadColor:
      return fromVec4(pl->color);
    case kBiPayloadValue:
      return fromUint(pl->value);
    case kBiPayloadWord:
      return fromUint(pl->words[e.index % kMaxPayloadWords]);
    case kBiChildColor:
      return fromVec4(env.child.color);
    case kBiChildValue:
      return fromUint(env.child.value);
    case kBiChildWord:
      return fromUint(env.child.words[e.index % kMaxPayloadWords]);
    case kBiCallPosition:
      return fromVec3(cd->position);
    case kBiCallNormal:
      return fromVec3(cd->normal);
    case kBiCallColor:
      return fromVec4(cd->color);
    case kBiCallValue:
      return fromUint(cd->value);
    case kBiCalleeColor:
      return fromVec4(env.callee.color);
    case kBiCalleeValue:
      return fromUint(env.callee.value);
    case kBiCallWord:
      return fromUint(cd->words[e.index % kMaxCallDataWords]);
    case kBiCalleeWord:
      return fromUint(env.callee.words[e.index % kMaxCallDataWords]);
    case kBiPayloadSized:
      return pl->sized.read(static_cast<ValueType>(e.index));
    case kBiChildSized:
      return env.child.sized.read(static_cast<ValueType>(e.index));
    case kBiCallSized:
      return cd->sized.read(static_cast<ValueType>(e.index));
    case kBiCalleeSized:
      return env.callee.sized.read(static_cast<ValueType>(e.index));
    default:
      break;
  }
  unknown(e);
  return Val{};
}

uint32_t* ModelBuiltins::dataWord(WordArray which, uint32_t words, uint32_t index, StageEnv& env) {
  if (words == 0) return nullptr;
  const uint32_t i = index % words;
  switch (which) {
    case WordArray::Payload:
      return env.payload && i < kMaxPayloadWords ? &env.payload->words[i] : nullptr;
    case WordArray::Child:
      return i < kMaxPayloadWords ? &env.child.words[i] : nullptr;
    case WordArray::Call:
      return env.call && i < kMaxCallDataWords ? &env.call->words[i] : nullptr;
    case WordArray::Callee:
      return i < kMaxCallDataWords ? &env.callee.words[i] : nullptr;
  }
  return nullptr;
}

// vertex_position<i>: the hit triangle's vertex in object space (zero for a
// box, where reading it is refused at parse time). The planted fault
// position_fetch_world_space takes it through the instance transform.
Val ModelBuiltins::vertexPosition(const HitView& hv, int i) const {
  if (!hv.vertices) return Val{};
  const Vec3& p = (*hv.vertices)[static_cast<size_t>(i)];
  if (!sh_.fault_seam.positionFetchWorldSpace()) return fromVec3(p);
  return fromVec3(applyAffine(sh_.c->scene.instances[hv.instance].transform, p, 1.0f));
}

// object_to_world<c> / _3x4_<r> (k = c, or 4 + r) and world_to_object's
// (k + 7): the hit instance's transform and its inverse, both row-major 3x4.
// The planted fault transform_builtins_swapped gives each the other.
Val ModelBuiltins::transformBuiltin(const HitView& hv, int k) const {
  if (hv.instance >= sh_.scene->instances.size()) return Val{};
  const bool inverse = (k >= 7) != sh_.fault_seam.transformBuiltinsSwapped();
  const ModelInstance& mi = sh_.scene->instances[hv.instance];
  const Transform& m = inverse ? mi.inverse_f : mi.src->transform;
  const int i = k % 7;
  Val v;
  if (i < 4)
    v.f = {m[i], m[4 + i], m[8 + i], 0};  // column i of mat4x3
  else
    v.f = {m[4 * (i - 4)], m[4 * (i - 4) + 1], m[4 * (i - 4) + 2], m[4 * (i - 4) + 3]};  // row
  return v;
}

// The launch and the ray: launch_*, ray_*, flags, cull mask, world ray, depth, hit.
Val ModelBuiltins::rayBuiltin(const CExpr& e, const StageEnv& env) const {
  static const TraceRay kNoRay;
  const TraceRay* r = env.ray ? env.ray : &kNoRay;
  switch (e.builtin) {
    case kBiLaunchX:
      return fromUint(st_.x);
    case kBiLaunchY:  // the records' row y is launch z x launch height + launch y
      return fromUint(st_.y % st_.launch[1]);
    case kBiLaunchZ:
      return fromUint(st_.y / st_.launch[1]);
    case kBiLaunchW:
      return fromUint(st_.launch[0]);
    case kBiLaunchH:
      return fromUint(st_.launch[1]);
    case kBiLaunchD:
      return fromUint(st_.launch[2]);
    case kBiTmin:
      return fromFloat(r->tmin);
    case kBiTmax:
      return fromFloat(env.tmax_view);
    case kBiCullMask:  // the low 8 bits only (program/builtin_table.h)
      return fromUint(r->cull_mask & kVisibilityMask);
    case kBiFlags:
      return fromUint(r->flags);
    case kBiWorldOrigin:
      return fromVec3(r->origin);
    case kBiWorldDirection:
      return fromVec3(r->direction);
    case kBiDepth:
      return fromUint(env.depth);
    case kBiHit:
      return fromUint(env.stage == Stage::ClosestHit ? 1u : 0u);
    default:
      return Val{};  // builtin() sends no other
  }
}

// The hit or candidate: its ids, kind, t, attributes, box, object-space ray,
// position and vertices.
// The object-space origin is a float affine transform of the world origin,
// row r: sum_j W[r][j] o_j + W[r][3]. Any order or fusing of those roundings
// errs by some gamma(4) of the sum of the terms' magnitudes, which a far
// translation cancelled in it leaves large beside the result (an origin at
// 1030 in an instance translated by -1026 gives 4, off by an ulp of 1030).
// The field's tolerance is relative to the result, so where the terms exceed
// it, the ray's bound becomes the tolerance relative to the terms.
void ModelBuiltins::noteObjectOriginBound(const HitView& hv, const Vec3& o) const {
  if (!sh_.scene || hv.instance >= sh_.scene->instances.size()) return;
  const std::array<float, 12>& w = sh_.scene->instances[hv.instance].inverse_f;
  double terms = 0, result = 1;
  for (int row = 0; row < 3; ++row) {
    double sum = std::fabs(static_cast<double>(w[4 * row + 3]));
    for (int j = 0; j < 3; ++j) sum += std::fabs(static_cast<double>(w[4 * row + j]) * o[j]);
    terms = std::max(terms, sum);
    result = std::max(result, std::fabs(static_cast<double>(hv.object_origin[row])));
  }
  if (terms <= result) return;
  const Tolerance tol = toleranceFor("object_ray_origin");
  st_.object_origin_bounds.push_back({st_.index, static_cast<float>(tol.abs + tol.rel * terms)});
}

Val ModelBuiltins::hitBuiltin(const CExpr& e, const StageEnv& env) const {
  static const HitView kNone;
  static const TraceRay kNoRay;
  const HitView* hv = env.hit ? env.hit : &kNone;
  const TraceRay* r = env.ray ? env.ray : &kNoRay;
  switch (e.builtin) {
    case kBiPrimitive:
      return fromUint(hv->primitive);
    case kBiInstance:
      return fromUint(hv->instance);
    case kBiCustomIndex:  // planted, in an inlined query's hit stages: the instance id
      return fromUint(sh_.fault_seam.inlinedQuery(env.depth).custom_index_is_instance_id
                          ? hv->instance
                          : hv->custom_index);
    case kBiGeometry:
      return fromUint(hv->geometry);
    case kBiHitKind:
      return fromUint(hv->hit_kind);
    case kBiHitT:
      return fromFloat(hv->t);
    case kBiBarycentrics: {
      Val v;
      v.f = {hv->b1, hv->b2, 0, 0};
      return v;
    }
    case kBiAabbMin:
      return fromVec3(hv->aabb_min);
    case kBiAabbMax:
      return fromVec3(hv->aabb_max);
    case kBiObjectOrigin:
      noteObjectOriginBound(*hv, r->origin);
      return fromVec3(hv->object_origin);
    case kBiObjectDirection:
      return fromVec3(hv->object_direction);
    case kBiHitPosition: {
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = r->origin[k] + hv->t * r->direction[k];
      return fromVec3(p);
    }
    case kBiAttributeWord:
      return fromUint(hv->words[e.index % kMaxAttributeWords]);
    case kBiAttributeSized:
      return hv->sized.read(static_cast<ValueType>(e.index));
    default:
      return Val{};  // builtin() sends no other
  }
}

// The rows dataBuiltin reads: the payload and callable data.
#define RAYSPEC_DATA_BUILTIN_CASES \
  case kBiPayloadColor:            \
  case kBiPayloadValue:            \
  case kBiPayloadWord:             \
  case kBiPayloadSized:            \
  case kBiChildColor:              \
  case kBiChildValue:              \
  case kBiChildWord:               \
  case kBiChildSized:              \
  case kBiCallPosition:            \
  case kBiCallNormal:              \
  case kBiCallColor:               \
  case kBiCallValue:               \
  case kBiCallWord:                \
  case kBiCallSized:               \
  case kBiCalleeColor:             \
  case kBiCalleeValue:             \
  case kBiCalleeWord:              \
  case kBiCalleeSized:

// Every row of program/builtin_table.h, with no default: a row the model
// gives no meaning fails the build (-Werror=switch).
Val ModelBuiltins::read(const CExpr& e, StageEnv& env) const {
  static const HitView kNone;
  switch (static_cast<Builtin>(e.builtin)) {
    case kBiLaunchX:
    case kBiLaunchY:
    case kBiLaunchZ:
    case kBiLaunchW:
    case kBiLaunchH:
    case kBiLaunchD:
    case kBiTmin:
    case kBiTmax:
    case kBiCullMask:
    case kBiFlags:
    case kBiWorldOrigin:
    case kBiWorldDirection:
    case kBiDepth:
    case kBiHit:
      return rayBuiltin(e, env);
    case kBiPrimitive:
    case kBiInstance:
    case kBiCustomIndex:
    case kBiGeometry:
    case kBiHitKind:
    case kBiHitT:
    case kBiBarycentrics:
    case kBiAabbMin:
    case kBiAabbMax:
    case kBiObjectOrigin:
    case kBiObjectDirection:
    case kBiHitPosition:
    case kBiAttributeWord:
    case kBiAttributeSized:
      return hitBuiltin(e, env);
    case kBiVertex0:
    case kBiVertex1:
    case kBiVertex2:
      return vertexPosition(env.hit ? *env.hit : kNone, e.builtin - kBiVertex0);
    case kBiObjectToWorld0:
    case kBiObjectToWorld1:
    case kBiObjectToWorld2:
    case kBiObjectToWorld3:
    case kBiObjectToWorld3x4_0:
    case kBiObjectToWorld3x4_1:
    case kBiObjectToWorld3x4_2:
    case kBiWorldToObject0:
    case kBiWorldToObject1:
    case kBiWorldToObject2:
    case kBiWorldToObject3:
    case kBiWorldToObject3x4_0:
    case kBiWorldToObject3x4_1:
    case kBiWorldToObject3x4_2:
      return transformBuiltin(env.hit ? *env.hit : kNone, e.builtin - kBiObjectToWorld0);
      RAYSPEC_DATA_BUILTIN_CASES
      return dataBuiltin(e, env);
#define RAYSPEC_BUILTIN_CASE(id, ...) case kBi##id:
      RAYSPEC_QUERY_BUILTINS(RAYSPEC_BUILTIN_CASE)
      return queryBuiltin(e, env);
      RAYSPEC_HIT_OBJECT_BUILTINS(RAYSPEC_BUILTIN_CASE)
#undef RAYSPEC_BUILTIN_CASE
      return hitObjectBuiltin(e, env);
    case kBiCount:
    case kBiUnknown:
      break;
  }
  unknown(e);
  return Val{};
}
#undef RAYSPEC_DATA_BUILTIN_CASES

void ModelBuiltins::unknown(const CExpr& e) const {
  if (st_.error.empty())
    st_.error = "model: unknown built-in '" + (e.src ? e.src->name : std::string("?")) + "'";
}

}  // namespace rayspec
