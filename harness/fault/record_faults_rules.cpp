// Record edits of the values stages read: built-ins, hit kinds, ids, tmax.
#include <cmath>
#include <functional>

#include "fault/fault_impl.h"
#include "program/builtins.h"
#include "program/ops.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

bool readsBuiltin(const Expr& e, const std::function<bool(Builtin)>& pred) {
  if (e.kind == Expr::Kind::Builtin && pred(e.builtin)) return true;
  for (const Expr& a : e.args)
    if (readsBuiltin(a, pred)) return true;
  return false;
}

// The case records `field` straight from the built-in of the same name.
bool recordsOwnBuiltin(const Case& c, const std::string& field) {
  for (const FieldWrite& w : fieldWrites(c))
    if (w.field == field && isBuiltin(*w.value, builtinId(findBuiltin(field)))) return true;
  return false;
}

bool hitStage(Stage s) {
  return s == Stage::Intersection || s == Stage::AnyHit || s == Stage::ClosestHit;
}

// Values carried between stages, not built-ins of the API.
bool isApiBuiltin(Builtin b) {
  return !(builtinNeeds(b) & builtin_needs::CarriedData) && b != kBiHit && b != kBiDepth;
}

bool inactiveTriangle(const Geometry& g, uint32_t p) {
  for (uint32_t v = 0; v < 3; ++v) {
    const uint32_t i = g.indices.empty() ? p * 3 + v : g.indices[p * 3 + v];
    if (i < g.vertices.size() && std::isnan(g.vertices[i][0])) return true;
  }
  return false;
}

// R-INACTIVE: primitives of the geometry before p that are inactive.
uint32_t inactiveBefore(const Geometry& g, uint32_t p) {
  uint32_t n = 0;
  for (uint32_t q = 0; q < p && q < g.primitiveCount(); ++q)
    n += g.kind == Geometry::Kind::Aabbs ? std::isnan(g.aabbs[q][0]) : inactiveTriangle(g, q);
  return n;
}

// The geometry of a hit ray: instance and geometry index as recorded, else
// the first one with an inactive primitive.
const Geometry* hitGeometry(const Case& c, const RecordView& v, uint32_t ray) {
  const auto& insts = c.scene.instances;
  auto with_inactive = [&](const Geometry& g) {
    return inactiveBefore(g, g.primitiveCount()) > 0;
  };
  const Blas* blas = nullptr;
  if (v.written(ray, "instance_id")) {
    const uint32_t i = v.get(ray, "instance_id");
    if (i < insts.size() && insts[i].blas) blas = &c.scene.blases[*insts[i].blas];
  } else {
    for (const Instance& inst : insts)
      if (!blas && inst.blas)
        for (const Geometry& g : c.scene.blases[*inst.blas].geometries)
          if (with_inactive(g)) blas = &c.scene.blases[*inst.blas];
  }
  if (!blas) return nullptr;
  if (v.written(ray, "geometry_index")) {
    const uint32_t gi = v.get(ray, "geometry_index");
    return gi < blas->geometries.size() ? &blas->geometries[gi] : nullptr;
  }
  for (const Geometry& g : blas->geometries)
    if (with_inactive(g)) return &g;
  return nullptr;
}

}  // namespace

FaultResult hitKindFlipped(RecordFaultArgs& a) {
  uint32_t edited = 0, first = 0;
  for (uint32_t ray = 0; ray < a.dev.rays(); ++ray) {
    if (a.ambiguous.count(ray) || !a.dev.written(ray, "hit_kind")) continue;
    const uint32_t k = a.dev.get(ray, "hit_kind");
    if (k != 0xFE && k != 0xFF) continue;
    a.dev.set(ray, "hit_kind", k ^ 1u);
    if (!edited++) first = ray;
  }
  if (!edited) return notApplicable("no clear ray recorded a triangle hit kind");
  return describeRay(first,
                     "hit kind flipped (and on " + std::to_string(edited - 1) + " more rays)");
}

