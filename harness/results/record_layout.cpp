#include "results/record_layout.h"

#include <algorithm>
#include <string_view>
#include <unordered_map>

namespace rayspec {
namespace {

struct Row {
  const char* name;
  FieldType type;
  uint32_t words;
  RecordWritten written;
  FieldKind kind;
  const char* rule;
  ToleranceKind tolerance;
  FieldBound bound;
  const char* meaning;
};

#define RAYSPEC_RECORD_ROW(name, type, words, written, kind, rule, tolerance, bound, meaning) \
  Row{#name,                                                                                  \
      FieldType::type,                                                                        \
      words,                                                                                  \
      RecordWritten::written,                                                                 \
      FieldKind::kind,                                                                        \
      rule,                                                                                   \
      ToleranceKind::tolerance,                                                               \
      FieldBound::bound,                                                                      \
      meaning},
constexpr Row kRows[] = {RAYSPEC_RECORD_FIELDS(RAYSPEC_RECORD_ROW)};
#undef RAYSPEC_RECORD_ROW

// A field's index is its bit in the written mask: the Bit rows come first.
constexpr bool bitRowsFirst() {
  for (uint32_t i = 0; i < kWrittenFieldCount; ++i)
    if (kRows[i].written != RecordWritten::Bit) return false;
  return true;
}
static_assert(bitRowsFirst(), "record_field_table.h: every Bit row comes before the Auto rows");

std::vector<RecordField> buildFields() {
  std::vector<RecordField> fields;
  uint32_t offset = kRecordWrittenMaskWord + kWrittenMaskWords;
  for (const Row& r : kRows) {
    fields.push_back({r.name, r.type, r.words, offset, r.written == RecordWritten::Auto,
                      static_cast<uint32_t>(fields.size()), r.kind, r.rule, r.tolerance, r.bound,
                      r.meaning});
    offset += r.words;
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
  return f.kind == FieldKind::Traversal;
}

uint32_t recordWords() {
  const RecordField& last = recordFields().back();
  return last.offset + last.words;
}

bool written(const uint32_t* rec, int field_index) {
  if (field_index < 0 || static_cast<uint32_t>(field_index) >= kWrittenFieldCount) return false;
  const auto i = static_cast<uint32_t>(field_index);
  return (rec[kRecordWrittenMaskWord + i / 32] >> (i % 32)) & 1u;
}

void markWritten(uint32_t* rec, uint32_t field_index) {
  rec[kRecordWrittenMaskWord + field_index / 32] |= 1u << (field_index % 32);
}

bool sameWrittenMask(const uint32_t* a, const uint32_t* b) {
  return std::equal(a + kRecordWrittenMaskWord, a + kRecordWrittenMaskWord + kWrittenMaskWords,
                    b + kRecordWrittenMaskWord);
}

bool isFreeField(std::string_view name) {
  const RecordField* f = findRecordField(name);
  return f && f->kind == FieldKind::Free;
}

bool isHitIdentityField(std::string_view name) {
  const RecordField* f = findRecordField(name);
  return f && f->kind == FieldKind::HitIdentity;
}

}  // namespace rayspec
