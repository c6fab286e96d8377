// What the Amber subset cannot express (export_amber.h), named.
#include <cmath>
#include <cstring>

#include "export/amber_sections.h"
#include "export/export_support.h"
#include "results/record_layout.h"
#include "spirv/compile_glsl.h"
#include "vulkan/build_layout.h"

namespace rayspec {
namespace {

std::string cannot(const std::string& construct) {
  return "export: case uses " + construct + ", which an Amber script cannot express";
}

// The build flags that change no trace's answer: PREFER_FAST_TRACE,
// PREFER_FAST_BUILD, LOW_MEMORY (Amber builds with none).
constexpr uint32_t kHintBuildFlags = 0x4 | 0x8 | 0x10;
// Byte indices up to here are exact as the float EXPECT reads (multiples of 4 up to 2^26).
constexpr uint64_t kMaxExpectIndex = uint64_t{1} << 26;
// The geometry flags GEOMETRY ... FLAGS names: OPAQUE, NO_DUPLICATE_ANY_HIT.
constexpr uint32_t kAmberGeometryFlags = 0x1 | 0x2;

// One triangle geometry as Amber lays it: float32x3 vertices, three a
// triangle, tightly packed from offset 0, no transform.
std::string triangleConstruct(const Geometry& g, const AsBuild& build) {
  if (!g.indices.empty())
    return "an index buffer (triangles.indices: Amber's GEOMETRY TRIANGLES lists three vertices "
           "a triangle)";
  if (g.transform) return "a geometry transform (triangles.transform)";
  const TriangleInputs in = layTriangles(g, build, LayoutFault::None);
  if (in.format != VertexFormat::Float3)
    return std::string("vertex format ") + vertexFormatName(in.format) +
           " (Amber's vertices are float32x3)";
  if (in.stride != 12 || in.range.primitiveOffset || in.range.firstVertex ||
      in.vertices.size() != 36u * in.range.primitiveCount)
    return "a build input layout (scene.build: offsets, strides, first_vertex)";
  return "";
}

std::string aabbConstruct(const Geometry& g, const AsBuild& build) {
  const AabbInputs in = layAabbs(g, build, LayoutFault::None);
  if (in.stride != 24 || in.range.primitiveOffset)
    return "a build input layout (scene.build: offsets, aabb_stride)";
  return "";
}

// The operations of rayspec's builds an Amber script has no command for: it
// builds each structure once, one top level, and asks nothing of it.
std::string buildConstruct(const Scene& s) {
  if (s.updates()) return "acceleration structure updates (scene.update)";
  if (s.build.copy != AsCopy::None) return "acceleration structure copies (scene.build.copy)";
  if (!s.build.queries.queries.empty())
    return "acceleration structure queries (scene.build.queries)";
  if (s.tlasCount() > 1) return "several top levels";
  for (const Blas& b : s.blases)
    if (b.geometries.empty()) return "an empty bottom level";
  return "";
}

std::string sceneConstruct(const Scene& s) {
  if (std::string k = buildConstruct(s); !k.empty()) return k;
  if (s.build.flags & ~kHintBuildFlags)
    return "build flags beyond the performance hints (scene.build.flags " +
           std::to_string(s.build.flags) + ")";
  for (const Blas& b : s.blases)
    for (const Geometry& g : b.geometries) {
      if (g.flags & ~kAmberGeometryFlags) return "geometry flags " + std::to_string(g.flags);
      const std::string k = g.kind == Geometry::Kind::Aabbs ? aabbConstruct(g, s.build)
                                                            : triangleConstruct(g, s.build);
      if (!k.empty()) return k;
    }
  for (const Instance& i : s.instances)
    if (!i.blas) return "a null instance (an instance of no bottom level)";
  return "";
}

// Amber's shader binding tables: group handles alone, one after another.
std::string sbtConstruct(const Pipeline& p, const Plan& plan) {
  if (plan.shader_record_data || !p.raygen_data.empty())
    return "shader record data (pipeline.sbt.record_data)";
  if (p.sbt_padding.miss || p.sbt_padding.hit || p.sbt_padding.callable)
    return "SBT record padding (pipeline.sbt.padding)";
  if (plan.zero_records) return "an all-zero SBT record (a record of no group)";
  for (const HitGroup& g : p.hit_groups)
    if (!g.closest_hit && !g.any_hit && !g.intersection)
      return "an empty hit group (Amber's SHADER_GROUP needs a shader)";
  return "";
}

// What the model expects, as EXPECT lines can hold it: one record a ray,
// compared word by word (the written mask whole).
std::string expectationConstruct(const Plan& plan, const Results& model) {
  if (!model.ambiguous.empty())
    return "numerically ambiguous rays (" + std::to_string(model.ambiguous.size()) +
           " with several legal answers; an EXPECT holds one value)";
  if (!model.repeat_dependent.empty())
    return "rays any-hit repetition may change (R-AHIT-DUP: the written mask may then differ, and "
           "an EXPECT compares whole words)";
  if (model.records.size() * 4 > kMaxExpectIndex)
    return "a record buffer over 64 MiB (EXPECT reads its byte index as a float)";
  for (const RecordField* f : comparedRecordFields(plan)) {
    if (f->type != FieldType::Float) continue;
    for (size_t w = f->offset; w < model.records.size(); w += recordWords())
      for (uint32_t k = 0; k < f->words; ++k) {
        float v;
        std::memcpy(&v, &model.records[w + k], 4);
        if (std::isinf(v)) return std::string("an infinite expected float (field ") + f->name + ")";
      }
  }
  return "";
}

// Whether a module reads its shader record: a pointer type of storage class
// ShaderRecordBufferKHR (Amber's records hold the group handle alone, so a
// read would reach the next record's handle).
bool readsShaderRecord(const std::vector<uint32_t>& words) {
  constexpr uint32_t kOpTypePointer = 32, kShaderRecordBuffer = 5343, kHeaderWords = 5;
  for (size_t i = kHeaderWords; i < words.size();) {
    const uint32_t count = words[i] >> 16;
    if ((words[i] & 0xFFFF) == kOpTypePointer && i + 2 < words.size() &&
        words[i + 2] == kShaderRecordBuffer)
      return true;
    i += count ? count : 1;
  }
  return false;
}

}  // namespace

std::string amberRefusal(const Case& c, const Plan& plan, const Results& model) {
  if (const std::string feature = unexportedFeature(c, plan, model); !feature.empty())
    return "export: case uses " + feature + ", not yet exported";
  if (!plan.images.empty()) return cannot("storage images (outputs.images)");
  if (c.pipeline.from_compute || c.pipeline.ray_query || c.pipeline.ray_query_in_hit ||
      plan.ray_queries)
    return cannot("ray queries (Amber requests no rayQuery feature)");
  if (std::string k = sceneConstruct(c.scene); !k.empty()) return cannot(k);
  if (std::string k = sbtConstruct(c.pipeline, plan); !k.empty()) return cannot(k);
  if (std::string k = expectationConstruct(plan, model); !k.empty()) return cannot(k);
  return "";
}

std::string amberStageRefusal(const std::vector<AmberStage>& stages) {
  for (const AmberStage& s : stages)
    if (readsShaderRecord(s.compiled->spirv))
      return cannot("a shader record read in " + s.name +
                    " (Amber's SBT records hold the group handle alone)");
  for (const AmberStage& s : stages)
    for (uint32_t capability : declaredCapabilities(s.compiled->spirv))
      if (!amberCapabilityFeature(capability))
        return cannot("SPIR-V capability " + std::to_string(capability) + " in " + s.name +
                      " (no DEVICE_FEATURE of Amber's enables it)");
  return "";
}

}  // namespace rayspec