FaultResult inactiveRenumbered(RecordFaultArgs& a) {
  const Case& c = a.c;
  const bool prims = recordsOwnBuiltin(c, "primitive_id"),
             insts = recordsOwnBuiltin(c, "instance_id");
  uint32_t edited = 0, first = 0;
  for (uint32_t ray = 0; ray < a.dev.rays(); ++ray) {
    if (a.ambiguous.count(ray) || a.dev.get(ray, "closest_hit_runs") == 0) continue;
    bool changed = false;
    if (insts && a.dev.written(ray, "instance_id")) {
      const uint32_t i = a.mod.get(ray, "instance_id");
      uint32_t nulls = 0;
      for (uint32_t j = 0; j < i && j < c.scene.instances.size(); ++j)
        nulls += !c.scene.instances[j].blas;
      if (nulls) a.dev.set(ray, "instance_id", i - nulls);
      changed = nulls > 0;
    }
    if (prims && a.dev.written(ray, "primitive_id")) {
      const Geometry* g = hitGeometry(c, a.mod, ray);
      const uint32_t p = a.mod.get(ray, "primitive_id");
      const uint32_t n = g ? inactiveBefore(*g, p) : 0;
      if (n) a.dev.set(ray, "primitive_id", p - n);
      changed = changed || n > 0;
    }
    if (changed && !edited++) first = ray;
  }
  if (!edited)
    return notApplicable(
        "no clear hit ray records an id after an inactive primitive or null instance");
  return describeRay(first, "ids counted without the inactive ones (and on " +
                                std::to_string(edited - 1) + " more rays)");
}

FaultResult tmaxViewInitial(RecordFaultArgs& a) {
  const Case& c = a.c;
  // Where hit stages record gl_RayTmaxEXT: the field and its component.
  std::vector<std::pair<std::string, uint32_t>> slots;
  for (const FieldWrite& w : fieldWrites(c)) {
    if (!hitStage(w.stage)) continue;
    const Expr& e = *w.value;
    if (isBuiltin(e, kBiTmax)) slots.push_back({w.field, 0});
    if (e.kind == Expr::Kind::Op && isVectorConstructor(e.op))
      for (size_t j = 0; j < e.args.size(); ++j)
        if (isBuiltin(e.args[j], kBiTmax) &&
            e.args.size() == static_cast<size_t>(componentCount(e.type)))
          slots.push_back({w.field, static_cast<uint32_t>(j)});
  }
  if (slots.empty()) return notApplicable("no hit stage records gl_RayTmaxEXT");
  // The tmax raygen's trace starts with: the launch ray's, or a literal.
  std::optional<float> literal;
  for (const Stmt& s : c.pipeline.raygen)
    if (s.kind == Stmt::Kind::Trace && !s.trace.tmax.empty()) {
      const Expr& t = s.trace.tmax.front();
      if (t.kind != Expr::Kind::Literal) return notApplicable("raygen traces with a computed tmax");
      literal = static_cast<float>(t.literal[0]);
    }
  uint32_t edited = 0, first = 0;
  for (uint32_t ray = 0; ray < a.dev.rays(); ++ray) {
    if (a.ambiguous.count(ray) || a.dev.get(ray, "closest_hit_runs") == 0) continue;
    const float initial = literal ? *literal : c.rays.launchRay(ray).tmax;
    bool changed = false;
    for (const auto& [field, k] : slots) {
      if (!a.dev.written(ray, field) || a.dev.getFloat(ray, field, k) == initial) continue;
      a.dev.setFloat(ray, field, initial, k);
      changed = true;
    }
    if (changed && !edited++) first = ray;
  }
  if (!edited) return notApplicable("no clear hit ray recorded a tmax other than the trace's");
  return describeRay(first, "gl_RayTmaxEXT read as the trace's tmax (and on " +
                                std::to_string(edited - 1) + " more rays)");
}

