// hitObjectTraceRayNV and hitObjectExecuteShaderNV in the model
// (GL_NV_shader_invocation_reorder, model_tracer.h): a hit object is the
// committed hit of its trace (or its miss) with the SBT record that hit or
// miss selects; executing it runs what the trace would have run
// (ModelTracer::shade), with that hit's built-ins.
#include "case/bit_widths.h"
#include "model/model_tracer.h"
#include "model/traversal.h"

namespace rayspec {

using namespace trace_detail;

Payload ModelTracer::traceIntoHitObject(const TraceRay& r, uint32_t depth, const CStmt* site,
                                        Payload payload, HitObjectState& into) {
  uint32_t flags = 0;
  const Committed best = committedHit(r, depth, site, payload, flags);
  into = HitObjectState{};
  into.ray = r;
  into.flags = flags;
  into.depth = depth;
  if (best.valid) {
    into.kind = HitObjectState::Kind::Hit;
    into.hit = viewOf(*sh_.scene, *sh_.c, r, best.instance, best.geometry, best.primitive, true);
    setHit(into.hit, static_cast<float>(best.t), best.kind, best.b1, best.b2);
    into.hit.words = best.words;
    into.hit.sized = best.sized;
    into.sbt_index = static_cast<uint32_t>(sbt_.hitIndex(best.instance, best.geometry, r));
  } else {
    into.kind = HitObjectState::Kind::Miss;
    into.sbt_index = r.miss & kTraceMissIndexMask;
  }
  noteRecordData(into);
  // Planted (R-HIT-OBJECT-DEFERRED broken): closest-hit or miss runs at the
  // trace, as traceRayEXT runs it.
  if (sh_.fault_seam.hitObjectTraceShades()) shade(r, flags, depth, best, payload);
  return payload;
}

void ModelTracer::executeHitObject(const HitObjectState& h, Payload& payload) {
  if (h.kind == HitObjectState::Kind::Empty) return;
  Committed best;
  best.valid = h.kind == HitObjectState::Kind::Hit;
  best.t = h.hit.t;
  best.instance = h.hit.instance;
  best.geometry = h.hit.geometry;
  best.primitive = h.hit.primitive;
  best.kind = h.hit.hit_kind;
  best.b1 = h.hit.b1;
  best.b2 = h.hit.b2;
  best.words = h.hit.words;
  best.sized = h.hit.sized;
  payload.depth = h.depth;
  shade(h.ray, h.flags, h.depth, best, payload,
        best.valid ? std::optional<uint64_t>(h.sbt_index) : std::nullopt);
}

}  // namespace rayspec
