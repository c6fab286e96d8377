#include <algorithm>
#include <bit>
#include <string_view>
#include <vector>

#include "compare/compare_parts.h"
#include "results/record_layout.h"
#include "results/tolerances.h"

namespace rayspec {

float asFloat(uint32_t w) {
  return std::bit_cast<float>(w);
}

uint32_t fieldWord(const uint32_t* rec, const char* name) {
  return rec[findRecordField(name)->offset];
}

bool hitFits(const uint32_t* rec, const Candidate& k) {
  const auto fits = [&](const char* field, uint32_t want) {
    return !written(rec, recordFieldIndex(field)) || fieldWord(rec, field) == want;
  };
  return k.hit && fits("primitive_id", k.primitive) && fits("instance_id", k.instance) &&
         fits("geometry_index", k.geometry);
}

float tBound(const std::map<uint32_t, float>& t_bounds, uint32_t ray) {
  const auto b = t_bounds.find(ray);
  return b == t_bounds.end() ? 0.0f : b->second;
}

namespace {

// Each field's tolerance by field index, and which of the ray's bounds
// widens it: looked up once, not per ray.
struct FieldTolerance {
  Tolerance tol;
  RayBoundSlot slot;
};

const std::vector<FieldTolerance>& fieldTolerances() {
  static const std::vector<FieldTolerance> table = [] {
    std::vector<FieldTolerance> t;
    for (const RecordField& f : recordFields())
      t.push_back({toleranceOf(f.tolerance), boundSlotOf(f)});
    return t;
  }();
  return table;
}

}  // namespace

RayBoundSlot boundSlotOf(const RecordField& f) {
  switch (f.bound) {
    case FieldBound::TBound:
      return RayBoundSlot::T;
    case FieldBound::OriginBound:
      return RayBoundSlot::ObjectOrigin;
    case FieldBound::PositionBound:
      return RayBoundSlot::Position;
    case FieldBound::NoBound:
      break;
  }
  return f.kind == FieldKind::Free ? RayBoundSlot::Carried : RayBoundSlot::None;
}

float boundIn(const RayBounds& bounds, RayBoundSlot s) {
  switch (s) {
    case RayBoundSlot::T:
      return bounds.t;
    case RayBoundSlot::ObjectOrigin:
      return bounds.object_origin;
    case RayBoundSlot::Position:
      return bounds.position;
    case RayBoundSlot::Carried:
      return bounds.carried;
    case RayBoundSlot::None:
      break;
  }
  return 0;
}

Tolerance fieldTolerance(const RecordField& f, const RayBounds& bounds) {
  const FieldTolerance& ft = fieldTolerances()[f.index];
  Tolerance tol = ft.tol;
  tol.abs = std::max(tol.abs, static_cast<double>(boundIn(bounds, ft.slot)));
  return tol;
}

ModelRayBounds::ModelRayBounds(const Case& c, const Results& model)
    : carries_(carriesBoundedBuiltins(c)) {
  for (const TBound& b : model.t_bounds) t_[b.ray] = b.bound;
  for (const TBound& b : model.object_origin_bounds) origin_[b.ray] = b.bound;
  for (const TBound& b : model.position_bounds) position_[b.ray] = b.bound;
}

RayBounds ModelRayBounds::of(uint32_t ray) const {
  RayBounds bounds{tBound(t_, ray), tBound(origin_, ray), tBound(position_, ray)};
  if (carries_) bounds.carried = carriedBound(bounds);
  return bounds;
}

bool sameField(const RecordField& f, const uint32_t* d, const uint32_t* m,
               const RayBounds& bounds) {
  const int index = static_cast<int>(f.index);
  if (!f.automatic && written(d, index) != written(m, index)) return false;
  if (!f.automatic && !written(d, index)) return true;
  if (f.type == FieldType::Uint)  // most are one word: no memcmp call for those
    return f.words == 1 ? d[f.offset] == m[f.offset]
                        : std::equal(d + f.offset, d + f.offset + f.words, m + f.offset);
  const Tolerance tol = fieldTolerance(f, bounds);
  for (uint32_t k = 0; k < f.words; ++k)
    if (!tol.matches(asFloat(d[f.offset + k]), asFloat(m[f.offset + k]))) return false;
  return true;
}

}  // namespace rayspec