// R-INDIRECT: a device that reads the launch height of an indirect trace
// as one less: the last row of the launch never runs raygen.
FaultResult indirectLaunchShort(RecordFaultArgs& a) {
  if (a.c.rays.command == TraceCommand::Direct)
    return notApplicable("the case traces with vkCmdTraceRaysKHR, not an indirect command");
  const uint32_t width = a.c.rays.width, height = a.c.rays.height;
  if (height < 2) return notApplicable("a one-row launch has no row to lose");
  for (uint32_t x = 0; x < width; ++x) a.dev.set((height - 1) * width + x, "raygen_runs", 0);
  return {true, "the launch ran " + std::to_string(width) + " x " + std::to_string(height - 1) +
                    ": raygen_runs 0 on row " + std::to_string(height - 1)};
}

namespace {

// A launch of ids all alike (rays.same, and no per-ray record to tell them
// apart): each counter a multiple of the ids moves by `ids_moved` ids' share
// of it (negative: those ids never ran); the counters moved, by name.
std::string moveUniformCounters(RecordFaultArgs& a, int64_t ids_moved) {
  const uint64_t ids = a.c.rays.launchRays();
  std::string moved;
  for (auto& [name, count] : a.dev.w.counters) {
    if (count == 0 || count % ids != 0) continue;
    count = static_cast<uint64_t>(static_cast<int64_t>(count) +
                                  ids_moved * static_cast<int64_t>(count / ids));
    moved += (moved.empty() ? "" : ", ") + name;
  }
  return moved;
}

bool uniformCountersOnly(const Case& c) {
  return c.rays.same && c.outputs.per_ray.empty() && c.rays.launchRays() != 0;
}

// R-LAUNCH-3D: a launch of ids all alike whose last row of ids (y = height -
// 1, each z) runs `times` more times (1: twice, -1: never).
FaultResult lastRowRuns(RecordFaultArgs& a, int64_t times) {
  const std::array<uint32_t, 3> size = a.c.rays.launchSize();
  if (!uniformCountersOnly(a.c) || size[1] < 2)
    return notApplicable("not a rays.same launch of counters only with rows to tell apart");
  const uint64_t row = uint64_t{size[0]} * size[2];
  const std::string moved = moveUniformCounters(a, times * static_cast<int64_t>(row));
  if (moved.empty()) return notApplicable("no counter counts every id alike");
  return {true, std::string("the last row of ") + std::to_string(row) + " ids ran " +
                    (times > 0 ? "twice" : "never") + ": counters " + moved + " moved"};
}

// launchDepthLost for a launch of ids all alike: the counters of the layers
// beyond the first are lost.
FaultResult uniformDepthLost(RecordFaultArgs& a, uint64_t layer) {
  const uint64_t lost = a.c.rays.launchRays() - layer;
  const std::string moved = moveUniformCounters(a, -static_cast<int64_t>(lost));
  if (moved.empty()) return notApplicable("no counter counts every id alike");
  return {true, "the launch ran its first z layer of " + std::to_string(layer) + " ids, not " +
                    std::to_string(lost) + " more: counters " + moved + " moved"};
}

}  // namespace

// R-LAUNCH-3D: a device that launches only the first z layer of a 3D
// launch: raygen never runs for z >= 1.
FaultResult launchDepthLost(RecordFaultArgs& a) {
  const std::array<uint32_t, 3> launch = a.c.rays.launchSize();
  const uint32_t layer = launch[0] * launch[1];
  if (launch[2] >= 2 && uniformCountersOnly(a.c)) return uniformDepthLost(a, layer);
  if (launch[2] < 2 || a.c.rays.rays.empty())
    return notApplicable("the launch has one z layer (rays.launch)");
  for (uint32_t ray = layer; ray < a.dev.rays(); ++ray) a.dev.set(ray, "raygen_runs", 0);
  return {true, "the launch ran " + std::to_string(launch[0]) + " x " + std::to_string(launch[1]) +
                    " x 1 of " + std::to_string(launch[2]) + " layers: raygen_runs 0 on " +
                    std::to_string(a.dev.rays() - layer) + " rays"};
}

