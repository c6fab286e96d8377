// The model's shader binding table (model_sbt.h).
#include "model/model_sbt.h"

namespace rayspec {
namespace {

// A region of one record per shader group, in order.
std::vector<SbtRecord> oneRecordPerGroup(size_t n) {
  std::vector<SbtRecord> v(n);
  for (size_t i = 0; i < n; ++i) v[i].group = static_cast<uint32_t>(i);
  return v;
}

}  // namespace

ModelSbt::ModelSbt(const Case& c) : c_(c) {
  const Pipeline& p = c.pipeline;
  miss_ = p.sbt_miss.empty() ? oneRecordPerGroup(p.miss.size()) : p.sbt_miss;
  hit_ = p.sbt_hit.empty() ? oneRecordPerGroup(p.hit_groups.size()) : p.sbt_hit;
  callable_ = p.sbt_callable.empty() ? oneRecordPerGroup(p.callables.size()) : p.sbt_callable;
}

uint64_t ModelSbt::hitIndex(uint32_t instance, uint32_t geometry, const TraceRay& r) const {
  const Instance& inst = c_.scene.instances[instance];
  return static_cast<uint64_t>(inst.sbt_offset & kInstanceFieldMask) +
         static_cast<uint64_t>(geometry) * (r.sbt_stride & kTraceSbtFieldMask) +
         (r.sbt_offset & kTraceSbtFieldMask);
}

}  // namespace rayspec
