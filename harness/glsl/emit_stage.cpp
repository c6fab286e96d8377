#include "glsl/emit_stage.h"

#include <algorithm>
#include <bit>

#include "glsl/bindings.h"
#include "glsl/embedded_shaders.h"
#include "glsl/emit_call_data.h"
#include "glsl/emit_compute.h"
#include "glsl/emit_control.h"
#include "glsl/emit_expr.h"
#include "glsl/emit_payloads.h"
#include "glsl/emit_ray_query.h"
#include "glsl/emit_stmt.h"
#include "glsl/glsl_writer.h"
#include "glsl/inlined_levels.h"
#include "glsl/stage_context.h"
#include "glsl/stage_prologue.h"
#include "glsl/tlas_function.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

std::string define(const std::string& name, uint32_t value) {
  return "#define " + name + " " + std::to_string(value);
}

void include(const std::string& file, GlslWriter& out) {
  const auto& shaders = embeddedShaders();
  auto it = shaders.find(file);
  out.line("");
  out.line("// ---- shaders/" + file + " ----");
  if (it == shaders.end()) {
    out.raw("#error rayspec: shaders/" + file + " is not embedded\n");
    return;
  }
  out.raw(it->second);
  if (!it->second.empty() && it->second.back() != '\n') out.raw("\n");
  out.line("// ---- end of shaders/" + file + " ----");
}

void defines(const StageContext& ctx, GlslWriter& out) {
  const StageUses& u = ctx.uses;
  const bool raygen = ctx.stage == Stage::Raygen;
  out.line("// Bindings and layouts from harness/glsl/bindings.h and results/record_layout.h.");
  out.line(define("RS_BINDING_TLAS", kBindingTlas));
  // Several top levels: rs_tlas is an array of them, indexed by constants.
  if (ctx.c.scene.tlasCount() > 1) out.line(define("RS_TLAS_COUNT", ctx.c.scene.tlasCount()));
  out.line(define("RS_BINDING_RAYS", kBindingRays));
  out.line(define("RS_BINDING_RECORDS", kBindingRecords));
  out.line(define("RS_BINDING_COUNTERS", kBindingCounters));
  out.line(define("RS_BINDING_SCENE", kBindingScene));
  out.line(define("RS_BINDING_SBT_TABLES", kBindingSbtTables));
  if (ctx.c.pipeline.empty_layout) {
    out.line("#define RS_EMPTY_LAYOUT");
    out.line(define("RS_TABLE_LO_ID", kTableLowConstantId));
    out.line(define("RS_TABLE_HI_ID", kTableHighConstantId));
  }
  out.line(define("RS_RAY_WORDS", kRayWords));
  if (!ctx.compute) {  // a compute shader's: glsl/emit_compute.h
    out.line("#define RS_LAUNCH_ID gl_LaunchIDEXT");
    out.line("#define RS_LAUNCH_SIZE gl_LaunchSizeEXT");
  }
  out.line(define("RS_RECORD_WORDS", recordWords()));
  if (ctx.plan.records)
    for (int index : u.record_fields) {
      const RecordField& f = recordFields()[index];
      out.line(define(fieldOffsetMacro(f.name), f.offset) + "u");
      out.line(define(fieldBitMacro(f.name), static_cast<uint32_t>(index)) + "u");
      // shaders/common.glsl rs_mark_written sets bit RS_BIT_<NAME> of the
      // record's first word: one written-mask word. A table of more than 32
      // Bit rows makes that (bit >> 5u, bit & 31u), which every stage's GLSL
      // then shows.
      static_assert(kWrittenMaskWords == 1, "rs_mark_written marks one written-mask word");
    }
  if (raygen && ctx.plan.records)
    for (size_t i = 0; i < ctx.plan.images.size(); ++i)
      out.line(define("RS_BINDING_IMAGE_" + std::to_string(i),
                      kBindingFirstImage + static_cast<uint32_t>(i)));
  if (raygen && u.launch_ray) out.line("#define RS_USE_RAYS");
  if (u.trace || u.ray_query) out.line("#define RS_USE_TLAS");
  if (ctx.plan.records) out.line("#define RS_USE_RECORDS");
  if (ctx.plan.records && ctx.plan.records_bound) out.line("#define RS_RECORDS_BOUND");
  if (u.counters) out.line("#define RS_USE_COUNTERS");
  if (u.shader_record && !ctx.compute) {
    // The record block holds exactly the case's data bytes (pipeline.sbt.record_data):
    // the parser keeps every read inside them.
    out.line("#define RS_USE_SHADER_RECORD");
    out.line(define("RS_SHADER_RECORD_WORDS",
                    std::max<uint32_t>(ctx.c.pipeline.sbt_record_data / 4, 1)));
  }
}

