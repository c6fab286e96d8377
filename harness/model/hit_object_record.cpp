// Hits recorded by hand into a hit object (hitObjectRecordHitNV,
// hitObjectRecordHitWithIndexNV; GL_NV_shader_invocation_reorder) and the
// record data its shader record handle addresses. A recorded hit holds what
// it was given (ids, hit kind, attributes, the ray; t is the ray's tmax) and
// what the instance it names decides (custom index, matrices, object-space
// ray); its record is the instance's SBT offset plus the given offset and
// geometry times stride, or the index given.
#include "case/bit_widths.h"
#include "model/model_tracer.h"
#include "model/traversal.h"

namespace rayspec {
namespace {

// The instance, geometry and primitive lie in the scene (an active instance).
bool inScene(const ModelScene& scene, const HitView& h) {
  if (h.instance >= scene.instances.size() || scene.instances[h.instance].blas < 0) return false;
  const auto& geometries = scene.blases[scene.instances[h.instance].blas].geometries;
  return h.geometry < geometries.size() && h.primitive < geometries[h.geometry].count;
}

}  // namespace

// The record the recorded hit runs (model_tracer.h); the planted faults
// break the instance's part.
uint64_t ModelTracer::recordedHitIndex(const HitView& h, const TraceRay& r,
                                       std::optional<uint32_t> index) const {
  using F = HitObjectRecordFault;
  const ModelFaultSeam& seam = sh_.fault_seam;
  const uint64_t own = sh_.c->scene.instances[h.instance].sbt_offset & kInstanceFieldMask;
  if (index) return *index + (seam.hitObjectRecord(F::IndexPlusInstanceOffset) ? own : 0);
  const uint64_t full = sbt_.hitIndex(h.instance, h.geometry, r);
  return seam.hitObjectRecord(F::SbtNoInstanceOffset) ? full - own : full;
}

void ModelTracer::recordHit(const TraceRay& r, const HitView& hit, std::optional<uint32_t> index,
                            uint32_t depth, const CStmt* site, HitObjectState& into) {
  into = HitObjectState{};
  if (st_.checkRayParameters(r, site, depth)) return;
  if (!inScene(*sh_.scene, hit) || (index && *index > kTraceSbtFieldMask)) {
    st_.markUndefined(UndefinedReason::HitObjectRecordOutsideScene,
                      "record_hit of instance " + std::to_string(hit.instance) + ", geometry " +
                          std::to_string(hit.geometry) + ", primitive " +
                          std::to_string(hit.primitive) +
                          (index ? ", SBT record " + std::to_string(*index) : std::string()) +
                          ": outside the top level (or a record index of 16 or more)");
    return;
  }
  into.kind = HitObjectState::Kind::Hit;
  into.ray = r;
  into.ray.flags = 0;  // hitObjectRecordHitNV takes no flags
  into.depth = depth;
  into.hit = viewOf(*sh_.scene, *sh_.c, r, hit.instance, hit.geometry, hit.primitive, true);
  setHit(into.hit, r.tmax, hit.hit_kind, hit.b1, hit.b2);
  if (sh_.fault_seam.hitObjectRecord(HitObjectRecordFault::CustomIndexIsId))
    into.hit.custom_index = hit.instance;
  into.sbt_index = static_cast<uint32_t>(recordedHitIndex(into.hit, r, index));
  noteRecordData(into);
}

void ModelTracer::noteRecordData(HitObjectState& h) const {
  h.record_data = nullptr;
  if (h.kind == HitObjectState::Kind::Hit) {
    if (const SbtRecord* rec = sbt_.hitAt(h.sbt_index)) h.record_data = &rec->data;
  } else if (h.kind == HitObjectState::Kind::Miss && h.sbt_index < sbt_.miss().size()) {
    h.record_data = &sbt_.miss()[h.sbt_index].data;
  }
}

}  // namespace rayspec
