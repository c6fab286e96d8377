// The per-ray record: one fixed layout of 32-bit words, used by the device
// (the GLSL struct offsets are generated from this table, see glsl/) and by the
// model and the results reader. Its fields are the rows of
// results/record_field_table.h; this is where they are laid out.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "results/record_field_table.h"

namespace rayspec {

enum class FieldType { Uint, Float };
// The columns of results/record_field_table.h.
enum class FieldKind { Plain, HitIdentity, Free, Traversal };
enum class ToleranceKind { Exact, Field, Barycentric, Color };
enum class FieldBound { NoBound, TBound, OriginBound, PositionBound };
enum class RecordWritten { Bit, Auto };

struct RecordField {
  const char* name;  // as written in cases: record: {hit_t: ...}
  FieldType type;
  uint32_t words;   // 1..4 components
  uint32_t offset;  // word offset inside one record
  bool automatic;   // maintained by the harness, never written by `record`
  uint32_t index;   // position in recordFields(): the field's bit in the written mask
  FieldKind kind;
  const char* rule;  // the rule a mismatch points at (compare/compare_records.cpp)
  ToleranceKind tolerance;
  FieldBound bound;     // the model's per-ray bound that widens the tolerance
  const char* meaning;  // what the field holds
};

// The fields with a bit in the written mask (the table's Bit rows, first)
// and the mask's width: one word per 32 of them.
#define RAYSPEC_WRITTEN_BIT_COUNT(name, type, words, written, ...) \
  +(RecordWritten::written == RecordWritten::Bit ? 1 : 0)
constexpr uint32_t kWrittenFieldCount = 0 RAYSPEC_RECORD_FIELDS(RAYSPEC_WRITTEN_BIT_COUNT);
#undef RAYSPEC_WRITTEN_BIT_COUNT
constexpr uint32_t kWrittenMaskWords = (kWrittenFieldCount + 31) / 32;

// Words 0 .. kWrittenMaskWords - 1: bit mask of the recordable fields written
// (field index i: bit i % 32 of word i / 32). Then the recordable fields, then
// the automatic per-ray stage run counts.
const std::vector<RecordField>& recordFields();
const RecordField* findRecordField(std::string_view name);
int recordFieldIndex(std::string_view name);    // -1 when unknown
constexpr uint32_t kRecordWrittenMaskWord = 0;  // the first word of the mask
// A set of fields by index (every field, automatic ones included).
using FieldMask = uint64_t;
constexpr FieldMask fieldBit(uint32_t index) {
  return FieldMask{1} << index;
}
// A field no built-in fills: it holds what a program computes (value,
// value1 .. value11, color, color2, color3).
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
// The one formula, over numbers (the model, the judge) or over GLSL text
// (glsl/: a type whose * + & write the expression).
constexpr uint32_t kAnyHitSlotInstanceFactor = 13, kAnyHitSlotGeometryFactor = 5,
                   kAnyHitSlotMask = 31;
template <typename T>
constexpr T anyHitSlotOf(T instance, T geometry, T primitive) {
  return (instance * kAnyHitSlotInstanceFactor + geometry * kAnyHitSlotGeometryFactor + primitive) &
         kAnyHitSlotMask;
}
constexpr uint32_t anyHitSlot(uint32_t instance, uint32_t geometry, uint32_t primitive) {
  return anyHitSlotOf<uint32_t>(instance, geometry, primitive);
}

// An automatic field whose value depends on traversal order and duplicate
// invocations (any_hit_runs, intersection_runs, any_hit_slots,
// any_hit_repeats): never compared word for word with the model's.
bool traversalDependent(const RecordField& f);
// Whether a record's stages wrote the field of this index (its bit in the
// written mask); false for -1 and for the automatic fields, which have none.
bool written(const uint32_t* rec, int field_index);
// Sets the field's bit in the written mask (a recordable field's index).
void markWritten(uint32_t* rec, uint32_t field_index);
// Whether two records' stages wrote the same fields.
bool sameWrittenMask(const uint32_t* a, const uint32_t* b);

}  // namespace rayspec