// The shader record block with the members of pipeline.sbt.record_layout, in
// its layout: the compiler places them (the model: shader_record_layout.h).
void recordMembersBlock(const StageContext& ctx, GlslWriter& out) {
  if (!ctx.uses.record_members) return;
  const ShaderRecordLayout& l = ctx.c.pipeline.record_layout;
  out.open(std::string("layout(shaderRecordEXT, ") + (l.scalar ? "scalar" : "std430") +
           ") buffer RsRecordMembers {");
  for (const RecordMember& m : l.members)
    out.line(std::string(glslType(m.type)) + " " + m.name + ";");
  out.close("} rs_members;");
}

// The stage's hit object (GL_NV_shader_invocation_reorder), global so that
// functions reach it, and its attributes as hitObjectGetAttributesNV writes
// them (hit_object.attributes: a vec2, the hit attribute's first 8 bytes).
void hitObjectVariables(const StageContext& ctx, GlslWriter& out) {
  if (!ctx.uses.hit_object) return;
  out.line("hitObjectNV rs_hit_object;");
  out.line("layout(location = 0) hitObjectAttributeNV vec2 rs_hit_object_attr;");
  // Its shader record's data (hitObjectGetShaderRecordBufferHandleNV): the
  // words hit_object_record_uint / _float read.
  if (ctx.uses.hit_object_record)
    out.line(
        "layout(buffer_reference, std430, buffer_reference_align = 4, hitobjectshaderrecordnv) "
        "buffer RsHitObjectRecord { uint words[]; };");
  out.open("vec2 rs_hit_object_attributes() {");
  out.line("hitObjectGetAttributesNV(rs_hit_object, 0);");
  out.line("return rs_hit_object_attr;");
  out.close();
}

void interfaceVariables(const StageContext& ctx, GlslWriter& out) {
  const StageUses& u = ctx.uses;
  const Stage s = ctx.stage;
  out.line("");
  out.line("// ---- interface of this stage ----");
  recordMembersBlock(ctx, out);
  emitPayloadVariables(ctx, out);
  emitCallDataVariables(ctx, out);
  if (u.hit_attribute &&
      (s == Stage::ClosestHit || s == Stage::AnyHit || s == Stage::Intersection || ctx.rejected)) {
    if (ctx.attributeStruct()) {  // pipeline.hit_attribute: 8 + 4 x words bytes, sized members
      out.open("struct RsAttr {");
      out.line("vec2 bary;");
      if (ctx.attribute_words) out.line("uint words[" + std::to_string(ctx.attribute_words) + "];");
      emitSizedMembers(ctx.attribute_sized, out);
      out.close("};");
      out.line("hitAttributeEXT RsAttr rs_attr;");
    } else {
      out.line("hitAttributeEXT vec2 rs_attr;");
    }
  }
  hitObjectVariables(ctx, out);
  if (s == Stage::Raygen && ctx.plan.records) {
    for (size_t i = 0; i < ctx.plan.images.size(); ++i) {
      const ImageOutput& img = ctx.plan.images[i];
      const RecordField* f = findRecordField(img.field);
      const bool is_float = f && f->type == FieldType::Float;
      out.line(
          "layout(set = 0, binding = RS_BINDING_IMAGE_" + std::to_string(i) + ", " +
          (is_float ? "rgba32f) uniform writeonly image2D" : "r32ui) uniform writeonly uimage2D") +
          " rs_image_" + std::to_string(i) + ";  // image \"" + img.name + "\" from " + img.field);
    }
  }
}

// Raygen, after the program: each image gets this launch's record field.
// r32ui: uvec4(word, 0, 0, 0). rgba32f: the field's float components, missing
// components 0, alpha 1 unless the field has 4 components.
void imageStores(const StageContext& ctx, GlslWriter& out) {
  if (ctx.stage != Stage::Raygen || !ctx.plan.records) return;
  for (size_t i = 0; i < ctx.plan.images.size(); ++i) {
    const ImageOutput& img = ctx.plan.images[i];
    const RecordField* f = findRecordField(img.field);
    const std::string image = "rs_image_" + std::to_string(i);
    if (!f) {
      out.raw("#error rayspec: image \"" + img.name + "\" from unknown field " + img.field + "\n");
      continue;
    }
    const std::string off = fieldOffsetMacro(f->name);
    auto word = [&](uint32_t k) {
      return "rs_record_word(" + off + ", " + std::to_string(k) + "u)";
    };
    std::string value;
    if (f->type == FieldType::Uint) {
      value = "uvec4(" + word(0) + ", 0u, 0u, 0u)";
    } else {
      value = "vec4(";
      for (uint32_t k = 0; k < 4; ++k) {
        if (k) value += ", ";
        value += k < f->words ? "uintBitsToFloat(" + word(k) + ")" : (k == 3 ? "1.0" : "0.0");
      }
      value += ")";
    }
    out.line("imageStore(" + image + ", rs_image_texel(imageSize(" + image + ").x), " + value +
             ");");
  }
}

