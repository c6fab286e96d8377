// Hit objects (GL_NV_shader_invocation_reorder) broken as a faulty device
// would break them, each on the model's test-only hook (model/model_faults.h):
// closest-hit or miss run at hitObjectTraceRayNV (R-HIT-OBJECT-DEFERRED),
// one family of the getters reading wrong each (R-HIT-OBJECT), a hit
// recorded by hand or the shader record handle wrong (R-HIT-OBJECT-RECORD).
// A case that has none of what a fault breaks is not applicable.
#include <optional>

#include "fault/fault_impl.h"
#include "fault/program_edit.h"
#include "program/builtins.h"
#include "program/hit_object.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

// Reads of the built-ins in [first, last] anywhere in the pipeline.
size_t readsOf(const Case& c, int first, int last) {
  size_t reads = 0;
  forEachProgram(c.pipeline, [&](const Program& p, Stage) {
    walkExpressions(p, [&](const Expr& e) {
      reads += e.kind == Expr::Kind::Builtin && e.builtin >= first && e.builtin <= last;
    });
  });
  return reads;
}

std::string getterFault(Case& c, ModelOptions& o, HitObjectGetterFault family, int first, int last,
                        const std::string& what) {
  const size_t reads = readsOf(c, first, last);
  if (!reads) return "";
  o.faults.hit_object_getter = family;
  return describeCount(reads, what);
}

// record_hit statements by their SBT record index (`by_index`: size 1) or
// either form (nullopt).
size_t recordHits(const Case& c, std::optional<bool> by_index) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](const Program& p, Stage) {
    walkStatements(p, [&](const Stmt& s) {
      n += s.kind == Stmt::Kind::RecordHit && (!by_index || (s.size == 1) == *by_index);
    });
  });
  return n;
}

std::string recordFault(ModelOptions& o, HitObjectRecordFault f, size_t sites,
                        const std::string& what) {
  if (!sites) return "";
  o.faults.hit_object_record = f;
  return describeCount(sites, what);
}

}  // namespace

std::string hitObjectRecordSbtNoInstanceOffset(Case& c, ModelOptions& o) {
  return recordFault(o, HitObjectRecordFault::SbtNoInstanceOffset, recordHits(c, false),
                     "hits recorded by SBT offset and stride whose record leaves out the "
                     "instance's SBT offset");
}

std::string hitObjectRecordIndexPlusInstanceOffset(Case& c, ModelOptions& o) {
  return recordFault(o, HitObjectRecordFault::IndexPlusInstanceOffset, recordHits(c, true),
                     "hits recorded by SBT record index whose record adds the instance's SBT "
                     "offset");
}

std::string hitObjectRecordCustomIndexIsId(Case& c, ModelOptions& o) {
  return recordFault(o, HitObjectRecordFault::CustomIndexIsId, recordHits(c, std::nullopt),
                     "recorded hits whose custom index is their instance id");
}

std::string hitObjectRecordHandleOwn(Case& c, ModelOptions& o) {
  size_t reads = 0;
  forEachProgram(c.pipeline, [&](const Program& p, Stage) {
    walkExpressions(p, [&](const Expr& e) { reads += isHitObjectRecordRead(e); });
  });
  return recordFault(o, HitObjectRecordFault::HandleOwn, reads,
                     "reads of the hit object's shader record that read the stage's own");
}

std::string hitObjectTraceShades(Case& c, ModelOptions& o) {
  size_t traces = 0;
  forEachProgram(c.pipeline, [&](const Program& p, Stage) {
    walkStatements(
        p, [&](const Stmt& s) { traces += s.kind == Stmt::Kind::Trace && s.trace.hit_object; });
  });
  if (!traces) return "";
  o.faults.hit_object_trace_shades = true;
  return describeCount(traces, "traces into a hit object that run closest-hit or miss at once");
}

std::string hitObjectStateWrong(Case& c, ModelOptions& o) {
  return getterFault(c, o, HitObjectGetterFault::StateWrong, kBiHoIsMiss, kBiHoIsEmpty,
                     "reads of hit_object.is_miss / is_empty that read the other");
}

std::string hitObjectIdsSwapped(Case& c, ModelOptions& o) {
  return getterFault(c, o, HitObjectGetterFault::IdsSwapped, kBiHoInstance, kBiHoHitKind,
                     "reads of the hit object's ids that read another id (hit kind: the "
                     "other face's)");
}

std::string hitObjectTInitial(Case& c, ModelOptions& o) {
  return getterFault(c, o, HitObjectGetterFault::TInitial, kBiHoT, kBiHoT,
                     "reads of hit_object.t that read the trace's tmax");
}

std::string hitObjectObjectRayWorld(Case& c, ModelOptions& o) {
  return getterFault(c, o, HitObjectGetterFault::ObjectRayWorld, kBiHoObjectOrigin,
                     kBiHoObjectDirection,
                     "reads of the hit object's object ray that read the world ray");
}

std::string hitObjectMatricesSwapped(Case& c, ModelOptions& o) {
  return getterFault(c, o, HitObjectGetterFault::MatricesSwapped, kBiHoObjectToWorld0,
                     kBiHoWorldToObject3, "reads of the hit object's matrices that read the other");
}

std::string hitObjectAttributesLost(Case& c, ModelOptions& o) {
  return getterFault(c, o, HitObjectGetterFault::AttributesLost, kBiHoAttributes, kBiHoAttributes,
                     "reads of hit_object.attributes that read zero");
}

std::string hitObjectSbtIndexOfInstance(Case& c, ModelOptions& o) {
  return getterFault(c, o, HitObjectGetterFault::SbtIndexOfInstance, kBiHoSbtIndex, kBiHoSbtIndex,
                     "reads of hit_object.sbt_record_index that read the instance's offset alone");
}

}  // namespace rayspec
