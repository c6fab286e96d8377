#include "plan/plan.h"

#include "results/record_layout.h"

#include <algorithm>

#include "case/flag_names.h"
#include "plan/walk_program.h"
#include "program/builtins.h"
#include "program/hit_object.h"
#include "program/ops.h"

namespace rayspec {
namespace {

struct StageProgram {
  Stage stage;
  const Program* program;
};

std::vector<StageProgram> allPrograms(const Pipeline& p) {
  std::vector<StageProgram> out{{Stage::Raygen, &p.raygen}};
  for (const Program& m : p.miss) out.push_back({Stage::Miss, &m});
  for (const HitGroup& g : p.hit_groups) {
    if (g.closest_hit) out.push_back({Stage::ClosestHit, &*g.closest_hit});
    if (g.any_hit) out.push_back({Stage::AnyHit, &*g.any_hit});
    if (g.intersection) out.push_back({Stage::Intersection, &*g.intersection});
  }
  for (const Program& c : p.callables) out.push_back({Stage::Callable, &c});
  return out;
}

// The ray flags a trace can use: the literal flags, or all bits when they are
// computed at run time.
uint32_t possibleFlags(const Stmt& trace, const Rays& rays) {
  if (trace.trace.flags.empty()) return 0;
  const Expr& f = trace.trace.flags.front();
  if (f.kind == Expr::Kind::Literal && !f.literal.empty())
    return static_cast<uint32_t>(f.literal[0]);
  (void)rays;
  return 0xFFFFFFFFu;
}

// The ray flags every trace may use (OR), those every trace surely uses
// (AND), and whether some trace may clear cull mask bits.
struct TraceFlags {
  uint32_t any = 0, all = 0xFFFFFFFFu;
  bool mask_bits_clear = false;
  void add(uint32_t flags, uint32_t mask) {
    any |= flags;
    all &= flags;
    if ((mask & kVisibilityMask) != kVisibilityMask) mask_bits_clear = true;
  }
};

TraceFlags traceFlags(const Case& c, const std::vector<StageProgram>& programs) {
  TraceFlags f;
  for (const Ray& r : c.rays.rays) f.add(r.flags, r.cull_mask);
  for (const auto& sp : programs)
    walkStatements(*sp.program, [&](const Stmt& s) {
      if (s.kind != Stmt::Kind::Trace && s.kind != Stmt::Kind::RayQuery &&
          s.kind != Stmt::Kind::RestartQuery)
        return;
      // Nested traces take the case defaults unless they say otherwise.
      uint32_t flags = s.trace.flags.empty()
                           ? (sp.stage == Stage::Raygen ? 0 : c.rays.defaults.flags)
                           : possibleFlags(s, c.rays);
      uint32_t mask = c.rays.defaults.cull_mask;
      if (!s.trace.cull_mask.empty()) mask = 0;  // conservatively: may clear bits
      if (sp.stage == Stage::Raygen && s.trace.flags.empty())
        return;  // the launch's rays, added above
      f.add(flags, mask);
    });
  return f;
}

// The geometry instances reach: triangles, AABBs, instance flags and masks.
// Returns whether some of it is not opaque.
bool planGeometry(const Scene& scene, Plan& plan) {
  bool non_opaque_geometry = false;
  for (const Instance& inst : scene.instances) {
    if (!inst.blas) continue;
    const Blas& b = scene.blases[*inst.blas];
    for (const Geometry& g : b.geometries) {
      if (g.primitiveCount() == 0) continue;
      if (g.kind == Geometry::Kind::Triangles)
        plan.triangles = true;
      else
        plan.aabbs = true;
      bool opaque = (g.flags & kGeometryOpaque) != 0;
      if (inst.flags & kInstanceForceOpaque) opaque = true;
      if (inst.flags & kInstanceForceNoOpaque) opaque = false;
      if (!opaque) non_opaque_geometry = true;
    }
    if (inst.flags & (kInstanceFacingCullDisable | kInstanceFlipFacing)) plan.facing_culls = true;
    if (inst.flags & (kInstanceForceOpaque | kInstanceForceNoOpaque)) plan.opacity_flags = true;
    if ((inst.mask & kVisibilityMask) != kVisibilityMask) plan.masks = true;
  }
  return non_opaque_geometry;
}

// What the ray flags and the pipeline's skip flags add or take away.
void applyRayFlags(const TraceFlags& flags, uint32_t pipeline_flags, Plan& plan) {
  if ((pipeline_flags & kPipelineSkipTriangles) || (flags.all & kRaySkipTriangles))
    plan.triangles = false;
  if ((pipeline_flags & kPipelineSkipAabbs) || (flags.all & kRaySkipAabbs)) plan.aabbs = false;
  if (flags.mask_bits_clear) plan.masks = true;
  if (flags.any & (kRayCullBackFacing | kRayCullFrontFacing)) plan.facing_culls = true;
  if (flags.any & (kRayOpaque | kRayNoOpaque | kRayCullOpaque | kRayCullNoOpaque))
    plan.opacity_flags = true;
}

// The stages that can run: closest-hit, miss, any-hit, intersection.
void planStages(const Pipeline& pipe, const TraceFlags& flags, bool non_opaque_geometry,
                Plan& plan) {
  bool group_any_hit = false, group_intersection = false;
  for (const HitGroup& g : pipe.hit_groups) {
    if (g.any_hit) group_any_hit = true;
    if (g.intersection) group_intersection = true;
    if (g.closest_hit) plan.closest_hit = true;
  }
  plan.miss = !pipe.miss.empty();
  const bool every_ray_opaque = (flags.all & kRayOpaque) != 0;
  const bool can_be_non_opaque =
      (non_opaque_geometry || (flags.any & kRayNoOpaque)) && !every_ray_opaque;
  plan.any_hit = group_any_hit && can_be_non_opaque && (plan.triangles || plan.aabbs);
  plan.intersection = group_intersection && plan.aabbs;
  // R-NULL-SHADERS: under no_null_any_hit every hit group names its any-hit
  // (VUID-VkRayTracingPipelineCreateInfoKHR-flags-03470), whether or not it can run.
  if (pipe.flags & kPipelineNoNullAnyHit) plan.any_hit = group_any_hit;
}

void noteSized(ValueType t, Plan& plan) {
  if (isSized(t)) plan.sized_types |= 1u << static_cast<int>(sizedComponent(t));
}

// The sized members the payload, callable data and hit attribute types
// declare: each stage declaring one needs its type's extension and feature,
// read or not.
void planSizedMembers(const Pipeline& pipe, Plan& plan) {
  for (const auto* all : {&pipe.payload_sized, &pipe.call_data_sized})
    for (const SizedMembers& m : *all)
      for (ValueType t : m) noteSized(t, plan);
  for (ValueType t : pipe.attribute_sized) noteSized(t, plan);
}

// What the statements do: callables, nested traces (and the depth), scene
// data read by intersection programs, the sized scalars computed with.
void planStatements(const std::vector<StageProgram>& programs, const Pipeline& pipe, Plan& plan) {
  for (const auto& sp : programs) {
    walkStatements(*sp.program, [&](const Stmt& s) {
      if (s.kind == Stmt::Kind::Call) plan.callables = true;
      if (s.kind == Stmt::Kind::Trace && sp.stage != Stage::Raygen) plan.nested_trace = true;
      if (s.kind == Stmt::Kind::RayQuery) plan.ray_queries = true;
      if (isHitObjectStatement(s)) plan.hit_objects = true;
      if (!s.trace.tlas_index.empty()) plan.dynamic_tlas_index = true;
      if (s.kind == Stmt::Kind::Array) noteSized(s.local_type, plan);
      auto& structs = plan.struct_types;
      if (s.kind == Stmt::Kind::Struct &&
          std::find(structs.begin(), structs.end(), s.params) == structs.end())
        structs.push_back(s.params);
      for (const auto& [name, type] : s.params) noteSized(type, plan);
    });
    walkExpressions(*sp.program, [&](const Expr& e) {
      const BuiltinNeeds needs =
          e.kind == Expr::Kind::Builtin ? builtinNeeds(e.builtin) : builtin_needs::NoNeeds;
      if (needs & builtin_needs::CullMask) plan.cull_mask_builtin = true;
      if (needs & builtin_needs::PositionFetch) plan.position_fetch = true;
      if ((needs & builtin_needs::HitObject) || isHitObjectRecordRead(e)) plan.hit_objects = true;
      const bool reads_box =
          (needs & builtin_needs::BoxData) || (e.kind == Expr::Kind::Op && isSphereOp(e.op));
      // In another stage, sphere_* of a ray_query's AABB candidate (program/ops.h).
      if (reads_box) plan.scene_data = true;
      noteSized(e.type, plan);
    });
  }
  plan.trace_depth = plan.nested_trace ? std::max<uint32_t>(pipe.max_recursion, 1) : 1;
}

// Shader record data and all-zero records in the SBT.
void planShaderRecords(const Pipeline& pipe, Plan& plan) {
  auto has_data = [](const std::vector<SbtRecord>& v) {
    return std::any_of(v.begin(), v.end(), [](const SbtRecord& r) { return !r.data.empty(); });
  };
  auto has_zero = [](const std::vector<SbtRecord>& v) {
    return std::any_of(v.begin(), v.end(), [](const SbtRecord& r) { return !r.group; });
  };
  plan.shader_record_data = !pipe.raygen_data.empty() || has_data(pipe.sbt_miss) ||
                            has_data(pipe.sbt_hit) || has_data(pipe.sbt_callable);
  plan.zero_records =
      has_zero(pipe.sbt_miss) || has_zero(pipe.sbt_hit) || has_zero(pipe.sbt_callable);
  // The ray query forms' inlined programs find their group and read their
  // record's data in tables (glsl/bindings.h, packSbtTables).
  plan.sbt_tables = pipe.ray_query || pipe.ray_query_in_hit;
}

// What the case keeps: counters, per-ray fields, images. Per-ray records
// (with the automatic stage run counts, which is how the comparison checks
// miss-xor-closest-hit per ray) exist when the case keeps per-ray fields or
// images; a counters-only case simulates no record at all.
void planOutputs(const Case& c, Plan& plan) {
  plan.counters = c.outputs.counters;
  plan.record_fields = c.outputs.per_ray;
  plan.images = c.outputs.images;
  plan.records = !plan.record_fields.empty() || !plan.images.empty();
}

}  // namespace

Plan derivePlan(const Case& c) {
  Plan plan;
  const std::vector<StageProgram> programs = allPrograms(c.pipeline);
  const TraceFlags flags = traceFlags(c, programs);
  const bool non_opaque_geometry = planGeometry(c.scene, plan);
  applyRayFlags(flags, c.pipeline.flags, plan);
  planStages(c.pipeline, flags, non_opaque_geometry, plan);
  planStatements(programs, c.pipeline, plan);
  planSizedMembers(c.pipeline, plan);
  planShaderRecords(c.pipeline, plan);
  planOutputs(c, plan);
  if (!c.expected_rejections.empty()) {
    // The case launches nothing (its shaders are only compiled, R-STAGE-INTERFACE):
    // no records, counters or images to read back.
    plan.records = false;
    plan.record_fields.clear();
    plan.counters.clear();
    plan.images.clear();
  }
  return plan;
}

Plan everyEffectPlan(const Case& c) {
  Plan plan = derivePlan(c);
  for (bool* flag : {&plan.triangles, &plan.aabbs, &plan.any_hit, &plan.intersection,
                     &plan.closest_hit, &plan.miss, &plan.callables, &plan.nested_trace,
                     &plan.facing_culls, &plan.masks, &plan.opacity_flags, &plan.scene_data,
                     &plan.shader_record_data, &plan.zero_records, &plan.sbt_tables, &plan.records})
    *flag = true;
  plan.record_fields.clear();
  plan.images.clear();
  for (const RecordField& f : recordFields()) {
    if (f.automatic) continue;
    plan.record_fields.push_back(f.name);
    ImageOutput im;
    im.name = std::string("all-") + f.name;
    im.field = f.name;
    plan.images.push_back(im);
  }
  return plan;
}

std::vector<std::string> Plan::describe() const {
  std::vector<std::string> lines;
  auto line = [&](bool on, const std::string& what) {
    lines.push_back(std::string(on ? "  [x] " : "  [ ] ") + what);
  };
  line(triangles, "triangle geometry (BLAS of triangles)");
  line(aabbs, "procedural geometry (BLAS of AABBs)");
  line(any_hit, "any-hit can run (filter on non-opaque candidates)");
  line(intersection, "intersection shaders (user geometry)");
  line(closest_hit, "closest-hit shaders");
  line(miss, "miss shaders");
  line(callables, "callable shaders");
  line(nested_trace, "nested traces (recursion), depth " + std::to_string(trace_depth));
  line(facing_culls, "facing culls / facing instance flags");
  line(masks, "instance masks / cull masks");
  line(opacity_flags, "opacity ray / instance flags");
  line(scene_data, "scene data buffer (AABBs read by intersection programs and query sphere_*)");
  line(shader_record_data, "shader record data");
  line(zero_records, "all-zero SBT records");
  line(sbt_tables, "SBT tables buffer (hit groups, miss programs, record data for ray queries)");
  line(cull_mask_builtin, "gl_CullMaskEXT read (VK_KHR_ray_tracing_maintenance1)");
  line(ray_queries, "ray_query statements (VK_KHR_ray_query)");
  line(hit_objects, "hit objects (VK_NV_ray_tracing_invocation_reorder)");
  line(dynamic_tlas_index, "top levels indexed dynamically (nonuniformEXT: descriptorIndexing)");
  line(position_fetch,
       "vertex positions read (gl_HitTriangleVertexPositionsEXT or a ray query's: "
       "VK_KHR_ray_tracing_position_fetch, structures "
       "built with ALLOW_DATA_ACCESS)");
  std::string sized_line;
  for (ValueType t : enumValues<ValueType>())
    if (isSizedScalar(t) && usesSized(t)) sized_line += std::string(" ") + valueTypeSpelling(t);
  if (!sized_line.empty()) lines.push_back("  sized scalars:" + sized_line);
  std::string counters_line = "counters:";
  for (const auto& c : counters) counters_line += " " + c;
  lines.push_back("  " + counters_line);
  std::string fields_line = "per-ray fields:";
  for (const auto& f : record_fields) fields_line += " " + f;
  lines.push_back("  " + fields_line + " (+ automatic stage run counts)");
  std::string images_line = "images:";
  for (const auto& i : images) images_line += " " + i.name + "(" + i.field + ")";
  lines.push_back("  " + images_line);
  return lines;
}

std::vector<const RecordField*> comparedRecordFields(const Plan& plan) {
  std::vector<const RecordField*> fields;
  for (const std::string& name : plan.record_fields)
    if (const RecordField* f = findRecordField(name)) fields.push_back(f);
  for (const RecordField& f : recordFields())
    if (f.automatic && !traversalDependent(f)) fields.push_back(&f);
  return fields;
}

}  // namespace rayspec
