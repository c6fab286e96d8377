#include <algorithm>
#include <bit>

#include "compare/compare_parts.h"
#include "results/record_layout.h"
#include "results/tolerances.h"

namespace rayspec {

float asFloat(uint32_t w) { return std::bit_cast<float>(w); }

bool written(const uint32_t* rec, int field_index) {
  return field_index >= 0 && ((rec[kRecordWrittenMaskWord] >> field_index) & 1u);
}

uint32_t fieldWord(const uint32_t* rec, const char* name) { return rec[findRecordField(name)->offset]; }

float tBound(const std::map<uint32_t, float>& t_bounds, uint32_t ray) {
  const auto b = t_bounds.find(ray);
  return b == t_bounds.end() ? 0.0f : b->second;
}

bool sameField(const RecordField& f, const uint32_t* d, const uint32_t* m, float t_bound) {
  const int index = recordFieldIndex(f.name);
  if (!f.automatic && written(d, index) != written(m, index)) return false;
  if (!f.automatic && !written(d, index)) return true;
  Tolerance tol = toleranceFor(f.name);
  if (f.name == std::string("hit_t") || f.name == std::string("ray_tmax"))
    tol.abs = std::max(tol.abs, static_cast<double>(t_bound));
  for (uint32_t k = 0; k < f.words; ++k) {
    const uint32_t dw = d[f.offset + k], mw = m[f.offset + k];
    if (f.type == FieldType::Uint ? dw != mw : !tol.matches(asFloat(dw), asFloat(mw))) return false;
  }
  return true;
}

}  // namespace rayspec
