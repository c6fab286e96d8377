// The launch ray's state and what it leaves behind (launch_state.h).
#include "model/launch_state.h"

#include <algorithm>
#include <bit>

#include "results/record_layout.h"

namespace rayspec {

LaunchState::LaunchState(const ModelShared& shared, const ModelSbt& sbt, uint32_t* records_in)
    : records(records_in), launch(shared.c->rays.launchSize()), sh_(shared), sbt_(sbt) {
  counters.assign(sh_.plan->counters.size(), 0);
  floors.assign(counters.size(), 0);
  ray_floors.assign(counters.size(), 0);
  const char* runs[6] = {"raygen_runs",  "miss_runs",         "closest_hit_runs",
                         "any_hit_runs", "intersection_runs", "callable_runs"};
  for (int k = 0; k < 6; ++k) runs_offset_[k] = findRecordField(runs[k])->offset;
  slots_offset_ = findRecordField("any_hit_slots")->offset;
  repeats_offset_ = findRecordField("any_hit_repeats")->offset;
}

void LaunchState::startRay(uint32_t i) {
  index = i;
  rec = records ? records + static_cast<size_t>(i) * recordWords() : nullptr;
  ray_ambiguous = false;
  ray_undefined = false;
  ray_t_free = false;
  repeated_any_hit = false;
  call_nesting = 0;
  std::fill(ray_floors.begin(), ray_floors.end(), 0);
}

// A launch ray whose answer is not clear (ambiguous: its legal answers run
// other traces and programs) or undefined bounds nothing.
void LaunchState::keepRayFloors() {
  if (ray_ambiguous || ray_undefined) return;
  for (size_t k = 0; k < floors.size(); ++k) floors[k] += ray_floors[k];
}

void LaunchState::markAnyHit(const HitView& hv) {
  bumpRuns(kRunsAnyHit);
  if (!rec) return;
  const uint32_t bit = 1u << anyHitSlot(hv.instance, hv.geometry, hv.primitive);
  if (rec[slots_offset_] & bit) rec[repeats_offset_] |= bit;
  rec[slots_offset_] |= bit;
}

void LaunchState::record(int idx, const Val& v, ValueType t) {
  if (!rec || idx < 0) return;
  const RecordField& f = recordFields()[idx];
  if (f.type == FieldType::Uint) {
    rec[f.offset] = t == ValueType::Float ? static_cast<uint32_t>(v.f[0]) : v.u;
  } else {
    for (uint32_t k = 0; k < f.words; ++k)
      rec[f.offset + k] = std::bit_cast<uint32_t>(
          t == ValueType::Uint && k == 0 ? static_cast<float>(v.u) : v.f[k]);
  }
  markWritten(rec, static_cast<uint32_t>(idx));
}

LaunchState::Saved LaunchState::save() const {
  Saved s{counters, {}, error, ray_floors};
  if (rec) s.record.assign(rec, rec + recordWords());
  return s;
}

void LaunchState::restore(const Saved& s) {
  counters = s.counters;
  error = s.error;
  ray_floors = s.ray_floors;
  if (rec) std::copy(s.record.begin(), s.record.end(), rec);
}

}  // namespace rayspec