// pipeline.constants, each with its default; the pipeline's
// VkSpecializationInfo gives a shader its pipeline.specialize values.
void specializationConstants(const StageContext& ctx, GlslWriter& out) {
  const std::vector<SpecConstant>& constants = ctx.c.pipeline.constants;
  if (constants.empty()) return;
  out.line("");
  out.line("// ---- specialization constants (pipeline.constants) ----");
  for (size_t k = 0; k < constants.size(); ++k) {
    const SpecConstant& c = constants[k];
    Expr value;
    value.type = c.type;
    value.literal = {c.value};
    out.line("layout(constant_id = " + std::to_string(k) + ") const " + glslType(c.type) + " c_" +
             c.name + " = " + emitExpr(value, ctx) + ";");
  }
}

// The 32-bit values of the constants pipeline.specialize sets for `shader`.
std::vector<std::pair<uint32_t, uint32_t>> specializationOf(const Case& c,
                                                            const std::string& shader) {
  std::vector<std::pair<uint32_t, uint32_t>> out;
  const auto it = c.pipeline.specialize.find(shader);
  if (it == c.pipeline.specialize.end()) return out;
  for (const auto& [k, v] : it->second) {
    const ValueType t = c.pipeline.constants[k].type;
    const uint32_t bits = t == ValueType::Float  ? std::bit_cast<uint32_t>(static_cast<float>(v))
                          : t == ValueType::Bool ? (v != 0 ? 1u : 0u)
                                                 : static_cast<uint32_t>(v);
    out.emplace_back(static_cast<uint32_t>(k), bits);
  }
  return out;
}

// GL_EXT_shader_explicit_arithmetic_types_*: each the case's sized scalars
// and vectors need, once (int8 and uint8 share one); GL_EXT_null_initializer
// for their arrays (declared `= {}`: OpConstantNull, glsl/emit_control.h).
void sizedTypeExtensions(const Plan& plan, GlslWriter& out) {
  std::string last;
  for (ValueType t : enumValues<ValueType>()) {
    if (!isSizedScalar(t) || !plan.usesSized(t)) continue;
    if (!*sizedType(t)->extension || sizedType(t)->extension == last) continue;  // int32: core
    last = sizedType(t)->extension;
    out.line("#extension " + last + " : require");
  }
  if (plan.sized_types) out.line("#extension GL_EXT_null_initializer : require");
}

// The #extension lines the stage's GLSL needs.
void extensions(const StageContext& ctx, bool ray_query, GlslWriter& out) {
  const StageUses& u = ctx.uses;
  if (!ctx.compute) out.line("#extension GL_EXT_ray_tracing : require");
  if (ray_query || u.ray_query) out.line("#extension GL_EXT_ray_query : require");
  // A trace's or query's dynamic top level index (glsl/emit_trace.h).
  if (ctx.c.scene.tlasCount() > 1) out.line("#extension GL_EXT_nonuniform_qualifier : require");
  // The records live behind a buffer reference (shaders/common.glsl): a large
  // launch's records may exceed maxStorageBufferRange (128 MiB on lavapipe).
  // pipeline.layout: empty reaches every buffer so (RS_EMPTY_LAYOUT).
  // The hit object's shader record is read through a uvec2 buffer reference.
  if (ctx.plan.records || ctx.c.pipeline.empty_layout || u.hit_object_record)
    out.line("#extension GL_EXT_buffer_reference : require");
  if (ctx.c.pipeline.empty_layout || u.hit_object_record)
    out.line("#extension GL_EXT_buffer_reference_uvec2 : require");
  if (u.cull_mask) out.line("#extension GL_EXT_ray_cull_mask : require");
  if (u.hit_object) out.line("#extension GL_NV_shader_invocation_reorder : require");
  if (u.position_fetch || u.query_position_fetch)
    out.line("#extension GL_EXT_spirv_intrinsics : require");
  if (u.record_members && ctx.c.pipeline.record_layout.scalar)
    out.line("#extension GL_EXT_scalar_block_layout : require");
  sizedTypeExtensions(ctx.plan, out);
}

}  // namespace

