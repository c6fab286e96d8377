// The per-ray record: one fixed layout of 32-bit words, used by the device
// (the GLSL struct offsets are generated from this table, see glsl/) and by the
// model and the results reader. The only place the layout is written down.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rayspec {

enum class FieldType { Uint, Float };

struct RecordField {
  const char* name;  // as written in cases: record: {hit_t: ...}
  FieldType type;
  uint32_t words;   // 1..4 components
  uint32_t offset;  // word offset inside one record
  bool automatic;   // maintained by the harness, never written by `record`
  uint32_t index;   // position in recordFields(): the field's bit in the written mask
};

// Word 0: bit mask of the recordable fields written (bit = field index).
// Then the recordable fields, then the automatic per-ray stage run counts.
const std::vector<RecordField>& recordFields();
const RecordField* findRecordField(std::string_view name);
int recordFieldIndex(std::string_view name);  // -1 when unknown
constexpr uint32_t kRecordWrittenMaskWord = 0;
// A set of fields by index (every field, automatic ones included).
using FieldMask = uint64_t;
constexpr FieldMask fieldBit(uint32_t index) {
  return FieldMask{1} << index;
}
// A field no built-in fills: it holds what a program computes (value,
// value1 .. value11, color, color2, color3). Every field a case may write has
// an index below 32: its bit in the written mask (word kRecordWrittenMaskWord).
bool isFreeField(std::string_view name);
// The fields the judge reads as the hit itself (which primitive of which
// geometry and instance, at which t: compare/record_words.cpp hitFits and
// the legal-t check): a case may record only the built-in of the same name
// there (program/check_program.cpp).
bool isHitIdentityField(std::string_view name);
uint32_t recordWords();  // words per ray

// Names of the automatic counters, in the order of the fields that hold them.
//   raygen_runs, miss_runs, closest_hit_runs, any_hit_runs,
//   intersection_runs, callable_runs
// Then two automatic bit masks of the primitives any-hit ran on (R-AHIT-DUP
// per primitive): any_hit_slots has bit anyHitSlot(instance, geometry,
// primitive) set for every primitive any-hit ran on; any_hit_repeats has it
// set when any-hit ran on a primitive whose bit was already set.
constexpr uint32_t kAnyHitSlotInstanceFactor = 13, kAnyHitSlotGeometryFactor = 5;
constexpr uint32_t anyHitSlot(uint32_t instance, uint32_t geometry, uint32_t primitive) {
  return (instance * kAnyHitSlotInstanceFactor + geometry * kAnyHitSlotGeometryFactor + primitive) &
         31u;
}

// An automatic field whose value depends on traversal order and duplicate
// invocations (any_hit_runs, intersection_runs, any_hit_slots,
// any_hit_repeats): never compared word for word with the model's.
bool traversalDependent(const RecordField& f);
// Whether a record's stages wrote the field of this index (the written-mask
// word); false for index -1.
bool written(const uint32_t* rec, int field_index);

}  // namespace rayspec