// R-LAUNCH-3D: a device that runs a launch with a zero dimension as one
// invocation: raygen's first counter counts 1.
FaultResult zeroLaunchRuns(RecordFaultArgs& a) {
  if (!a.c.rays.rays.empty()) return notApplicable("the launch has rays");
  const std::string counter = a.dev.bumpCounter(
      countersIn(a.c,
                 [&](const std::function<void(const Program&)>& f) { f(a.c.pipeline.raygen); }),
      1);
  if (counter.empty()) return notApplicable("raygen counts nothing");
  return {true, "the zero-sized launch ran raygen once: counter '" + counter + "' + 1"};
}

FaultResult launchRowRepeated(RecordFaultArgs& a) {
  return lastRowRuns(a, 1);
}

FaultResult launchRowLost(RecordFaultArgs& a) {
  return lastRowRuns(a, -1);
}

FaultResult builtinWrong(RecordFaultArgs& a) {
  const std::vector<FieldWrite> writes = fieldWrites(a.c);
  for (const std::string& field : a.c.outputs.per_ray) {
    bool from_builtin = false;
    for (const FieldWrite& w : writes)
      from_builtin = from_builtin || (w.field == field && readsBuiltin(*w.value, isApiBuiltin));
    const RecordField* f = findRecordField(field);
    if (!from_builtin || !f) continue;
    for (uint32_t ray = 0; ray < a.dev.rays(); ++ray) {
      if (a.ambiguous.count(ray) || !a.dev.written(ray, field)) continue;
      if (f->type == FieldType::Uint) {
        const uint32_t v = a.dev.get(ray, field);
        a.dev.set(ray, field, v + 1);
        return describeRay(ray, field + " " + std::to_string(v) + " -> " + std::to_string(v + 1));
      }
      const float v = a.dev.getFloat(ray, field);
      a.dev.setFloat(ray, field, v + 1.0f);
      return describeRay(ray,
                         field + "[0] " + std::to_string(v) + " -> " + std::to_string(v + 1.0f));
    }
  }
  return notApplicable("no clear ray records a field computed from a built-in");
}

}  // namespace rayspec

namespace rayspec {

FaultResult plantDeviceFinding(RecordFaultArgs& a, DeviceFinding finding, std::string what) {
  a.dev.w.device_findings.push_back(std::move(finding));
  return {true, std::move(what)};
}

// R-LIBRARY with VK_EXT_pipeline_library_group_handles: a device whose group
// handle read from a library differs from the same group's handle in the
// linked pipeline (the check vulkan/library_group_handles.h makes).
FaultResult libraryHandleDiffers(RecordFaultArgs& a) {
  if (a.c.pipeline.libraries.empty()) return notApplicable("the case links no pipeline library");
  return plantDeviceFinding(
      a,
      {"R-LIBRARY",
       "group 1 (library group 0): its handle read from the library differs from its handle in "
       "the linked pipeline (planted)"},
      "a library group's handle differs from the linked pipeline's");
}

// R-AS-MEMORY: a device whose build wrote past the size it reported, as the
// guards after each structure (vulkan/memory_guards.h) find it.
FaultResult memoryGuardOverwritten(RecordFaultArgs& a) {
  if (a.c.scene.instances.empty()) return notApplicable("the case builds no structure");
  return plantDeviceFinding(a,
                            {"R-AS-MEMORY",
                             "BLAS 0, its accelerationStructureSize: 4 of the 256 guard bytes "
                             "after it changed (planted)"},
                            "a build wrote past the size the device reported");
}

}  // namespace rayspec
