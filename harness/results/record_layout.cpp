#include "results/record_layout.h"

#include <set>
#include <string_view>
#include <unordered_map>

namespace rayspec {
namespace {

std::vector<RecordField> buildFields() {
  struct Decl {
    const char* name;
    FieldType type;
    uint32_t words;
    bool automatic;
  };
  const Decl decls[] = {
      {"hit", FieldType::Uint, 1, false},
      {"instance_id", FieldType::Uint, 1, false},
      {"instance_custom_index", FieldType::Uint, 1, false},
      {"geometry_index", FieldType::Uint, 1, false},
      {"primitive_id", FieldType::Uint, 1, false},
      {"hit_kind", FieldType::Uint, 1, false},
      {"hit_t", FieldType::Float, 1, false},
      {"barycentrics", FieldType::Float, 2, false},
      {"ray_tmin", FieldType::Float, 1, false},
      {"ray_tmax", FieldType::Float, 1, false},
      {"incoming_ray_flags", FieldType::Uint, 1, false},
      {"world_ray_origin", FieldType::Float, 3, false},
      {"world_ray_direction", FieldType::Float, 3, false},
      {"object_ray_origin", FieldType::Float, 3, false},
      {"object_ray_direction", FieldType::Float, 3, false},
      {"hit_position", FieldType::Float, 3, false},
      {"depth", FieldType::Uint, 1, false},
      {"value", FieldType::Uint, 1, false},
      {"color", FieldType::Float, 4, false},
      {"color2", FieldType::Float, 4, false},
      {"value1", FieldType::Uint, 1, false},
      {"value2", FieldType::Uint, 1, false},
      {"value3", FieldType::Uint, 1, false},
      {"value4", FieldType::Uint, 1, false},
      {"value5", FieldType::Uint, 1, false},
      {"value6", FieldType::Uint, 1, false},
      {"value7", FieldType::Uint, 1, false},
      // Free fields beyond value7 and color2 (issue 43: loops folded their
      // results into single numbers). The written mask is one word: every
      // field a case writes has an index below 32 (record_layout.h).
      {"value8", FieldType::Uint, 1, false},
      {"value9", FieldType::Uint, 1, false},
      {"value10", FieldType::Uint, 1, false},
      {"value11", FieldType::Uint, 1, false},
      {"color3", FieldType::Float, 4, false},
      {"raygen_runs", FieldType::Uint, 1, true},
      {"miss_runs", FieldType::Uint, 1, true},
      {"closest_hit_runs", FieldType::Uint, 1, true},
      {"any_hit_runs", FieldType::Uint, 1, true},
      {"intersection_runs", FieldType::Uint, 1, true},
      {"callable_runs", FieldType::Uint, 1, true},
      {"any_hit_slots", FieldType::Uint, 1, true},
      {"any_hit_repeats", FieldType::Uint, 1, true},
  };
  std::vector<RecordField> fields;
  uint32_t offset = kRecordWrittenMaskWord + 1;
  for (const Decl& d : decls) {
    fields.push_back(
        {d.name, d.type, d.words, offset, d.automatic, static_cast<uint32_t>(fields.size())});
    offset += d.words;
  }
  return fields;
}

}  // namespace

const std::vector<RecordField>& recordFields() {
  static const std::vector<RecordField> fields = buildFields();
  return fields;
}

// By name through a hash table: the comparison asks per ray.
const RecordField* findRecordField(std::string_view name) {
  static const std::unordered_map<std::string_view, const RecordField*> by_name = [] {
    std::unordered_map<std::string_view, const RecordField*> m;
    for (const RecordField& f : recordFields()) m.emplace(f.name, &f);
    return m;
  }();
  const auto it = by_name.find(name);
  return it == by_name.end() ? nullptr : it->second;
}

int recordFieldIndex(std::string_view name) {
  const RecordField* f = findRecordField(name);
  return f ? static_cast<int>(f->index) : -1;
}

bool traversalDependent(const RecordField& f) {
  const std::string_view n = f.name;
  return n == "any_hit_runs" || n == "intersection_runs" || n == "any_hit_slots" ||
         n == "any_hit_repeats";
}

uint32_t recordWords() {
  const RecordField& last = recordFields().back();
  return last.offset + last.words;
}

bool written(const uint32_t* rec, int field_index) {
  return field_index >= 0 && field_index < 32 &&
         ((rec[kRecordWrittenMaskWord] >> field_index) & 1u);
}

bool isFreeField(std::string_view name) {
  static const std::set<std::string_view> kFree = {
      "value",  "value1", "value2",  "value3",  "value4", "value5", "value6", "value7",
      "value8", "value9", "value10", "value11", "color",  "color2", "color3"};
  return kFree.count(name) > 0;
}

bool isHitIdentityField(std::string_view name) {
  return name == "primitive_id" || name == "instance_id" || name == "geometry_index" ||
         name == "hit_t";
}

}  // namespace rayspec