namespace {

// What the stage's GLSL is written from: the case, the plan, what the
// program uses, the prologue's fields and (raygen hosting --through
// ray-query) what its inlined stages use.
StageContext stageContext(const Case& c, const Plan& plan, Stage stage, const std::string& name,
                          const Program& program, uint32_t incoming_location, bool procedural) {
  StageContext ctx{c, plan, stage, name, findStageUses(program, stage, plan)};
  (stage == Stage::Callable ? ctx.call_data_location : ctx.payload_location) = incoming_location;
  for (const ExpectedRejection& e : c.expected_rejections)
    if (e.shader == name) ctx.rejected = true;
  if (procedural || (ctx.rejected && stage == Stage::Miss)) {
    ctx.attribute_words = c.pipeline.attribute_words;
    ctx.attribute_sized = c.pipeline.attribute_sized;
  }
  addPrologueFields(plan, stage, ctx.uses);
  ctx.compute = stage == Stage::Raygen && c.pipeline.ray_query && c.pipeline.from_compute;
  return ctx;
}

// Everything before main(): the header, the #defines, the shared pieces of
// shaders/ the stage needs, its interface, the inlined stages and the
// program's functions.
void declarations(const StageContext& ctx, bool ray_query, const Program& program,
                  GlslWriter& out) {
  const StageUses& u = ctx.uses;
  const Stage stage = ctx.stage;
  out.line("#version 460");
  extensions(ctx, ray_query, out);
  out.line("// rayspec case: " + (ctx.c.name.empty() ? std::string("(unnamed)") : ctx.c.name));
  out.line("// stage: " + std::string(stageName(stage)) + " (" + ctx.name + ")" +
           (ctx.compute ? " run as a compute shader" : "") + ", generated by harness/glsl");
  out.line("");
  if (ctx.compute) emitComputeLaunch(ctx, out);
  defines(ctx, out);
  include("common.glsl", out);
  include("payload.glsl", out);
  emitPayloadStructs(ctx, out);
  emitCallDataStructs(ctx, out);
  emitStructTypes(ctx, out);
  if (ray_query) out.line("rayQueryEXT rs_rq;  // every trace's (glsl/emit_ray_query.h)");
  // The box of an inlined intersection program's candidate, or of a ray
  // query's AABB candidate (shaders/query_sphere.glsl), as scene.glsl reads it.
  const bool candidates = ray_query || u.query_sphere;
  if (u.scene && candidates) emitCandidateMacros(out);
  if (u.scene && (stage == Stage::Intersection || candidates)) include("scene.glsl", out);
  if (u.sphere && (stage == Stage::Intersection || candidates)) include("sphere.glsl", out);
  if (u.query_sphere) include("query_sphere.glsl", out);
  if (u.light) include("lights.glsl", out);
  if (u.position_fetch) include("position_fetch.glsl", out);
  if (u.query_position_fetch) include("query_position_fetch.glsl", out);
  if (ctx.compute) emitComputeShaderRecord(ctx, out);
  interfaceVariables(ctx, out);
  specializationConstants(ctx, out);
  // Raygen's launch ray is global: a function's trace may take its fields.
  if (stage == Stage::Raygen && u.launch_ray) out.line("RsRay rs_ray;");
  emitTlasFunctions(ctx, out);  // before anything that traces or queries
  if (ray_query) emitInlinedStages(ctx, out);
  emitFunctions(program, ctx, out);
}

// main(): the prologue, the launch ray, the payload and call data, the
// program, and raygen's image stores.
void mainFunction(const StageContext& ctx, const Program& program, GlslWriter& out) {
  const Stage stage = ctx.stage;
  out.line("");
  out.open("void main() {");
  if (ctx.compute) emitComputeLaunchId(ctx, out);
  emitStagePrologue(ctx, {"uint(gl_InstanceID)", "gl_GeometryIndexEXT", "uint(gl_PrimitiveID)"},
                    out);
  // rays.same: one ray in the buffer, which every launch id traces.
  if (stage == Stage::Raygen && ctx.uses.launch_ray)
    out.line(ctx.c.rays.same ? "rs_ray = rs_load_ray(0u);"
                             : "rs_ray = rs_load_ray(rs_launch_index());");
  emitPayloadStart(ctx, out);
  emitCallDataStart(ctx, out);
  if (ctx.uses.hit_object) out.line("hitObjectRecordEmptyNV(rs_hit_object);");
  out.line("// ---- program ----");
  emitProgram(program, ctx, out);
  if (stage == Stage::Raygen && !ctx.plan.images.empty()) {
    out.line("// ---- images ----");
    imageStores(ctx, out);
  }
  out.close();
}

}  // namespace

GeneratedShader emitStage(const Case& c, const Plan& plan, Stage stage, const std::string& name,
                          const Program& program, uint32_t incoming_location, bool procedural) {
  StageContext ctx = stageContext(c, plan, stage, name, program, incoming_location, procedural);
  const bool ray_query = hostsInlinedStages(c, stage, ctx.uses);
  if (ray_query) addInlinedUses(ctx);
  GlslWriter out;
  declarations(ctx, ray_query, program, out);
  mainFunction(ctx, program, out);
  return {stage, name, out.text(), specializationOf(c, name), ctx.compute};
}

}  // namespace rayspec
