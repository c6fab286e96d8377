#include "model/any_hit_repeat.h"

#include <algorithm>

#include "program/walk_program.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

bool writesPayloadOrRecord(const Program& p) {
  bool writes = false;
  walkStatements(p, [&writes](const Stmt& s) {
    writes = writes || s.kind == Stmt::Kind::SetPayload || s.kind == Stmt::Kind::Record;
  });
  return writes;
}

// Per ray, the judged fields whose words differ between `once` and `repeated`.
void noteDifferentFields(const std::vector<const RecordField*>& fields, const Results& repeated,
                         Results& once, std::vector<FieldMask>& masks) {
  const uint32_t words = recordWords();
  if (repeated.records.size() != once.records.size()) return;
  for (size_t ray = 0; ray < masks.size(); ++ray) {
    const uint32_t* a = &once.records[ray * words];
    const uint32_t* b = &repeated.records[ray * words];
    for (const RecordField* f : fields)
      if (!std::equal(a + f->offset, a + f->offset + f->words, b + f->offset) ||
          (!f->automatic &&
           written(a, static_cast<int>(f->index)) != written(b, static_cast<int>(f->index))))
        masks[ray] |= fieldBit(f->index);
  }
}

void noteDifferentCounters(const Results& repeated, Results& once) {
  for (const auto& [name, value] : once.counters) {
    const auto it = repeated.counters.find(name);
    if ((it == repeated.counters.end() || it->second != value) &&
        std::find(once.repeat_counters.begin(), once.repeat_counters.end(), name) ==
            once.repeat_counters.end())
      once.repeat_counters.push_back(name);
  }
}

}  // namespace

bool anyHitRepeatMayMatter(const Case& c) {
  bool without_flag = false;
  for (const Blas& b : c.scene.blases)
    for (const Geometry& g : b.geometries)
      without_flag = without_flag || !(g.flags & kGeometryNoDuplicateAnyHit);
  if (!without_flag) return false;
  for (const HitGroup& g : c.pipeline.hit_groups)
    if (g.any_hit && writesPayloadOrRecord(*g.any_hit)) return true;
  return false;
}

void findAnyHitRepeatDependence(const Case& c, const Plan& plan, const ModelOptions& opt,
                                Results& once) {
  if (!anyHitRepeatMayMatter(c)) return;
  const std::vector<const RecordField*> fields = comparedRecordFields(plan);
  std::vector<FieldMask> masks(once.records.size() / recordWords(), 0);
  for (AnyHitRepeat repeat : {AnyHitRepeat::First, AnyHitRepeat::All}) {
    ModelOptions repeating = opt;
    repeating.any_hit_repeat = repeat;
    const Results repeated = runOnModel(c, plan, repeating);
    if (!repeated.ok()) continue;
    noteDifferentFields(fields, repeated, once, masks);
    noteDifferentCounters(repeated, once);
  }
  for (size_t ray = 0; ray < masks.size(); ++ray)
    if (masks[ray]) once.repeat_dependent.push_back({static_cast<uint32_t>(ray), masks[ray]});
}

}  // namespace rayspec
