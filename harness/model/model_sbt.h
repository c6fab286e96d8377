// The shader binding table as the model reads it: the miss, hit and
// callable regions (a pipeline without an `sbt` gets one record per shader
// group, in order) and where a hit's record lies (R-SBT-HIT).
#pragma once

#include <cstdint>
#include <vector>

#include "case/case.h"
#include "model/model_stage_env.h"

namespace rayspec {

class ModelSbt {
 public:
  explicit ModelSbt(const Case& c);
  // R-SBT-HIT: instance offset (24 bits) + geometry x stride + offset (4 bits each).
  uint64_t hitIndex(uint32_t instance, uint32_t geometry, const TraceRay& r) const;
  // Beyond the hit region: nullptr (R-UB: the caller marks the ray).
  const SbtRecord* hit(uint32_t instance, uint32_t geometry, const TraceRay& r) const {
    const uint64_t idx = hitIndex(instance, geometry, r);
    return idx < hit_.size() ? &hit_[idx] : nullptr;
  }
  // The hit record at index `idx` (hitObjectRecordHitWithIndexNV's); nullptr beyond.
  const SbtRecord* hitAt(uint64_t idx) const { return idx < hit_.size() ? &hit_[idx] : nullptr; }
  size_t hitCount() const { return hit_.size(); }
  const std::vector<SbtRecord>& miss() const { return miss_; }
  const std::vector<SbtRecord>& callables() const { return callable_; }

 private:
  const Case& c_;
  std::vector<SbtRecord> miss_, hit_, callable_;
};

}  // namespace rayspec
