// The hit object's getters (hit_object.*, GL_NV_shader_invocation_reorder):
// its state, and the built-ins a closest-hit of its hit would read, on its
// hit and ray (model_builtins.h). The planted getter faults
// (model_faults.h) break one family each.
#include "model/model_builtins.h"

#include "case/bit_widths.h"

namespace rayspec {
namespace {

// The hit stage built-in a getter reads on the hit object's hit and ray;
// kBiUnknown for the getters of its own (state, t, SBT record).
Builtin mirrored(uint8_t b) {
  if (b >= kBiHoObjectToWorld0 && b <= kBiHoObjectToWorld3)
    return static_cast<Builtin>(kBiObjectToWorld0 + (b - kBiHoObjectToWorld0));
  if (b >= kBiHoWorldToObject0 && b <= kBiHoWorldToObject3)
    return static_cast<Builtin>(kBiWorldToObject0 + (b - kBiHoWorldToObject0));
  switch (b) {
    case kBiHoInstance:
      return kBiInstance;
    case kBiHoCustomIndex:
      return kBiCustomIndex;
    case kBiHoPrimitive:
      return kBiPrimitive;
    case kBiHoGeometry:
      return kBiGeometry;
    case kBiHoHitKind:
      return kBiHitKind;
    case kBiHoTmin:
      return kBiTmin;
    case kBiHoWorldOrigin:
      return kBiWorldOrigin;
    case kBiHoWorldDirection:
      return kBiWorldDirection;
    case kBiHoObjectOrigin:
      return kBiObjectOrigin;
    case kBiHoObjectDirection:
      return kBiObjectDirection;
    case kBiHoAttributes:
      return kBiBarycentrics;
    default:
      return kBiUnknown;
  }
}

// The built-in a planted getter fault reads instead (the ids each other's,
// the object ray the world's, each matrix the other).
Builtin faulty(Builtin b, const ModelFaultSeam& seam) {
  if (seam.hitObjectIdsSwapped()) {
    if (b == kBiInstance || b == kBiCustomIndex)
      return b == kBiInstance ? kBiCustomIndex : kBiInstance;
    if (b == kBiPrimitive || b == kBiGeometry)
      return b == kBiPrimitive ? kBiGeometry : kBiPrimitive;
  }
  if (seam.hitObjectObjectRayWorld()) {
    if (b == kBiObjectOrigin) return kBiWorldOrigin;
    if (b == kBiObjectDirection) return kBiWorldDirection;
  }
  if (seam.hitObjectMatricesSwapped() && isInstanceTransform(b))
    return static_cast<Builtin>(b < kBiWorldToObject0 ? b + 7 : b - 7);
  return b;
}

}  // namespace

// The state, t and SBT record: the hit object's own.
Val ModelBuiltins::hitObjectOwn(const CExpr& e, const HitObjectState& h) const {
  using K = HitObjectState::Kind;
  const ModelFaultSeam& seam = sh_.fault_seam;
  const bool swapped = seam.hitObjectStateWrong();
  switch (e.builtin) {
    case kBiHoIsHit:
      return fromUint(h.kind == K::Hit ? 1u : 0u);
    case kBiHoIsMiss:
      return fromUint(h.kind == (swapped ? K::Empty : K::Miss) ? 1u : 0u);
    case kBiHoIsEmpty:
      return fromUint(h.kind == (swapped ? K::Miss : K::Empty) ? 1u : 0u);
    case kBiHoT:  // a hit's t; a miss's, the ray's tmax
      return fromFloat(h.kind == K::Hit && !seam.hitObjectTInitial() ? h.hit.t : h.ray.tmax);
    default:  // kBiHoSbtIndex
      break;
  }
  if (!seam.hitObjectSbtIndexOfInstance()) return fromUint(h.sbt_index);
  if (h.kind != K::Hit || h.hit.instance >= sh_.c->scene.instances.size()) return fromUint(0);
  return fromUint(sh_.c->scene.instances[h.hit.instance].sbt_offset & kInstanceFieldMask);
}

Val ModelBuiltins::hitObjectBuiltin(const CExpr& e, const StageEnv& env) const {
  static const HitObjectState kEmpty;
  const HitObjectState& h = env.hit_object ? *env.hit_object : kEmpty;
  const Builtin b = mirrored(e.builtin);
  if (b == kBiUnknown) return hitObjectOwn(e, h);
  if (b == kBiBarycentrics && sh_.fault_seam.hitObjectAttributesLost()) return Val{};
  if (b == kBiHitKind && sh_.fault_seam.hitObjectIdsSwapped()) return fromUint(h.hit.hit_kind ^ 1u);
  StageEnv view;
  view.stage = Stage::ClosestHit;
  view.ray = &h.ray;
  view.hit = &h.hit;
  view.tmax_view = h.kind == HitObjectState::Kind::Hit ? h.hit.t : h.ray.tmax;
  view.depth = h.depth;
  CExpr read_as;
  read_as.kind = Expr::Kind::Builtin;
  read_as.builtin = faulty(b, sh_.fault_seam);
  read_as.src = e.src;
  return read(read_as, view);
}

}  // namespace rayspec
