/* rayspec export of case lavapipe-rejected-report-attribute (references/driver-reports/lavapipe-rejected-report-attribute.yaml)
 * Rules it checks: R-PAYLOAD, R-ISECT-REPORT, R-ORDER-UNSPEC
 * A standalone reproducer: the case's scene, pipeline (SPIR-V, with the GLSL it was
 * compiled from in comments), shader binding table and rays, traced on a Vulkan
 * device, and each result compared with what rayspec's reference model expects.
 *
 * Build: cc repro.c -lvulkan -o repro   (add -DRAYSPEC_VALIDATION for the
 *        validation layer, when installed)
 * Run:   ./repro [DEVICE]   (DEVICE: an index, or a part of the device's name;
 *        default: the first device with VK_KHR_ray_tracing_pipeline)
 * Exit:  0 PASS; 0 too for a QualityWarning, as rayspec (a "should" broken, no
 *        failure: a ray on a shared edge or vertex that leaked or hit twice,
 *        R-WATERTIGHT), a WARNING line per ray (the first 8) and a last line
 *        starting "QualityWarning:" where PASS would stand; 1 FAIL, printing the
 *        rule, the ray, the field, the expected and the observed value;
 *        77 NotSupported, naming the missing feature; 2 a Vulkan call failed.
 */
/* The fixed part of a `rayspec export --format c` reproducer: a generic
 * player of one case, the case's data spliced in by rayspec (export_c.cpp)
 * where the marker line below stands. It creates an instance and a device,
 * builds the bottom levels and the top level from the embedded inputs,
 * creates the ray tracing pipeline from the embedded SPIR-V, writes the
 * shader binding table with the device's handles, binds the buffers, traces,
 * reads the per-ray records and counters back and compares them with the
 * reference model's expectations, embedded. Exit status: 0 PASS, or a
 * QualityWarning (a last line "QualityWarning: ...": R-WATERTIGHT broken, a
 * "should", as rayspec exits 0 on it), 1 FAIL (each wrong value: rule, ray,
 * field, expected, observed), 77 NotSupported (the missing feature named),
 * 2 a Vulkan error.
 * The player is the files of harness/export/player/ joined, in the order
 * parts.cmake lists them, by tools/embed_player.cmake: this one (the types
 * of the case's data, and the marker), then one file a step; they are
 * compiled only as that one file, an exported reproducer (C99, the Vulkan
 * loader and libc). */
#include <math.h> /* NAN, INFINITY in the data (macros: no -lm) */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vulkan/vulkan.h>

#define RS_NONE 0xFFFFFFFFu

typedef struct {
  VkShaderStageFlagBits stage;
  const uint32_t* code;
  size_t bytes;
} rs_shader;
typedef struct {
  VkRayTracingShaderGroupTypeKHR type;
  uint32_t general, closest_hit, any_hit, intersection; /* shader indices or RS_NONE */
} rs_group;
typedef struct {
  /* Triangles, or AABBs: then `vertices` holds the boxes (VkAabbPositionsKHR,
     `stride` apart) and the format and index fields are unused. */
  VkGeometryTypeKHR type;
  VkFormat format;
  const char* format_name; /* the case's name of it (triangles.vertex_format) */
  uint32_t stride, max_vertex;
  VkIndexType index_type;
  VkGeometryFlagsKHR flags;
  const uint8_t *vertices, *indices, *transform;
  size_t vertex_bytes, index_bytes, transform_bytes;
  VkAccelerationStructureBuildRangeInfoKHR range;
} rs_geometry;
typedef struct {
  uint32_t first_geometry, geometry_count;
  uint32_t reached; /* some instance of the scene as first built references it: built */
} rs_blas;
typedef struct {
  float transform[12];
  uint32_t custom_index, mask, sbt_offset, flags, blas; /* blas: RS_NONE for none */
  uint32_t tlas;                                        /* the top level it belongs to */
} rs_instance;
/* scene.build.copy: the structures the traces use are copies (R-AS-COPY). */
enum rs_copy { RS_COPY_NONE, RS_COPY_CLONE, RS_COPY_COMPACT, RS_COPY_SERIALIZE };
typedef struct {
  uint32_t group; /* RS_NONE: an all-zero record */
  uint32_t data_words;
  uint32_t data[8];
} rs_record;
/* RS_BIND_WORDS: a read-only buffer of fixed words (the scene data of
   intersection programs, the SBT as tables). RS_BIND_IMAGE: a storage image
   (outputs.images), image binding - RS_FIRST_IMAGE_BINDING. */
enum rs_binding_kind {
  RS_BIND_TLAS,
  RS_BIND_RAYS,
  RS_BIND_RECORDS,
  RS_BIND_COUNTERS,
  RS_BIND_WORDS,
  RS_BIND_IMAGE
};
typedef struct {
  uint32_t binding;
  enum rs_binding_kind kind;
  const uint32_t* words; /* RS_BIND_WORDS: the buffer's contents */
  size_t bytes;
} rs_binding;
typedef struct {
  const char *name, *rule;
  uint32_t offset, words, is_float, automatic, bit;
  uint32_t bound; /* the rs_bound.by a ray's bound widens its abs with (0: none) */
  double abs, rel;
} rs_field;
/* An ambiguous ray's answers in rs_replays from first_replay: `replays` legal
   ones, then `warnings` the judge accepts with a QualityWarning (R-WATERTIGHT),
   their words in rs_warning_notes from first_warning. ahit_limit: the most
   any-hit runs of a device that hits one triangle of the shared edge or
   vertex (more: a double hit, R-WATERTIGHT), RS_NONE where not judged so. */
typedef struct {
  uint32_t ray, first_replay, replays, warnings, first_warning, ahit_limit;
  const char *reason, *rule;
} rs_ambiguous;
typedef struct {
  const char *name, *rule;
  uint64_t lo, hi;
} rs_counter;
typedef struct {
  uint32_t ray;
  uint64_t fields; /* bit rs_field.bit: a field a repeated any-hit may change */
} rs_repeat;
typedef struct {
  uint32_t ray;
  /* 0, then the ray's t, object-origin, hit-position and carried bounds (R-PREC; the
     carried one: the widest, where the case carries them into a free field) */
  float by[5];
} rs_bound;

typedef struct {
  const char *name, *field;
  uint32_t is_float;      /* rgba32f (4 channels), else r32ui (1) */
  double abs, rel, scale; /* the field's tolerance, times the image's scale */
  uint32_t max_failing;   /* pixels allowed to differ */
  uint32_t equal_to;      /* an image it must equal texel for texel, or RS_NONE */
  uint32_t has_field;     /* the field's place in a record: */
  uint32_t offset, words, bit, automatic;
  const uint32_t* expected; /* the model's texels */
} rs_image;

#define RS_CASE_NAME "lavapipe-rejected-report-attribute"

/* The scene: each bottom level's triangles or boxes, laid out as rayspec's builds
   lay them out, and the instances of the top levels; the same again for each
   update (scene.update), in order. */
static const uint8_t rs_blas0_geometry0_boxes[] = {
  0x00, 0x00, 0xc0, 0xbf, 0x00, 0x00, 0xc0, 0xbf, 0x00, 0x00, 0x00, 0xc0, 0x00, 0x00, 0xc0, 0x3f,
  0x00, 0x00, 0xc0, 0x3f, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x80, 0xbf, 0x00, 0x00, 0x80, 0xbf,
  0x00, 0x00, 0x80, 0xbf, 0x00, 0x00, 0x80, 0x3f, 0x00, 0x00, 0x80, 0x3f, 0x00, 0x00, 0x80, 0x3f,
};
static const rs_geometry rs_geometries[] = {
  {VK_GEOMETRY_TYPE_AABBS_KHR, VK_FORMAT_UNDEFINED, "aabbs", 24, 0, VK_INDEX_TYPE_NONE_KHR, 0, rs_blas0_geometry0_boxes, NULL, NULL, 48, 0, 0, {2, 0, 0, 0}},
};
static const rs_blas rs_blases[] = {
  {0, 1, 1},  /* two */
};
static const rs_instance rs_instances[] = {
  {{0x1p+0f, 0x0p+0f, 0x0p+0f, 0x0p+0f, 0x0p+0f, 0x1p+0f, 0x0p+0f, 0x0p+0f, 0x0p+0f, 0x0p+0f, 0x1p+0f, 0x0p+0f}, 0u, 255u, 0u, 0u, 0u, 0u},
};
#define RS_BLAS_COUNT 1
#define RS_MAX_GEOMETRIES 1
#define RS_INSTANCE_COUNT 1
#define RS_TLAS_COUNT 1u
#define RS_STATE_COUNT 1u
#define RS_BUILD_FLAGS 4u
#define RS_COPY RS_COPY_NONE
#define RS_COPY_AT 1u
#define RS_UPDATE_INTO_OTHER 0
#define RS_TLAS_REBUILT 0
static const VkQueryType rs_queries[] = {
  0
};
static const uint32_t rs_query_count = 0;
#define RS_QUERY_AT 1u
#define RS_NEEDS_MAINTENANCE1 0
static const uint8_t rs_referenced[] = {
  1,
};

/* The pipeline's stages: SPIR-V as rayspec compiled it. */
/* raygen: its GLSL, as rayspec generated it */
// #version 460
// #extension GL_EXT_ray_tracing : require
// #extension GL_EXT_buffer_reference : require
// // rayspec case: lavapipe-rejected-report-attribute
// // stage: raygen (raygen), generated by harness/glsl
//
// // Bindings and layouts from harness/glsl/bindings.h and results/record_layout.h.
// #define RS_BINDING_TLAS 0
// #define RS_BINDING_RAYS 1
// #define RS_BINDING_RECORDS 2
// #define RS_BINDING_COUNTERS 3
// #define RS_BINDING_SCENE 4
// #define RS_BINDING_SBT_TABLES 5
// #define RS_RAY_WORDS 16
// #define RS_LAUNCH_ID gl_LaunchIDEXT
// #define RS_LAUNCH_SIZE gl_LaunchSizeEXT
// #define RS_RECORD_WORDS 61
// #define RS_FIELD_RAYGEN_RUNS 53u
// #define RS_BIT_RAYGEN_RUNS 32u
// #define RS_USE_RAYS
// #define RS_USE_TLAS
// #define RS_USE_RECORDS
//
// // ---- shaders/common.glsl ----
// // rayspec shared GLSL: buffers and helpers of set 0 (see harness/glsl/bindings.h).
// // Every number below comes from #defines the generator writes before this
// // file (RS_BINDING_*, RS_RAY_WORDS, RS_RECORD_WORDS, RS_FIELD_<NAME> word
// // offsets, RS_BIT_<NAME> written-mask bits); none is retyped here.
// // RS_LAUNCH_ID and RS_LAUNCH_SIZE are gl_LaunchIDEXT and gl_LaunchSizeEXT, or
// // in raygen run as a compute shader the launch id and size it derives from
// // the dispatch (harness/glsl/emit_compute.h).
// // Optional parts, switched on by the generator only where the stage needs them:
// //   RS_USE_RAYS           the rays buffer (raygen)
// //   RS_USE_TLAS           the acceleration structure (stages that trace)
// //   RS_USE_RECORDS        the per-ray record buffer
// //   RS_USE_COUNTERS       the counter buffer
// //   RS_USE_SHADER_RECORD  this stage's shader record data (8 words)
// // Model counterpart: harness/model (records, counters, shader record data).
//
// #ifdef RS_EMPTY_LAYOUT
// // pipeline.layout: empty. The pipeline layout has no descriptor set (and no
// // push constant): every buffer of set 0 below is reached through its device
// // address instead, the address of binding b being word pair b of the address
// // table, whose own address the specialization constants RS_TABLE_LO_ID and
// // RS_TABLE_HI_ID hold (harness/vulkan/address_table.h); the top level is
// // made from its address (accelerationStructureEXT(uvec2)).
// layout(constant_id = RS_TABLE_LO_ID) const uint rs_table_lo = 0u;
// layout(constant_id = RS_TABLE_HI_ID) const uint rs_table_hi = 0u;
// layout(buffer_reference, std430, buffer_reference_align = 8) readonly buffer RsAddressTable {
//   uvec2 address[];
// };
// uvec2 rs_address(uint binding) {
//   return RsAddressTable(uvec2(rs_table_lo, rs_table_hi)).address[binding];
// }
// // The uint words of the buffer of a binding.
// layout(buffer_reference, std430, buffer_reference_align = 4) buffer RsBoundWords {
//   uint words[];
// };
// #define RS_BOUND_WORDS(binding) RsBoundWords(rs_address(binding)).words
// #endif
//
// // Launch index of this ray: (z * height + y) * width + x (a 3D launch's z
// // layers one below the other).
// uint rs_launch_index() {
//   return (RS_LAUNCH_ID.z * RS_LAUNCH_SIZE.y + RS_LAUNCH_ID.y) * RS_LAUNCH_SIZE.x + RS_LAUNCH_ID.x;
// }
//
// // The texel of this launch's ray in an image `width` texels wide: the
// // launch's rays in row-major order, so a launch wider than the device's
// // largest image (a long ray list) folds into rows. For an image of the
// // launch's own size it is gl_LaunchIDEXT.xy. Device side only (the model
// // keeps images at the launch's size); harness/vulkan/case_buffers.h.
// ivec2 rs_image_texel(int width) {
//   const uint i = rs_launch_index();
//   return ivec2(int(i % uint(width)), int(i / uint(width)));
// }
//
// #ifdef RS_USE_TLAS
// #if defined(RS_EMPTY_LAYOUT)
// #define rs_tlas accelerationStructureEXT(rs_address(RS_BINDING_TLAS))
// #elif defined(RS_TLAS_COUNT)
// // Several top levels (scene.instances[].tlas): a trace names one by a constant.
// layout(set = 0, binding = RS_BINDING_TLAS) uniform accelerationStructureEXT rs_tlas[RS_TLAS_COUNT];
// #else
// layout(set = 0, binding = RS_BINDING_TLAS) uniform accelerationStructureEXT rs_tlas;
// #endif
// #endif
//
// #ifdef RS_USE_RAYS
// #ifdef RS_EMPTY_LAYOUT
// #define rs_rays RS_BOUND_WORDS(RS_BINDING_RAYS)
// #else
// layout(set = 0, binding = RS_BINDING_RAYS, std430) readonly buffer RsRays {
//   uint rs_rays[];
// };
// #endif
//
// // One ray of the launch, as packed by packRays (RS_RAY_WORDS words).
// struct RsRay {
//   vec3 origin;
//   float tmin;
//   vec3 direction;
//   float tmax;
//   uint flags, cull_mask, sbt_offset, sbt_stride, miss;
// };
//
// RsRay rs_load_ray(uint index) {
//   uint w = index * RS_RAY_WORDS;
//   RsRay r;
//   r.origin = vec3(uintBitsToFloat(rs_rays[w + 0u]), uintBitsToFloat(rs_rays[w + 1u]),
//                   uintBitsToFloat(rs_rays[w + 2u]));
//   r.tmin = uintBitsToFloat(rs_rays[w + 3u]);
//   r.direction = vec3(uintBitsToFloat(rs_rays[w + 4u]), uintBitsToFloat(rs_rays[w + 5u]),
//                      uintBitsToFloat(rs_rays[w + 6u]));
//   r.tmax = uintBitsToFloat(rs_rays[w + 7u]);
//   r.flags = rs_rays[w + 8u];
//   r.cull_mask = rs_rays[w + 9u];
//   r.sbt_offset = rs_rays[w + 10u];
//   r.sbt_stride = rs_rays[w + 11u];
//   r.miss = rs_rays[w + 12u];
//   return r;
// }
// #endif
//
// #ifdef RS_USE_RECORDS
// // The record words are reached through their device address, held by the
// // small buffer at RS_BINDING_RECORDS: a storage buffer binding is limited to
// // maxStorageBufferRange (128 MiB on lavapipe), and a launch of 2^20 rays
// // already needs more (the generator enables GL_EXT_buffer_reference).
// layout(buffer_reference, std430, buffer_reference_align = 4) buffer RsRecordWords {
//   uint words[];
// };
// #ifdef RS_EMPTY_LAYOUT
// // The words' address read as two uints, not as a reference: a reference
// // loaded through a PhysicalStorageBuffer pointer needs an 8-byte Aligned
// // operand that Debian 12's glslang does not give it (newer spirv-val:
// // VUID-StandaloneSpirv-PhysicalStorageBuffer64-06314).
// layout(buffer_reference, std430, buffer_reference_align = 8) readonly buffer RsRecordsRef {
//   uvec2 words_address;
// };
// #define rs_records RsRecordWords(RsRecordsRef(rs_address(RS_BINDING_RECORDS)).words_address).words
// #elif defined(RS_RECORDS_BOUND)
// // The words bound directly (the Amber export: a script cannot hand a shader an address).
// layout(set = 0, binding = RS_BINDING_RECORDS, std430) buffer RsRecordsBound {
//   uint rs_records_bound[];
// };
// #define rs_records rs_records_bound
// #else
// layout(set = 0, binding = RS_BINDING_RECORDS, std430) readonly buffer RsRecords {
//   RsRecordWords rs_records_ref;
// };
// #define rs_records rs_records_ref.words
// #endif
//
// // First word of this launch's record.
// uint rs_record_base() {
//   return rs_launch_index() * RS_RECORD_WORDS;
// }
//
// // Word 0 of a record: bit mask of the fields written.
// void rs_mark_written(uint bit) {
//   atomicOr(rs_records[rs_record_base()], 1u << bit);
// }
//
// void rs_record_uint(uint offset, uint bit, uint v) {
//   rs_records[rs_record_base() + offset] = v;
//   rs_mark_written(bit);
// }
//
// void rs_record_float(uint offset, uint bit, float v) {
//   rs_records[rs_record_base() + offset] = floatBitsToUint(v);
//   rs_mark_written(bit);
// }
//
// void rs_record_vec2(uint offset, uint bit, vec2 v) {
//   uint w = rs_record_base() + offset;
//   rs_records[w + 0u] = floatBitsToUint(v.x);
//   rs_records[w + 1u] = floatBitsToUint(v.y);
//   rs_mark_written(bit);
// }
//
// void rs_record_vec3(uint offset, uint bit, vec3 v) {
//   uint w = rs_record_base() + offset;
//   rs_records[w + 0u] = floatBitsToUint(v.x);
//   rs_records[w + 1u] = floatBitsToUint(v.y);
//   rs_records[w + 2u] = floatBitsToUint(v.z);
//   rs_mark_written(bit);
// }
//
// void rs_record_vec4(uint offset, uint bit, vec4 v) {
//   uint w = rs_record_base() + offset;
//   rs_records[w + 0u] = floatBitsToUint(v.x);
//   rs_records[w + 1u] = floatBitsToUint(v.y);
//   rs_records[w + 2u] = floatBitsToUint(v.z);
//   rs_records[w + 3u] = floatBitsToUint(v.w);
//   rs_mark_written(bit);
// }
//
// // Reads word i of a field of this launch's record (raygen, for images).
// uint rs_record_word(uint offset, uint i) {
//   return rs_records[rs_record_base() + offset + i];
// }
//
// // Automatic per-ray stage run count (raygen_runs, miss_runs, ...): +1.
// void rs_bump_runs(uint offset) {
//   atomicAdd(rs_records[rs_record_base() + offset], 1u);
// }
//
// // any-hit: the primitive's bit in any_hit_slots; in any_hit_repeats too when
// // it was set already (results/record_layout.h, anyHitSlot).
// void rs_mark_any_hit(uint slots_offset, uint repeats_offset, uint slot) {
//   uint bit = 1u << slot;
//   uint before = atomicOr(rs_records[rs_record_base() + slots_offset], bit);
//   if ((before & bit) != 0u) atomicOr(rs_records[rs_record_base() + repeats_offset], bit);
// }
// #endif
//
// #ifdef RS_USE_COUNTERS
// #ifdef RS_EMPTY_LAYOUT
// #define rs_counters RS_BOUND_WORDS(RS_BINDING_COUNTERS)
// #else
// layout(set = 0, binding = RS_BINDING_COUNTERS, std430) buffer RsCounters {
//   uint rs_counters[];
// };
// #endif
//
// // Global counter `index` (position of its name in the plan's counters): +1.
// void rs_count(uint index) {
//   atomicAdd(rs_counters[index], 1u);
// }
// #endif
//
// #ifdef RS_USE_SHADER_RECORD
// // Every SBT record carries RS_SHADER_RECORD_WORDS data words after its
// // handle (pipeline.sbt.record_data / 4, default 8; all zero unless the case
// // sets them); the parser keeps every read inside them.
// #ifndef RS_SHADER_RECORD_WORDS
// #define RS_SHADER_RECORD_WORDS 8
// #endif
// layout(shaderRecordEXT, std430) buffer RsShaderRecord {
//   uint words[RS_SHADER_RECORD_WORDS];
// } rs_shader_record;
//
// uint rs_shader_record_uint(uint i) {
//   return rs_shader_record.words[i];
// }
//
// float rs_shader_record_float(uint i) {
//   return uintBitsToFloat(rs_shader_record.words[i]);
// }
// #endif
// // ---- end of shaders/common.glsl ----
//
// // ---- shaders/payload.glsl ----
// // rayspec shared GLSL: the ray payload and the callable data.
// // Model counterpart: harness/model (the same fields, the same start values).
//
// // Payload of every trace (location 0 in raygen and as the incoming payload;
// // location 1 for a nested trace). A trace starts with the color and value its
// // statement gives (`trace: {payload: ...}`, 0 where not given) and depth = 1
// // from raygen, the caller's depth + 1 from a nested trace.
// struct RsPayload {
//   vec4 color;
//   uint value;
//   uint depth;
// };
//
// // Callable data of location L (pipeline.callable_data; declared at L in
// // raygen / closest-hit / miss, at L + 1 inside a callable, whose incoming data
// // is at location 0), RsCallDataW<N> when the type has N more words
// // (harness/glsl/emit_call_data.cpp). Fields a `call` does not give are zero.
// struct RsCallData {
//   vec4 color;
//   vec3 position;
//   uint value;
//   vec3 normal;
//   uint pad;
// };
// // ---- end of shaders/payload.glsl ----
//
// // ---- interface of this stage ----
// layout(location = 0) rayPayloadEXT RsPayload rs_payload_0;
// RsPayload payload;  // the last trace's payload
// RsRay rs_ray;
//
// void main() {
//   rs_bump_runs(RS_FIELD_RAYGEN_RUNS);
//   rs_ray = rs_load_ray(rs_launch_index());
//   payload.color = vec4(0.0);
//   payload.value = 0u;
//   payload.depth = 1u;
//   // ---- program ----
//   {  // trace
//     uint rs_flags = rs_ray.flags;
//     uint rs_cull_mask = rs_ray.cull_mask;
//     uint rs_sbt_offset = rs_ray.sbt_offset;
//     uint rs_sbt_stride = rs_ray.sbt_stride;
//     uint rs_miss = rs_ray.miss;
//     vec3 rs_origin = rs_ray.origin;
//     float rs_tmin = rs_ray.tmin;
//     vec3 rs_direction = rs_ray.direction;
//     float rs_tmax = rs_ray.tmax;
//     vec4 rs_start_color = vec4(0.0);
//     uint rs_start_value = 0u;
//     rs_payload_0.color = rs_start_color;
//     rs_payload_0.value = rs_start_value;
//     rs_payload_0.depth = 1u;
//     traceRayEXT(rs_tlas, rs_flags, rs_cull_mask, rs_sbt_offset, rs_sbt_stride, rs_miss, rs_origin, rs_tmin, rs_direction, rs_tmax, 0);
//     payload = rs_payload_0;
//   }
// }
static const uint32_t rs_spirv_0[] = {
  0x07230203u, 0x00010400u, 0x0008000bu, 0x000000f9u, 0x00000000u, 0x00020011u, 0x0000117fu, 0x00020011u,
  0x000014e3u, 0x0009000au, 0x5f565053u, 0x5f52484bu, 0x73796870u, 0x6c616369u, 0x6f74735fu, 0x65676172u,
  0x6675625fu, 0x00726566u, 0x0006000au, 0x5f565053u, 0x5f52484bu, 0x5f796172u, 0x63617274u, 0x00676e69u,
  0x0006000bu, 0x00000001u, 0x4c534c47u, 0x6474732eu, 0x3035342eu, 0x00000000u, 0x0003000eu, 0x000014e4u,
  0x00000001u, 0x000d000fu, 0x000014c1u, 0x00000004u, 0x6e69616du, 0x00000000u, 0x0000001au, 0x0000001fu,
  0x0000003bu, 0x000000a5u, 0x000000b3u, 0x000000bau, 0x000000e3u, 0x000000edu, 0x00030003u, 0x00000002u,
  0x000001ccu, 0x00070004u, 0x455f4c47u, 0x625f5458u, 0x65666675u, 0x65725f72u, 0x65726566u, 0x0065636eu,
  0x00060004u, 0x455f4c47u, 0x725f5458u, 0x745f7961u, 0x69636172u, 0x0000676eu, 0x00040005u, 0x00000004u,
  0x6e69616du, 0x00000000u, 0x00070005u, 0x00000008u, 0x6c5f7372u, 0x636e7561u, 0x6e695f68u, 0x28786564u,
  0x00000000u, 0x00040005u, 0x0000000du, 0x61527352u, 0x00000079u, 0x00050006u, 0x0000000du, 0x00000000u,
  0x6769726fu, 0x00006e69u, 0x00050006u, 0x0000000du, 0x00000001u, 0x6e696d74u, 0x00000000u, 0x00060006u,
  0x0000000du, 0x00000002u, 0x65726964u, 0x6f697463u, 0x0000006eu, 0x00050006u, 0x0000000du, 0x00000003u,
  0x78616d74u, 0x00000000u, 0x00050006u, 0x0000000du, 0x00000004u, 0x67616c66u, 0x00000073u, 0x00060006u,
  0x0000000du, 0x00000005u, 0x6c6c7563u, 0x73616d5fu, 0x0000006bu, 0x00060006u, 0x0000000du, 0x00000006u,
  0x5f746273u, 0x7366666fu, 0x00007465u, 0x00060006u, 0x0000000du, 0x00000007u, 0x5f746273u, 0x69727473u,
  0x00006564u, 0x00050006u, 0x0000000du, 0x00000008u, 0x7373696du, 0x00000000u, 0x00060005u, 0x00000010u,
  0x6c5f7372u, 0x5f64616fu, 0x28796172u, 0x003b3175u, 0x00040005u, 0x0000000fu, 0x65646e69u, 0x00000078u,
  0x00060005u, 0x00000012u, 0x725f7372u, 0x726f6365u, 0x61625f64u, 0x00286573u, 0x00070005u, 0x00000016u,
  0x625f7372u, 0x5f706d75u, 0x736e7572u, 0x3b317528u, 0x00000000u, 0x00040005u, 0x00000015u, 0x7366666fu,
  0x00007465u, 0x00060005u, 0x0000001au, 0x4c5f6c67u, 0x636e7561u, 0x45444968u, 0x00005458u, 0x00070005u,
  0x0000001fu, 0x4c5f6c67u, 0x636e7561u, 0x7a695368u, 0x54584565u, 0x00000000u, 0x00030005u, 0x00000030u,
  0x00000077u, 0x00030005u, 0x00000035u, 0x00000072u, 0x00040005u, 0x00000039u, 0x61527352u, 0x00007379u,
  0x00050006u, 0x00000039u, 0x00000000u, 0x725f7372u, 0x00737961u, 0x00030005u, 0x0000003bu, 0x00000000u,
  0x00050005u, 0x000000a1u, 0x65527352u, 0x64726f63u, 0x00000073u, 0x00070006u, 0x000000a1u, 0x00000000u,
  0x725f7372u, 0x726f6365u, 0x725f7364u, 0x00006665u, 0x00060005u, 0x000000a3u, 0x65527352u, 0x64726f63u,
  0x64726f57u, 0x00000073u, 0x00050006u, 0x000000a3u, 0x00000000u, 0x64726f77u, 0x00000073u, 0x00030005u,
  0x000000a5u, 0x00000000u, 0x00040005u, 0x000000b0u, 0x61726170u, 0x0000006du, 0x00040005u, 0x000000b3u,
  0x725f7372u, 0x00007961u, 0x00040005u, 0x000000b5u, 0x61726170u, 0x0000006du, 0x00050005u, 0x000000b8u,
  0x61507352u, 0x616f6c79u, 0x00000064u, 0x00050006u, 0x000000b8u, 0x00000000u, 0x6f6c6f63u, 0x00000072u,
  0x00050006u, 0x000000b8u, 0x00000001u, 0x756c6176u, 0x00000065u, 0x00050006u, 0x000000b8u, 0x00000002u,
  0x74706564u, 0x00000068u, 0x00040005u, 0x000000bau, 0x6c796170u, 0x0064616fu, 0x00050005u, 0x000000c2u,
  0x665f7372u, 0x7367616cu, 0x00000000u, 0x00060005u, 0x000000c5u, 0x635f7372u, 0x5f6c6c75u, 0x6b73616du,
  0x00000000u, 0x00060005u, 0x000000c8u, 0x735f7372u, 0x6f5f7462u, 0x65736666u, 0x00000074u, 0x00060005u,
  0x000000cbu, 0x735f7372u, 0x735f7462u, 0x64697274u, 0x00000065u, 0x00040005u, 0x000000ceu, 0x6d5f7372u,
  0x00737369u, 0x00050005u, 0x000000d1u, 0x6f5f7372u, 0x69676972u, 0x0000006eu, 0x00040005u, 0x000000d5u,
  0x745f7372u, 0x006e696du, 0x00060005u, 0x000000d9u, 0x645f7372u, 0x63657269u, 0x6e6f6974u, 0x00000000u,
  0x00040005u, 0x000000dcu, 0x745f7372u, 0x0078616du, 0x00060005u, 0x000000e0u, 0x735f7372u, 0x74726174u,
  0x6c6f635fu, 0x0000726fu, 0x00060005u, 0x000000e1u, 0x735f7372u, 0x74726174u, 0x6c61765fu, 0x00006575u,
  0x00060005u, 0x000000e3u, 0x705f7372u, 0x6f6c7961u, 0x305f6461u, 0x00000000u, 0x00040005u, 0x000000edu,
  0x745f7372u, 0x0073616cu, 0x00040047u, 0x0000001au, 0x0000000bu, 0x000014c7u, 0x00040047u, 0x0000001fu,
  0x0000000bu, 0x000014c8u, 0x00040047u, 0x00000038u, 0x00000006u, 0x00000004u, 0x00040048u, 0x00000039u,
  0x00000000u, 0x00000018u, 0x00050048u, 0x00000039u, 0x00000000u, 0x00000023u, 0x00000000u, 0x00030047u,
  0x00000039u, 0x00000002u, 0x00040047u, 0x0000003bu, 0x00000022u, 0x00000000u, 0x00040047u, 0x0000003bu,
  0x00000021u, 0x00000001u, 0x00040048u, 0x000000a1u, 0x00000000u, 0x00000018u, 0x00050048u, 0x000000a1u,
  0x00000000u, 0x00000023u, 0x00000000u, 0x00030047u, 0x000000a1u, 0x00000002u, 0x00040047u, 0x000000a2u,
  0x00000006u, 0x00000004u, 0x00050048u, 0x000000a3u, 0x00000000u, 0x00000023u, 0x00000000u, 0x00030047u,
  0x000000a3u, 0x00000002u, 0x00040047u, 0x000000a5u, 0x00000022u, 0x00000000u, 0x00040047u, 0x000000a5u,
  0x00000021u, 0x00000002u, 0x00040047u, 0x000000edu, 0x00000022u, 0x00000000u, 0x00040047u, 0x000000edu,
  0x00000021u, 0x00000000u, 0x00020013u, 0x00000002u, 0x00030021u, 0x00000003u, 0x00000002u, 0x00040015u,
  0x00000006u, 0x00000020u, 0x00000000u, 0x00030021u, 0x00000007u, 0x00000006u, 0x00040020u, 0x0000000au,
  0x00000007u, 0x00000006u, 0x00030016u, 0x0000000bu, 0x00000020u, 0x00040017u, 0x0000000cu, 0x0000000bu,
  0x00000003u, 0x000b001eu, 0x0000000du, 0x0000000cu, 0x0000000bu, 0x0000000cu, 0x0000000bu, 0x00000006u,
  0x00000006u, 0x00000006u, 0x00000006u, 0x00000006u, 0x00040021u, 0x0000000eu, 0x0000000du, 0x0000000au,
  0x00040021u, 0x00000014u, 0x00000002u, 0x0000000au, 0x00040017u, 0x00000018u, 0x00000006u, 0x00000003u,
  0x00040020u, 0x00000019u, 0x00000001u, 0x00000018u, 0x0004003bu, 0x00000019u, 0x0000001au, 0x00000001u,
  0x0004002bu, 0x00000006u, 0x0000001bu, 0x00000002u, 0x00040020u, 0x0000001cu, 0x00000001u, 0x00000006u,
  0x0004003bu, 0x00000019u, 0x0000001fu, 0x00000001u, 0x0004002bu, 0x00000006u, 0x00000020u, 0x00000001u,
  0x0004002bu, 0x00000006u, 0x00000027u, 0x00000000u, 0x0004002bu, 0x00000006u, 0x00000032u, 0x00000010u,
  0x00040020u, 0x00000034u, 0x00000007u, 0x0000000du, 0x00040015u, 0x00000036u, 0x00000020u, 0x00000001u,
  0x0004002bu, 0x00000036u, 0x00000037u, 0x00000000u, 0x0003001du, 0x00000038u, 0x00000006u, 0x0003001eu,
  0x00000039u, 0x00000038u, 0x00040020u, 0x0000003au, 0x0000000cu, 0x00000039u, 0x0004003bu, 0x0000003au,
  0x0000003bu, 0x0000000cu, 0x00040020u, 0x0000003eu, 0x0000000cu, 0x00000006u, 0x00040020u, 0x0000004du,
  0x00000007u, 0x0000000cu, 0x0004002bu, 0x00000036u, 0x0000004fu, 0x00000001u, 0x0004002bu, 0x00000006u,
  0x00000051u, 0x00000003u, 0x00040020u, 0x00000056u, 0x00000007u, 0x0000000bu, 0x0004002bu, 0x00000036u,
  0x00000058u, 0x00000002u, 0x0004002bu, 0x00000006u, 0x0000005au, 0x00000004u, 0x0004002bu, 0x00000006u,
  0x00000060u, 0x00000005u, 0x0004002bu, 0x00000006u, 0x00000066u, 0x00000006u, 0x0004002bu, 0x00000036u,
  0x0000006du, 0x00000003u, 0x0004002bu, 0x00000006u, 0x0000006fu, 0x00000007u, 0x0004002bu, 0x00000036u,
  0x00000075u, 0x00000004u, 0x0004002bu, 0x00000006u, 0x00000077u, 0x00000008u, 0x0004002bu, 0x00000036u,
  0x0000007cu, 0x00000005u, 0x0004002bu, 0x00000006u, 0x0000007eu, 0x00000009u, 0x0004002bu, 0x00000036u,
  0x00000083u, 0x00000006u, 0x0004002bu, 0x00000006u, 0x00000085u, 0x0000000au, 0x0004002bu, 0x00000036u,
  0x0000008au, 0x00000007u, 0x0004002bu, 0x00000006u, 0x0000008cu, 0x0000000bu, 0x0004002bu, 0x00000036u,
  0x00000091u, 0x00000008u, 0x0004002bu, 0x00000006u, 0x00000093u, 0x0000000cu, 0x0004002bu, 0x00000006u,
  0x0000009cu, 0x0000003du, 0x00030027u, 0x000000a0u, 0x000014e5u, 0x0003001eu, 0x000000a1u, 0x000000a0u,
  0x0003001du, 0x000000a2u, 0x00000006u, 0x0003001eu, 0x000000a3u, 0x000000a2u, 0x00040020u, 0x000000a0u,
  0x000014e5u, 0x000000a3u, 0x00040020u, 0x000000a4u, 0x0000000cu, 0x000000a1u, 0x0004003bu, 0x000000a4u,
  0x000000a5u, 0x0000000cu, 0x00040020u, 0x000000a6u, 0x0000000cu, 0x000000a0u, 0x00040020u, 0x000000acu,
  0x000014e5u, 0x00000006u, 0x0004002bu, 0x00000006u, 0x000000afu, 0x00000035u, 0x00040020u, 0x000000b2u,
  0x00000006u, 0x0000000du, 0x0004003bu, 0x000000b2u, 0x000000b3u, 0x00000006u, 0x00040017u, 0x000000b7u,
  0x0000000bu, 0x00000004u, 0x0005001eu, 0x000000b8u, 0x000000b7u, 0x00000006u, 0x00000006u, 0x00040020u,
  0x000000b9u, 0x00000006u, 0x000000b8u, 0x0004003bu, 0x000000b9u, 0x000000bau, 0x00000006u, 0x0004002bu,
  0x0000000bu, 0x000000bbu, 0x00000000u, 0x0007002cu, 0x000000b7u, 0x000000bcu, 0x000000bbu, 0x000000bbu,
  0x000000bbu, 0x000000bbu, 0x00040020u, 0x000000bdu, 0x00000006u, 0x000000b7u, 0x00040020u, 0x000000bfu,
  0x00000006u, 0x00000006u, 0x00040020u, 0x000000d2u, 0x00000006u, 0x0000000cu, 0x00040020u, 0x000000d6u,
  0x00000006u, 0x0000000bu, 0x00040020u, 0x000000dfu, 0x00000007u, 0x000000b7u, 0x00040020u, 0x000000e2u,
  0x000014dau, 0x000000b8u, 0x0004003bu, 0x000000e2u, 0x000000e3u, 0x000014dau, 0x00040020u, 0x000000e5u,
  0x000014dau, 0x000000b7u, 0x00040020u, 0x000000e8u, 0x000014dau, 0x00000006u, 0x000214ddu, 0x000000ebu,
  0x00040020u, 0x000000ecu, 0x00000000u, 0x000000ebu, 0x0004003bu, 0x000000ecu, 0x000000edu, 0x00000000u,
  0x00050036u, 0x00000002u, 0x00000004u, 0x00000000u, 0x00000003u, 0x000200f8u, 0x00000005u, 0x0004003bu,
  0x0000000au, 0x000000b0u, 0x00000007u, 0x0004003bu, 0x0000000au, 0x000000b5u, 0x00000007u, 0x0004003bu,
  0x0000000au, 0x000000c2u, 0x00000007u, 0x0004003bu, 0x0000000au, 0x000000c5u, 0x00000007u, 0x0004003bu,
  0x0000000au, 0x000000c8u, 0x00000007u, 0x0004003bu, 0x0000000au, 0x000000cbu, 0x00000007u, 0x0004003bu,
  0x0000000au, 0x000000ceu, 0x00000007u, 0x0004003bu, 0x0000004du, 0x000000d1u, 0x00000007u, 0x0004003bu,
  0x00000056u, 0x000000d5u, 0x00000007u, 0x0004003bu, 0x0000004du, 0x000000d9u, 0x00000007u, 0x0004003bu,
  0x00000056u, 0x000000dcu, 0x00000007u, 0x0004003bu, 0x000000dfu, 0x000000e0u, 0x00000007u, 0x0004003bu,
  0x0000000au, 0x000000e1u, 0x00000007u, 0x0003003eu, 0x000000b0u, 0x000000afu, 0x00050039u, 0x00000002u,
  0x000000b1u, 0x00000016u, 0x000000b0u, 0x00040039u, 0x00000006u, 0x000000b4u, 0x00000008u, 0x0003003eu,
  0x000000b5u, 0x000000b4u, 0x00050039u, 0x0000000du, 0x000000b6u, 0x00000010u, 0x000000b5u, 0x0003003eu,
  0x000000b3u, 0x000000b6u, 0x00050041u, 0x000000bdu, 0x000000beu, 0x000000bau, 0x00000037u, 0x0003003eu,
  0x000000beu, 0x000000bcu, 0x00050041u, 0x000000bfu, 0x000000c0u, 0x000000bau, 0x0000004fu, 0x0003003eu,
  0x000000c0u, 0x00000027u, 0x00050041u, 0x000000bfu, 0x000000c1u, 0x000000bau, 0x00000058u, 0x0003003eu,
  0x000000c1u, 0x00000020u, 0x00050041u, 0x000000bfu, 0x000000c3u, 0x000000b3u, 0x00000075u, 0x0004003du,
  0x00000006u, 0x000000c4u, 0x000000c3u, 0x0003003eu, 0x000000c2u, 0x000000c4u, 0x00050041u, 0x000000bfu,
  0x000000c6u, 0x000000b3u, 0x0000007cu, 0x0004003du, 0x00000006u, 0x000000c7u, 0x000000c6u, 0x0003003eu,
  0x000000c5u, 0x000000c7u, 0x00050041u, 0x000000bfu, 0x000000c9u, 0x000000b3u, 0x00000083u, 0x0004003du,
  0x00000006u, 0x000000cau, 0x000000c9u, 0x0003003eu, 0x000000c8u, 0x000000cau, 0x00050041u, 0x000000bfu,
  0x000000ccu, 0x000000b3u, 0x0000008au, 0x0004003du, 0x00000006u, 0x000000cdu, 0x000000ccu, 0x0003003eu,
  0x000000cbu, 0x000000cdu, 0x00050041u, 0x000000bfu, 0x000000cfu, 0x000000b3u, 0x00000091u, 0x0004003du,
  0x00000006u, 0x000000d0u, 0x000000cfu, 0x0003003eu, 0x000000ceu, 0x000000d0u, 0x00050041u, 0x000000d2u,
  0x000000d3u, 0x000000b3u, 0x00000037u, 0x0004003du, 0x0000000cu, 0x000000d4u, 0x000000d3u, 0x0003003eu,
  0x000000d1u, 0x000000d4u, 0x00050041u, 0x000000d6u, 0x000000d7u, 0x000000b3u, 0x0000004fu, 0x0004003du,
  0x0000000bu, 0x000000d8u, 0x000000d7u, 0x0003003eu, 0x000000d5u, 0x000000d8u, 0x00050041u, 0x000000d2u,
  0x000000dau, 0x000000b3u, 0x00000058u, 0x0004003du, 0x0000000cu, 0x000000dbu, 0x000000dau, 0x0003003eu,
  0x000000d9u, 0x000000dbu, 0x00050041u, 0x000000d6u, 0x000000ddu, 0x000000b3u, 0x0000006du, 0x0004003du,
  0x0000000bu, 0x000000deu, 0x000000ddu, 0x0003003eu, 0x000000dcu, 0x000000deu, 0x0003003eu, 0x000000e0u,
  0x000000bcu, 0x0003003eu, 0x000000e1u, 0x00000027u, 0x0004003du, 0x000000b7u, 0x000000e4u, 0x000000e0u,
  0x00050041u, 0x000000e5u, 0x000000e6u, 0x000000e3u, 0x00000037u, 0x0003003eu, 0x000000e6u, 0x000000e4u,
  0x0004003du, 0x00000006u, 0x000000e7u, 0x000000e1u, 0x00050041u, 0x000000e8u, 0x000000e9u, 0x000000e3u,
  0x0000004fu, 0x0003003eu, 0x000000e9u, 0x000000e7u, 0x00050041u, 0x000000e8u, 0x000000eau, 0x000000e3u,
  0x00000058u, 0x0003003eu, 0x000000eau, 0x00000020u, 0x0004003du, 0x000000ebu, 0x000000eeu, 0x000000edu,
  0x0004003du, 0x00000006u, 0x000000efu, 0x000000c2u, 0x0004003du, 0x00000006u, 0x000000f0u, 0x000000c5u,
  0x0004003du, 0x00000006u, 0x000000f1u, 0x000000c8u, 0x0004003du, 0x00000006u, 0x000000f2u, 0x000000cbu,
  0x0004003du, 0x00000006u, 0x000000f3u, 0x000000ceu, 0x0004003du, 0x0000000cu, 0x000000f4u, 0x000000d1u,
  0x0004003du, 0x0000000bu, 0x000000f5u, 0x000000d5u, 0x0004003du, 0x0000000cu, 0x000000f6u, 0x000000d9u,
  0x0004003du, 0x0000000bu, 0x000000f7u, 0x000000dcu, 0x000c115du, 0x000000eeu, 0x000000efu, 0x000000f0u,
  0x000000f1u, 0x000000f2u, 0x000000f3u, 0x000000f4u, 0x000000f5u, 0x000000f6u, 0x000000f7u, 0x000000e3u,
  0x0004003du, 0x000000b8u, 0x000000f8u, 0x000000e3u, 0x0003003eu, 0x000000bau, 0x000000f8u, 0x000100fdu,
  0x00010038u, 0x00050036u, 0x00000006u, 0x00000008u, 0x00000000u, 0x00000007u, 0x000200f8u, 0x00000009u,
  0x00050041u, 0x0000001cu, 0x0000001du, 0x0000001au, 0x0000001bu, 0x0004003du, 0x00000006u, 0x0000001eu,
  0x0000001du, 0x00050041u, 0x0000001cu, 0x00000021u, 0x0000001fu, 0x00000020u, 0x0004003du, 0x00000006u,
  0x00000022u, 0x00000021u, 0x00050084u, 0x00000006u, 0x00000023u, 0x0000001eu, 0x00000022u, 0x00050041u,
  0x0000001cu, 0x00000024u, 0x0000001au, 0x00000020u, 0x0004003du, 0x00000006u, 0x00000025u, 0x00000024u,
  0x00050080u, 0x00000006u, 0x00000026u, 0x00000023u, 0x00000025u, 0x00050041u, 0x0000001cu, 0x00000028u,
  0x0000001fu, 0x00000027u, 0x0004003du, 0x00000006u, 0x00000029u, 0x00000028u, 0x00050084u, 0x00000006u,
  0x0000002au, 0x00000026u, 0x00000029u, 0x00050041u, 0x0000001cu, 0x0000002bu, 0x0000001au, 0x00000027u,
  0x0004003du, 0x00000006u, 0x0000002cu, 0x0000002bu, 0x00050080u, 0x00000006u, 0x0000002du, 0x0000002au,
  0x0000002cu, 0x000200feu, 0x0000002du, 0x00010038u, 0x00050036u, 0x0000000du, 0x00000010u, 0x00000000u,
  0x0000000eu, 0x00030037u, 0x0000000au, 0x0000000fu, 0x000200f8u, 0x00000011u, 0x0004003bu, 0x0000000au,
  0x00000030u, 0x00000007u, 0x0004003bu, 0x00000034u, 0x00000035u, 0x00000007u, 0x0004003du, 0x00000006u,
  0x00000031u, 0x0000000fu, 0x00050084u, 0x00000006u, 0x00000033u, 0x00000031u, 0x00000032u, 0x0003003eu,
  0x00000030u, 0x00000033u, 0x0004003du, 0x00000006u, 0x0000003cu, 0x00000030u, 0x00050080u, 0x00000006u,
  0x0000003du, 0x0000003cu, 0x00000027u, 0x00060041u, 0x0000003eu, 0x0000003fu, 0x0000003bu, 0x00000037u,
  0x0000003du, 0x0004003du, 0x00000006u, 0x00000040u, 0x0000003fu, 0x0004007cu, 0x0000000bu, 0x00000041u,
  0x00000040u, 0x0004003du, 0x00000006u, 0x00000042u, 0x00000030u, 0x00050080u, 0x00000006u, 0x00000043u,
  0x00000042u, 0x00000020u, 0x00060041u, 0x0000003eu, 0x00000044u, 0x0000003bu, 0x00000037u, 0x00000043u,
  0x0004003du, 0x00000006u, 0x00000045u, 0x00000044u, 0x0004007cu, 0x0000000bu, 0x00000046u, 0x00000045u,
  0x0004003du, 0x00000006u, 0x00000047u, 0x00000030u, 0x00050080u, 0x00000006u, 0x00000048u, 0x00000047u,
  0x0000001bu, 0x00060041u, 0x0000003eu, 0x00000049u, 0x0000003bu, 0x00000037u, 0x00000048u, 0x0004003du,
  0x00000006u, 0x0000004au, 0x00000049u, 0x0004007cu, 0x0000000bu, 0x0000004bu, 0x0000004au, 0x00060050u,
  0x0000000cu, 0x0000004cu, 0x00000041u, 0x00000046u, 0x0000004bu, 0x00050041u, 0x0000004du, 0x0000004eu,
  0x00000035u, 0x00000037u, 0x0003003eu, 0x0000004eu, 0x0000004cu, 0x0004003du, 0x00000006u, 0x00000050u,
  0x00000030u, 0x00050080u, 0x00000006u, 0x00000052u, 0x00000050u, 0x00000051u, 0x00060041u, 0x0000003eu,
  0x00000053u, 0x0000003bu, 0x00000037u, 0x00000052u, 0x0004003du, 0x00000006u, 0x00000054u, 0x00000053u,
  0x0004007cu, 0x0000000bu, 0x00000055u, 0x00000054u, 0x00050041u, 0x00000056u, 0x00000057u, 0x00000035u,
  0x0000004fu, 0x0003003eu, 0x00000057u, 0x00000055u, 0x0004003du, 0x00000006u, 0x00000059u, 0x00000030u,
  0x00050080u, 0x00000006u, 0x0000005bu, 0x00000059u, 0x0000005au, 0x00060041u, 0x0000003eu, 0x0000005cu,
  0x0000003bu, 0x00000037u, 0x0000005bu, 0x0004003du, 0x00000006u, 0x0000005du, 0x0000005cu, 0x0004007cu,
  0x0000000bu, 0x0000005eu, 0x0000005du, 0x0004003du, 0x00000006u, 0x0000005fu, 0x00000030u, 0x00050080u,
  0x00000006u, 0x00000061u, 0x0000005fu, 0x00000060u, 0x00060041u, 0x0000003eu, 0x00000062u, 0x0000003bu,
  0x00000037u, 0x00000061u, 0x0004003du, 0x00000006u, 0x00000063u, 0x00000062u, 0x0004007cu, 0x0000000bu,
  0x00000064u, 0x00000063u, 0x0004003du, 0x00000006u, 0x00000065u, 0x00000030u, 0x00050080u, 0x00000006u,
  0x00000067u, 0x00000065u, 0x00000066u, 0x00060041u, 0x0000003eu, 0x00000068u, 0x0000003bu, 0x00000037u,
  0x00000067u, 0x0004003du, 0x00000006u, 0x00000069u, 0x00000068u, 0x0004007cu, 0x0000000bu, 0x0000006au,
  0x00000069u, 0x00060050u, 0x0000000cu, 0x0000006bu, 0x0000005eu, 0x00000064u, 0x0000006au, 0x00050041u,
  0x0000004du, 0x0000006cu, 0x00000035u, 0x00000058u, 0x0003003eu, 0x0000006cu, 0x0000006bu, 0x0004003du,
  0x00000006u, 0x0000006eu, 0x00000030u, 0x00050080u, 0x00000006u, 0x00000070u, 0x0000006eu, 0x0000006fu,
  0x00060041u, 0x0000003eu, 0x00000071u, 0x0000003bu, 0x00000037u, 0x00000070u, 0x0004003du, 0x00000006u,
  0x00000072u, 0x00000071u, 0x0004007cu, 0x0000000bu, 0x00000073u, 0x00000072u, 0x00050041u, 0x00000056u,
  0x00000074u, 0x00000035u, 0x0000006du, 0x0003003eu, 0x00000074u, 0x00000073u, 0x0004003du, 0x00000006u,
  0x00000076u, 0x00000030u, 0x00050080u, 0x00000006u, 0x00000078u, 0x00000076u, 0x00000077u, 0x00060041u,
  0x0000003eu, 0x00000079u, 0x0000003bu, 0x00000037u, 0x00000078u, 0x0004003du, 0x00000006u, 0x0000007au,
  0x00000079u, 0x00050041u, 0x0000000au, 0x0000007bu, 0x00000035u, 0x00000075u, 0x0003003eu, 0x0000007bu,
  0x0000007au, 0x0004003du, 0x00000006u, 0x0000007du, 0x00000030u, 0x00050080u, 0x00000006u, 0x0000007fu,
  0x0000007du, 0x0000007eu, 0x00060041u, 0x0000003eu, 0x00000080u, 0x0000003bu, 0x00000037u, 0x0000007fu,
  0x0004003du, 0x00000006u, 0x00000081u, 0x00000080u, 0x00050041u, 0x0000000au, 0x00000082u, 0x00000035u,
  0x0000007cu, 0x0003003eu, 0x00000082u, 0x00000081u, 0x0004003du, 0x00000006u, 0x00000084u, 0x00000030u,
  0x00050080u, 0x00000006u, 0x00000086u, 0x00000084u, 0x00000085u, 0x00060041u, 0x0000003eu, 0x00000087u,
  0x0000003bu, 0x00000037u, 0x00000086u, 0x0004003du, 0x00000006u, 0x00000088u, 0x00000087u, 0x00050041u,
  0x0000000au, 0x00000089u, 0x00000035u, 0x00000083u, 0x0003003eu, 0x00000089u, 0x00000088u, 0x0004003du,
  0x00000006u, 0x0000008bu, 0x00000030u, 0x00050080u, 0x00000006u, 0x0000008du, 0x0000008bu, 0x0000008cu,
  0x00060041u, 0x0000003eu, 0x0000008eu, 0x0000003bu, 0x00000037u, 0x0000008du, 0x0004003du, 0x00000006u,
  0x0000008fu, 0x0000008eu, 0x00050041u, 0x0000000au, 0x00000090u, 0x00000035u, 0x0000008au, 0x0003003eu,
  0x00000090u, 0x0000008fu, 0x0004003du, 0x00000006u, 0x00000092u, 0x00000030u, 0x00050080u, 0x00000006u,
  0x00000094u, 0x00000092u, 0x00000093u, 0x00060041u, 0x0000003eu, 0x00000095u, 0x0000003bu, 0x00000037u,
  0x00000094u, 0x0004003du, 0x00000006u, 0x00000096u, 0x00000095u, 0x00050041u, 0x0000000au, 0x00000097u,
  0x00000035u, 0x00000091u, 0x0003003eu, 0x00000097u, 0x00000096u, 0x0004003du, 0x0000000du, 0x00000098u,
  0x00000035u, 0x000200feu, 0x00000098u, 0x00010038u, 0x00050036u, 0x00000006u, 0x00000012u, 0x00000000u,
  0x00000007u, 0x000200f8u, 0x00000013u, 0x00040039u, 0x00000006u, 0x0000009bu, 0x00000008u, 0x00050084u,
  0x00000006u, 0x0000009du, 0x0000009bu, 0x0000009cu, 0x000200feu, 0x0000009du, 0x00010038u, 0x00050036u,
  0x00000002u, 0x00000016u, 0x00000000u, 0x00000014u, 0x00030037u, 0x0000000au, 0x00000015u, 0x000200f8u,
  0x00000017u, 0x00050041u, 0x000000a6u, 0x000000a7u, 0x000000a5u, 0x00000037u, 0x0004003du, 0x000000a0u,
  0x000000a8u, 0x000000a7u, 0x00040039u, 0x00000006u, 0x000000a9u, 0x00000012u, 0x0004003du, 0x00000006u,
  0x000000aau, 0x00000015u, 0x00050080u, 0x00000006u, 0x000000abu, 0x000000a9u, 0x000000aau, 0x00060041u,
  0x000000acu, 0x000000adu, 0x000000a8u, 0x00000037u, 0x000000abu, 0x000700eau, 0x00000006u, 0x000000aeu,
  0x000000adu, 0x00000020u, 0x00000027u, 0x00000020u, 0x000100fdu, 0x00010038u,
};
/* hit0.closest_hit: its GLSL, as rayspec generated it */
// #version 460
// #extension GL_EXT_ray_tracing : require
// #extension GL_EXT_buffer_reference : require
// // rayspec case: lavapipe-rejected-report-attribute
// // stage: closest_hit (hit0.closest_hit), generated by harness/glsl
//
// // Bindings and layouts from harness/glsl/bindings.h and results/record_layout.h.
// #define RS_BINDING_TLAS 0
// #define RS_BINDING_RAYS 1
// #define RS_BINDING_RECORDS 2
// #define RS_BINDING_COUNTERS 3
// #define RS_BINDING_SCENE 4
// #define RS_BINDING_SBT_TABLES 5
// #define RS_RAY_WORDS 16
// #define RS_LAUNCH_ID gl_LaunchIDEXT
// #define RS_LAUNCH_SIZE gl_LaunchSizeEXT
// #define RS_RECORD_WORDS 61
// #define RS_FIELD_BARYCENTRICS 8u
// #define RS_BIT_BARYCENTRICS 7u
// #define RS_FIELD_CLOSEST_HIT_RUNS 55u
// #define RS_BIT_CLOSEST_HIT_RUNS 34u
// #define RS_USE_RECORDS
//
// // ---- shaders/common.glsl ----
// // rayspec shared GLSL: buffers and helpers of set 0 (see harness/glsl/bindings.h).
// // Every number below comes from #defines the generator writes before this
// // file (RS_BINDING_*, RS_RAY_WORDS, RS_RECORD_WORDS, RS_FIELD_<NAME> word
// // offsets, RS_BIT_<NAME> written-mask bits); none is retyped here.
// // RS_LAUNCH_ID and RS_LAUNCH_SIZE are gl_LaunchIDEXT and gl_LaunchSizeEXT, or
// // in raygen run as a compute shader the launch id and size it derives from
// // the dispatch (harness/glsl/emit_compute.h).
// // Optional parts, switched on by the generator only where the stage needs them:
// //   RS_USE_RAYS           the rays buffer (raygen)
// //   RS_USE_TLAS           the acceleration structure (stages that trace)
// //   RS_USE_RECORDS        the per-ray record buffer
// //   RS_USE_COUNTERS       the counter buffer
// //   RS_USE_SHADER_RECORD  this stage's shader record data (8 words)
// // Model counterpart: harness/model (records, counters, shader record data).
//
// #ifdef RS_EMPTY_LAYOUT
// // pipeline.layout: empty. The pipeline layout has no descriptor set (and no
// // push constant): every buffer of set 0 below is reached through its device
// // address instead, the address of binding b being word pair b of the address
// // table, whose own address the specialization constants RS_TABLE_LO_ID and
// // RS_TABLE_HI_ID hold (harness/vulkan/address_table.h); the top level is
// // made from its address (accelerationStructureEXT(uvec2)).
// layout(constant_id = RS_TABLE_LO_ID) const uint rs_table_lo = 0u;
// layout(constant_id = RS_TABLE_HI_ID) const uint rs_table_hi = 0u;
// layout(buffer_reference, std430, buffer_reference_align = 8) readonly buffer RsAddressTable {
//   uvec2 address[];
// };
// uvec2 rs_address(uint binding) {
//   return RsAddressTable(uvec2(rs_table_lo, rs_table_hi)).address[binding];
// }
// // The uint words of the buffer of a binding.
// layout(buffer_reference, std430, buffer_reference_align = 4) buffer RsBoundWords {
//   uint words[];
// };
// #define RS_BOUND_WORDS(binding) RsBoundWords(rs_address(binding)).words
// #endif
//
// // Launch index of this ray: (z * height + y) * width + x (a 3D launch's z
// // layers one below the other).
// uint rs_launch_index() {
//   return (RS_LAUNCH_ID.z * RS_LAUNCH_SIZE.y + RS_LAUNCH_ID.y) * RS_LAUNCH_SIZE.x + RS_LAUNCH_ID.x;
// }
//
// // The texel of this launch's ray in an image `width` texels wide: the
// // launch's rays in row-major order, so a launch wider than the device's
// // largest image (a long ray list) folds into rows. For an image of the
// // launch's own size it is gl_LaunchIDEXT.xy. Device side only (the model
// // keeps images at the launch's size); harness/vulkan/case_buffers.h.
// ivec2 rs_image_texel(int width) {
//   const uint i = rs_launch_index();
//   return ivec2(int(i % uint(width)), int(i / uint(width)));
// }
//
// #ifdef RS_USE_TLAS
// #if defined(RS_EMPTY_LAYOUT)
// #define rs_tlas accelerationStructureEXT(rs_address(RS_BINDING_TLAS))
// #elif defined(RS_TLAS_COUNT)
// // Several top levels (scene.instances[].tlas): a trace names one by a constant.
// layout(set = 0, binding = RS_BINDING_TLAS) uniform accelerationStructureEXT rs_tlas[RS_TLAS_COUNT];
// #else
// layout(set = 0, binding = RS_BINDING_TLAS) uniform accelerationStructureEXT rs_tlas;
// #endif
// #endif
//
// #ifdef RS_USE_RAYS
// #ifdef RS_EMPTY_LAYOUT
// #define rs_rays RS_BOUND_WORDS(RS_BINDING_RAYS)
// #else
// layout(set = 0, binding = RS_BINDING_RAYS, std430) readonly buffer RsRays {
//   uint rs_rays[];
// };
// #endif
//
// // One ray of the launch, as packed by packRays (RS_RAY_WORDS words).
// struct RsRay {
//   vec3 origin;
//   float tmin;
//   vec3 direction;
//   float tmax;
//   uint flags, cull_mask, sbt_offset, sbt_stride, miss;
// };
//
// RsRay rs_load_ray(uint index) {
//   uint w = index * RS_RAY_WORDS;
//   RsRay r;
//   r.origin = vec3(uintBitsToFloat(rs_rays[w + 0u]), uintBitsToFloat(rs_rays[w + 1u]),
//                   uintBitsToFloat(rs_rays[w + 2u]));
//   r.tmin = uintBitsToFloat(rs_rays[w + 3u]);
//   r.direction = vec3(uintBitsToFloat(rs_rays[w + 4u]), uintBitsToFloat(rs_rays[w + 5u]),
//                      uintBitsToFloat(rs_rays[w + 6u]));
//   r.tmax = uintBitsToFloat(rs_rays[w + 7u]);
//   r.flags = rs_rays[w + 8u];
//   r.cull_mask = rs_rays[w + 9u];
//   r.sbt_offset = rs_rays[w + 10u];
//   r.sbt_stride = rs_rays[w + 11u];
//   r.miss = rs_rays[w + 12u];
//   return r;
// }
// #endif
//
// #ifdef RS_USE_RECORDS
// // The record words are reached through their device address, held by the
// // small buffer at RS_BINDING_RECORDS: a storage buffer binding is limited to
// // maxStorageBufferRange (128 MiB on lavapipe), and a launch of 2^20 rays
// // already needs more (the generator enables GL_EXT_buffer_reference).
// layout(buffer_reference, std430, buffer_reference_align = 4) buffer RsRecordWords {
//   uint words[];
// };
// #ifdef RS_EMPTY_LAYOUT
// // The words' address read as two uints, not as a reference: a reference
// // loaded through a PhysicalStorageBuffer pointer needs an 8-byte Aligned
// // operand that Debian 12's glslang does not give it (newer spirv-val:
// // VUID-StandaloneSpirv-PhysicalStorageBuffer64-06314).
// layout(buffer_reference, std430, buffer_reference_align = 8) readonly buffer RsRecordsRef {
//   uvec2 words_address;
// };
// #define rs_records RsRecordWords(RsRecordsRef(rs_address(RS_BINDING_RECORDS)).words_address).words
// #elif defined(RS_RECORDS_BOUND)
// // The words bound directly (the Amber export: a script cannot hand a shader an address).
// layout(set = 0, binding = RS_BINDING_RECORDS, std430) buffer RsRecordsBound {
//   uint rs_records_bound[];
// };
// #define rs_records rs_records_bound
// #else
// layout(set = 0, binding = RS_BINDING_RECORDS, std430) readonly buffer RsRecords {
//   RsRecordWords rs_records_ref;
// };
// #define rs_records rs_records_ref.words
// #endif
//
// // First word of this launch's record.
// uint rs_record_base() {
//   return rs_launch_index() * RS_RECORD_WORDS;
// }
//
// // Word 0 of a record: bit mask of the fields written.
// void rs_mark_written(uint bit) {
//   atomicOr(rs_records[rs_record_base()], 1u << bit);
// }
//
// void rs_record_uint(uint offset, uint bit, uint v) {
//   rs_records[rs_record_base() + offset] = v;
//   rs_mark_written(bit);
// }
//
// void rs_record_float(uint offset, uint bit, float v) {
//   rs_records[rs_record_base() + offset] = floatBitsToUint(v);
//   rs_mark_written(bit);
// }
//
// void rs_record_vec2(uint offset, uint bit, vec2 v) {
//   uint w = rs_record_base() + offset;
//   rs_records[w + 0u] = floatBitsToUint(v.x);
//   rs_records[w + 1u] = floatBitsToUint(v.y);
//   rs_mark_written(bit);
// }
//
// void rs_record_vec3(uint offset, uint bit, vec3 v) {
//   uint w = rs_record_base() + offset;
//   rs_records[w + 0u] = floatBitsToUint(v.x);
//   rs_records[w + 1u] = floatBitsToUint(v.y);
//   rs_records[w + 2u] = floatBitsToUint(v.z);
//   rs_mark_written(bit);
// }
//
// void rs_record_vec4(uint offset, uint bit, vec4 v) {
//   uint w = rs_record_base() + offset;
//   rs_records[w + 0u] = floatBitsToUint(v.x);
//   rs_records[w + 1u] = floatBitsToUint(v.y);
//   rs_records[w + 2u] = floatBitsToUint(v.z);
//   rs_records[w + 3u] = floatBitsToUint(v.w);
//   rs_mark_written(bit);
// }
//
// // Reads word i of a field of this launch's record (raygen, for images).
// uint rs_record_word(uint offset, uint i) {
//   return rs_records[rs_record_base() + offset + i];
// }
//
// // Automatic per-ray stage run count (raygen_runs, miss_runs, ...): +1.
// void rs_bump_runs(uint offset) {
//   atomicAdd(rs_records[rs_record_base() + offset], 1u);
// }
//
// // any-hit: the primitive's bit in any_hit_slots; in any_hit_repeats too when
// // it was set already (results/record_layout.h, anyHitSlot).
// void rs_mark_any_hit(uint slots_offset, uint repeats_offset, uint slot) {
//   uint bit = 1u << slot;
//   uint before = atomicOr(rs_records[rs_record_base() + slots_offset], bit);
//   if ((before & bit) != 0u) atomicOr(rs_records[rs_record_base() + repeats_offset], bit);
// }
// #endif
//
// #ifdef RS_USE_COUNTERS
// #ifdef RS_EMPTY_LAYOUT
// #define rs_counters RS_BOUND_WORDS(RS_BINDING_COUNTERS)
// #else
// layout(set = 0, binding = RS_BINDING_COUNTERS, std430) buffer RsCounters {
//   uint rs_counters[];
// };
// #endif
//
// // Global counter `index` (position of its name in the plan's counters): +1.
// void rs_count(uint index) {
//   atomicAdd(rs_counters[index], 1u);
// }
// #endif
//
// #ifdef RS_USE_SHADER_RECORD
// // Every SBT record carries RS_SHADER_RECORD_WORDS data words after its
// // handle (pipeline.sbt.record_data / 4, default 8; all zero unless the case
// // sets them); the parser keeps every read inside them.
// #ifndef RS_SHADER_RECORD_WORDS
// #define RS_SHADER_RECORD_WORDS 8
// #endif
// layout(shaderRecordEXT, std430) buffer RsShaderRecord {
//   uint words[RS_SHADER_RECORD_WORDS];
// } rs_shader_record;
//
// uint rs_shader_record_uint(uint i) {
//   return rs_shader_record.words[i];
// }
//
// float rs_shader_record_float(uint i) {
//   return uintBitsToFloat(rs_shader_record.words[i]);
// }
// #endif
// // ---- end of shaders/common.glsl ----
//
// // ---- shaders/payload.glsl ----
// // rayspec shared GLSL: the ray payload and the callable data.
// // Model counterpart: harness/model (the same fields, the same start values).
//
// // Payload of every trace (location 0 in raygen and as the incoming payload;
// // location 1 for a nested trace). A trace starts with the color and value its
// // statement gives (`trace: {payload: ...}`, 0 where not given) and depth = 1
// // from raygen, the caller's depth + 1 from a nested trace.
// struct RsPayload {
//   vec4 color;
//   uint value;
//   uint depth;
// };
//
// // Callable data of location L (pipeline.callable_data; declared at L in
// // raygen / closest-hit / miss, at L + 1 inside a callable, whose incoming data
// // is at location 0), RsCallDataW<N> when the type has N more words
// // (harness/glsl/emit_call_data.cpp). Fields a `call` does not give are zero.
// struct RsCallData {
//   vec4 color;
//   vec3 position;
//   uint value;
//   vec3 normal;
//   uint pad;
// };
// // ---- end of shaders/payload.glsl ----
//
// // ---- interface of this stage ----
// layout(location = 0) rayPayloadInEXT RsPayload payload;
// hitAttributeEXT vec2 rs_attr;
//
// void main() {
//   rs_bump_runs(RS_FIELD_CLOSEST_HIT_RUNS);
//   // ---- program ----
//   rs_record_vec2(RS_FIELD_BARYCENTRICS, RS_BIT_BARYCENTRICS, rs_attr);
// }
static const uint32_t rs_spirv_1[] = {
  0x07230203u, 0x00010400u, 0x0008000bu, 0x0000007au, 0x00000000u, 0x00020011u, 0x0000117fu, 0x00020011u,
  0x000014e3u, 0x0009000au, 0x5f565053u, 0x5f52484bu, 0x73796870u, 0x6c616369u, 0x6f74735fu, 0x65676172u,
  0x6675625fu, 0x00726566u, 0x0006000au, 0x5f565053u, 0x5f52484bu, 0x5f796172u, 0x63617274u, 0x00676e69u,
  0x0006000bu, 0x00000001u, 0x4c534c47u, 0x6474732eu, 0x3035342eu, 0x00000000u, 0x0003000eu, 0x000014e4u,
  0x00000001u, 0x000a000fu, 0x000014c4u, 0x00000004u, 0x6e69616du, 0x00000000u, 0x0000001fu, 0x00000024u,
  0x0000003fu, 0x00000070u, 0x00000079u, 0x00030003u, 0x00000002u, 0x000001ccu, 0x00070004u, 0x455f4c47u,
  0x625f5458u, 0x65666675u, 0x65725f72u, 0x65726566u, 0x0065636eu, 0x00060004u, 0x455f4c47u, 0x725f5458u,
  0x745f7961u, 0x69636172u, 0x0000676eu, 0x00040005u, 0x00000004u, 0x6e69616du, 0x00000000u, 0x00070005u,
  0x00000008u, 0x6c5f7372u, 0x636e7561u, 0x6e695f68u, 0x28786564u, 0x00000000u, 0x00060005u, 0x0000000au,
  0x725f7372u, 0x726f6365u, 0x61625f64u, 0x00286573u, 0x00070005u, 0x0000000fu, 0x6d5f7372u, 0x5f6b7261u,
  0x74697277u, 0x286e6574u, 0x003b3175u, 0x00030005u, 0x0000000eu, 0x00746962u, 0x00090005u, 0x00000018u,
  0x725f7372u, 0x726f6365u, 0x65765f64u, 0x75283263u, 0x31753b31u, 0x3266763bu, 0x0000003bu, 0x00040005u,
  0x00000015u, 0x7366666fu, 0x00007465u, 0x00030005u, 0x00000016u, 0x00746962u, 0x00030005u, 0x00000017u,
  0x00000076u, 0x00070005u, 0x0000001bu, 0x625f7372u, 0x5f706d75u, 0x736e7572u, 0x3b317528u, 0x00000000u,
  0x00040005u, 0x0000001au, 0x7366666fu, 0x00007465u, 0x00060005u, 0x0000001fu, 0x4c5f6c67u, 0x636e7561u,
  0x45444968u, 0x00005458u, 0x00070005u, 0x00000024u, 0x4c5f6c67u, 0x636e7561u, 0x7a695368u, 0x54584565u,
  0x00000000u, 0x00050005u, 0x0000003bu, 0x65527352u, 0x64726f63u, 0x00000073u, 0x00070006u, 0x0000003bu,
  0x00000000u, 0x725f7372u, 0x726f6365u, 0x725f7364u, 0x00006665u, 0x00060005u, 0x0000003du, 0x65527352u,
  0x64726f63u, 0x64726f57u, 0x00000073u, 0x00050006u, 0x0000003du, 0x00000000u, 0x64726f77u, 0x00000073u,
  0x00030005u, 0x0000003fu, 0x00000000u, 0x00030005u, 0x0000004bu, 0x00000077u, 0x00040005u, 0x00000060u,
  0x61726170u, 0x0000006du, 0x00040005u, 0x0000006bu, 0x61726170u, 0x0000006du, 0x00040005u, 0x00000070u,
  0x615f7372u, 0x00727474u, 0x00040005u, 0x00000071u, 0x61726170u, 0x0000006du, 0x00040005u, 0x00000072u,
  0x61726170u, 0x0000006du, 0x00040005u, 0x00000073u, 0x61726170u, 0x0000006du, 0x00050005u, 0x00000077u,
  0x61507352u, 0x616f6c79u, 0x00000064u, 0x00050006u, 0x00000077u, 0x00000000u, 0x6f6c6f63u, 0x00000072u,
  0x00050006u, 0x00000077u, 0x00000001u, 0x756c6176u, 0x00000065u, 0x00050006u, 0x00000077u, 0x00000002u,
  0x74706564u, 0x00000068u, 0x00040005u, 0x00000079u, 0x6c796170u, 0x0064616fu, 0x00040047u, 0x0000001fu,
  0x0000000bu, 0x000014c7u, 0x00040047u, 0x00000024u, 0x0000000bu, 0x000014c8u, 0x00040048u, 0x0000003bu,
  0x00000000u, 0x00000018u, 0x00050048u, 0x0000003bu, 0x00000000u, 0x00000023u, 0x00000000u, 0x00030047u,
  0x0000003bu, 0x00000002u, 0x00040047u, 0x0000003cu, 0x00000006u, 0x00000004u, 0x00050048u, 0x0000003du,
  0x00000000u, 0x00000023u, 0x00000000u, 0x00030047u, 0x0000003du, 0x00000002u, 0x00040047u, 0x0000003fu,
  0x00000022u, 0x00000000u, 0x00040047u, 0x0000003fu, 0x00000021u, 0x00000002u, 0x00020013u, 0x00000002u,
  0x00030021u, 0x00000003u, 0x00000002u, 0x00040015u, 0x00000006u, 0x00000020u, 0x00000000u, 0x00030021u,
  0x00000007u, 0x00000006u, 0x00040020u, 0x0000000cu, 0x00000007u, 0x00000006u, 0x00040021u, 0x0000000du,
  0x00000002u, 0x0000000cu, 0x00030016u, 0x00000011u, 0x00000020u, 0x00040017u, 0x00000012u, 0x00000011u,
  0x00000002u, 0x00040020u, 0x00000013u, 0x00000007u, 0x00000012u, 0x00060021u, 0x00000014u, 0x00000002u,
  0x0000000cu, 0x0000000cu, 0x00000013u, 0x00040017u, 0x0000001du, 0x00000006u, 0x00000003u, 0x00040020u,
  0x0000001eu, 0x00000001u, 0x0000001du, 0x0004003bu, 0x0000001eu, 0x0000001fu, 0x00000001u, 0x0004002bu,
  0x00000006u, 0x00000020u, 0x00000002u, 0x00040020u, 0x00000021u, 0x00000001u, 0x00000006u, 0x0004003bu,
  0x0000001eu, 0x00000024u, 0x00000001u, 0x0004002bu, 0x00000006u, 0x00000025u, 0x00000001u, 0x0004002bu,
  0x00000006u, 0x0000002cu, 0x00000000u, 0x0004002bu, 0x00000006u, 0x00000036u, 0x0000003du, 0x00030027u,
  0x0000003au, 0x000014e5u, 0x0003001eu, 0x0000003bu, 0x0000003au, 0x0003001du, 0x0000003cu, 0x00000006u,
  0x0003001eu, 0x0000003du, 0x0000003cu, 0x00040020u, 0x0000003au, 0x000014e5u, 0x0000003du, 0x00040020u,
  0x0000003eu, 0x0000000cu, 0x0000003bu, 0x0004003bu, 0x0000003eu, 0x0000003fu, 0x0000000cu, 0x00040015u,
  0x00000040u, 0x00000020u, 0x00000001u, 0x0004002bu, 0x00000040u, 0x00000041u, 0x00000000u, 0x00040020u,
  0x00000042u, 0x0000000cu, 0x0000003au, 0x00040020u, 0x00000046u, 0x000014e5u, 0x00000006u, 0x00040020u,
  0x00000053u, 0x00000007u, 0x00000011u, 0x0004002bu, 0x00000006u, 0x0000006au, 0x00000037u, 0x0004002bu,
  0x00000006u, 0x0000006du, 0x00000008u, 0x0004002bu, 0x00000006u, 0x0000006eu, 0x00000007u, 0x00040020u,
  0x0000006fu, 0x000014dbu, 0x00000012u, 0x0004003bu, 0x0000006fu, 0x00000070u, 0x000014dbu, 0x00040017u,
  0x00000076u, 0x00000011u, 0x00000004u, 0x0005001eu, 0x00000077u, 0x00000076u, 0x00000006u, 0x00000006u,
  0x00040020u, 0x00000078u, 0x000014deu, 0x00000077u, 0x0004003bu, 0x00000078u, 0x00000079u, 0x000014deu,
  0x00050036u, 0x00000002u, 0x00000004u, 0x00000000u, 0x00000003u, 0x000200f8u, 0x00000005u, 0x0004003bu,
  0x0000000cu, 0x0000006bu, 0x00000007u, 0x0004003bu, 0x0000000cu, 0x00000071u, 0x00000007u, 0x0004003bu,
  0x0000000cu, 0x00000072u, 0x00000007u, 0x0004003bu, 0x00000013u, 0x00000073u, 0x00000007u, 0x0003003eu,
  0x0000006bu, 0x0000006au, 0x00050039u, 0x00000002u, 0x0000006cu, 0x0000001bu, 0x0000006bu, 0x0003003eu,
  0x00000071u, 0x0000006du, 0x0003003eu, 0x00000072u, 0x0000006eu, 0x0004003du, 0x00000012u, 0x00000074u,
  0x00000070u, 0x0003003eu, 0x00000073u, 0x00000074u, 0x00070039u, 0x00000002u, 0x00000075u, 0x00000018u,
  0x00000071u, 0x00000072u, 0x00000073u, 0x000100fdu, 0x00010038u, 0x00050036u, 0x00000006u, 0x00000008u,
  0x00000000u, 0x00000007u, 0x000200f8u, 0x00000009u, 0x00050041u, 0x00000021u, 0x00000022u, 0x0000001fu,
  0x00000020u, 0x0004003du, 0x00000006u, 0x00000023u, 0x00000022u, 0x00050041u, 0x00000021u, 0x00000026u,
  0x00000024u, 0x00000025u, 0x0004003du, 0x00000006u, 0x00000027u, 0x00000026u, 0x00050084u, 0x00000006u,
  0x00000028u, 0x00000023u, 0x00000027u, 0x00050041u, 0x00000021u, 0x00000029u, 0x0000001fu, 0x00000025u,
  0x0004003du, 0x00000006u, 0x0000002au, 0x00000029u, 0x00050080u, 0x00000006u, 0x0000002bu, 0x00000028u,
  0x0000002au, 0x00050041u, 0x00000021u, 0x0000002du, 0x00000024u, 0x0000002cu, 0x0004003du, 0x00000006u,
  0x0000002eu, 0x0000002du, 0x00050084u, 0x00000006u, 0x0000002fu, 0x0000002bu, 0x0000002eu, 0x00050041u,
  0x00000021u, 0x00000030u, 0x0000001fu, 0x0000002cu, 0x0004003du, 0x00000006u, 0x00000031u, 0x00000030u,
  0x00050080u, 0x00000006u, 0x00000032u, 0x0000002fu, 0x00000031u, 0x000200feu, 0x00000032u, 0x00010038u,
  0x00050036u, 0x00000006u, 0x0000000au, 0x00000000u, 0x00000007u, 0x000200f8u, 0x0000000bu, 0x00040039u,
  0x00000006u, 0x00000035u, 0x00000008u, 0x00050084u, 0x00000006u, 0x00000037u, 0x00000035u, 0x00000036u,
  0x000200feu, 0x00000037u, 0x00010038u, 0x00050036u, 0x00000002u, 0x0000000fu, 0x00000000u, 0x0000000du,
  0x00030037u, 0x0000000cu, 0x0000000eu, 0x000200f8u, 0x00000010u, 0x00050041u, 0x00000042u, 0x00000043u,
  0x0000003fu, 0x00000041u, 0x0004003du, 0x0000003au, 0x00000044u, 0x00000043u, 0x00040039u, 0x00000006u,
  0x00000045u, 0x0000000au, 0x00060041u, 0x00000046u, 0x00000047u, 0x00000044u, 0x00000041u, 0x00000045u,
  0x0004003du, 0x00000006u, 0x00000048u, 0x0000000eu, 0x000500c4u, 0x00000006u, 0x00000049u, 0x00000025u,
  0x00000048u, 0x000700f1u, 0x00000006u, 0x0000004au, 0x00000047u, 0x00000025u, 0x0000002cu, 0x00000049u,
  0x000100fdu, 0x00010038u, 0x00050036u, 0x00000002u, 0x00000018u, 0x00000000u, 0x00000014u, 0x00030037u,
  0x0000000cu, 0x00000015u, 0x00030037u, 0x0000000cu, 0x00000016u, 0x00030037u, 0x00000013u, 0x00000017u,
  0x000200f8u, 0x00000019u, 0x0004003bu, 0x0000000cu, 0x0000004bu, 0x00000007u, 0x0004003bu, 0x0000000cu,
  0x00000060u, 0x00000007u, 0x00040039u, 0x00000006u, 0x0000004cu, 0x0000000au, 0x0004003du, 0x00000006u,
  0x0000004du, 0x00000015u, 0x00050080u, 0x00000006u, 0x0000004eu, 0x0000004cu, 0x0000004du, 0x0003003eu,
  0x0000004bu, 0x0000004eu, 0x00050041u, 0x00000042u, 0x0000004fu, 0x0000003fu, 0x00000041u, 0x0004003du,
  0x0000003au, 0x00000050u, 0x0000004fu, 0x0004003du, 0x00000006u, 0x00000051u, 0x0000004bu, 0x00050080u,
  0x00000006u, 0x00000052u, 0x00000051u, 0x0000002cu, 0x00050041u, 0x00000053u, 0x00000054u, 0x00000017u,
  0x0000002cu, 0x0004003du, 0x00000011u, 0x00000055u, 0x00000054u, 0x0004007cu, 0x00000006u, 0x00000056u,
  0x00000055u, 0x00060041u, 0x00000046u, 0x00000057u, 0x00000050u, 0x00000041u, 0x00000052u, 0x0005003eu,
  0x00000057u, 0x00000056u, 0x00000002u, 0x00000004u, 0x00050041u, 0x00000042u, 0x00000058u, 0x0000003fu,
  0x00000041u, 0x0004003du, 0x0000003au, 0x00000059u, 0x00000058u, 0x0004003du, 0x00000006u, 0x0000005au,
  0x0000004bu, 0x00050080u, 0x00000006u, 0x0000005bu, 0x0000005au, 0x00000025u, 0x00050041u, 0x00000053u,
  0x0000005cu, 0x00000017u, 0x00000025u, 0x0004003du, 0x00000011u, 0x0000005du, 0x0000005cu, 0x0004007cu,
  0x00000006u, 0x0000005eu, 0x0000005du, 0x00060041u, 0x00000046u, 0x0000005fu, 0x00000059u, 0x00000041u,
  0x0000005bu, 0x0005003eu, 0x0000005fu, 0x0000005eu, 0x00000002u, 0x00000004u, 0x0004003du, 0x00000006u,
  0x00000061u, 0x00000016u, 0x0003003eu, 0x00000060u, 0x00000061u, 0x00050039u, 0x00000002u, 0x00000062u,
  0x0000000fu, 0x00000060u, 0x000100fdu, 0x00010038u, 0x00050036u, 0x00000002u, 0x0000001bu, 0x00000000u,
  0x0000000du, 0x00030037u, 0x0000000cu, 0x0000001au, 0x000200f8u, 0x0000001cu, 0x00050041u, 0x00000042u,
  0x00000063u, 0x0000003fu, 0x00000041u, 0x0004003du, 0x0000003au, 0x00000064u, 0x00000063u, 0x00040039u,
  0x00000006u, 0x00000065u, 0x0000000au, 0x0004003du, 0x00000006u, 0x00000066u, 0x0000001au, 0x00050080u,
  0x00000006u, 0x00000067u, 0x00000065u, 0x00000066u, 0x00060041u, 0x00000046u, 0x00000068u, 0x00000064u,
  0x00000041u, 0x00000067u, 0x000700eau, 0x00000006u, 0x00000069u, 0x00000068u, 0x00000025u, 0x0000002cu,
  0x00000025u, 0x000100fdu, 0x00010038u,
};
/* hit0.intersection: its GLSL, as rayspec generated it */
// #version 460
// #extension GL_EXT_ray_tracing : require
// #extension GL_EXT_buffer_reference : require
// // rayspec case: lavapipe-rejected-report-attribute
// // stage: intersection (hit0.intersection), generated by harness/glsl
//
// // Bindings and layouts from harness/glsl/bindings.h and results/record_layout.h.
// #define RS_BINDING_TLAS 0
// #define RS_BINDING_RAYS 1
// #define RS_BINDING_RECORDS 2
// #define RS_BINDING_COUNTERS 3
// #define RS_BINDING_SCENE 4
// #define RS_BINDING_SBT_TABLES 5
// #define RS_RAY_WORDS 16
// #define RS_LAUNCH_ID gl_LaunchIDEXT
// #define RS_LAUNCH_SIZE gl_LaunchSizeEXT
// #define RS_RECORD_WORDS 61
// #define RS_FIELD_INTERSECTION_RUNS 57u
// #define RS_BIT_INTERSECTION_RUNS 36u
// #define RS_USE_RECORDS
//
// // ---- shaders/common.glsl ----
// // rayspec shared GLSL: buffers and helpers of set 0 (see harness/glsl/bindings.h).
// // Every number below comes from #defines the generator writes before this
// // file (RS_BINDING_*, RS_RAY_WORDS, RS_RECORD_WORDS, RS_FIELD_<NAME> word
// // offsets, RS_BIT_<NAME> written-mask bits); none is retyped here.
// // RS_LAUNCH_ID and RS_LAUNCH_SIZE are gl_LaunchIDEXT and gl_LaunchSizeEXT, or
// // in raygen run as a compute shader the launch id and size it derives from
// // the dispatch (harness/glsl/emit_compute.h).
// // Optional parts, switched on by the generator only where the stage needs them:
// //   RS_USE_RAYS           the rays buffer (raygen)
// //   RS_USE_TLAS           the acceleration structure (stages that trace)
// //   RS_USE_RECORDS        the per-ray record buffer
// //   RS_USE_COUNTERS       the counter buffer
// //   RS_USE_SHADER_RECORD  this stage's shader record data (8 words)
// // Model counterpart: harness/model (records, counters, shader record data).
//
// #ifdef RS_EMPTY_LAYOUT
// // pipeline.layout: empty. The pipeline layout has no descriptor set (and no
// // push constant): every buffer of set 0 below is reached through its device
// // address instead, the address of binding b being word pair b of the address
// // table, whose own address the specialization constants RS_TABLE_LO_ID and
// // RS_TABLE_HI_ID hold (harness/vulkan/address_table.h); the top level is
// // made from its address (accelerationStructureEXT(uvec2)).
// layout(constant_id = RS_TABLE_LO_ID) const uint rs_table_lo = 0u;
// layout(constant_id = RS_TABLE_HI_ID) const uint rs_table_hi = 0u;
// layout(buffer_reference, std430, buffer_reference_align = 8) readonly buffer RsAddressTable {
//   uvec2 address[];
// };
// uvec2 rs_address(uint binding) {
//   return RsAddressTable(uvec2(rs_table_lo, rs_table_hi)).address[binding];
// }
// // The uint words of the buffer of a binding.
// layout(buffer_reference, std430, buffer_reference_align = 4) buffer RsBoundWords {
//   uint words[];
// };
// #define RS_BOUND_WORDS(binding) RsBoundWords(rs_address(binding)).words
// #endif
//
// // Launch index of this ray: (z * height + y) * width + x (a 3D launch's z
// // layers one below the other).
// uint rs_launch_index() {
//   return (RS_LAUNCH_ID.z * RS_LAUNCH_SIZE.y + RS_LAUNCH_ID.y) * RS_LAUNCH_SIZE.x + RS_LAUNCH_ID.x;
// }
//
// // The texel of this launch's ray in an image `width` texels wide: the
// // launch's rays in row-major order, so a launch wider than the device's
// // largest image (a long ray list) folds into rows. For an image of the
// // launch's own size it is gl_LaunchIDEXT.xy. Device side only (the model
// // keeps images at the launch's size); harness/vulkan/case_buffers.h.
// ivec2 rs_image_texel(int width) {
//   const uint i = rs_launch_index();
//   return ivec2(int(i % uint(width)), int(i / uint(width)));
// }
//
// #ifdef RS_USE_TLAS
// #if defined(RS_EMPTY_LAYOUT)
// #define rs_tlas accelerationStructureEXT(rs_address(RS_BINDING_TLAS))
// #elif defined(RS_TLAS_COUNT)
// // Several top levels (scene.instances[].tlas): a trace names one by a constant.
// layout(set = 0, binding = RS_BINDING_TLAS) uniform accelerationStructureEXT rs_tlas[RS_TLAS_COUNT];
// #else
// layout(set = 0, binding = RS_BINDING_TLAS) uniform accelerationStructureEXT rs_tlas;
// #endif
// #endif
//
// #ifdef RS_USE_RAYS
// #ifdef RS_EMPTY_LAYOUT
// #define rs_rays RS_BOUND_WORDS(RS_BINDING_RAYS)
// #else
// layout(set = 0, binding = RS_BINDING_RAYS, std430) readonly buffer RsRays {
//   uint rs_rays[];
// };
// #endif
//
// // One ray of the launch, as packed by packRays (RS_RAY_WORDS words).
// struct RsRay {
//   vec3 origin;
//   float tmin;
//   vec3 direction;
//   float tmax;
//   uint flags, cull_mask, sbt_offset, sbt_stride, miss;
// };
//
// RsRay rs_load_ray(uint index) {
//   uint w = index * RS_RAY_WORDS;
//   RsRay r;
//   r.origin = vec3(uintBitsToFloat(rs_rays[w + 0u]), uintBitsToFloat(rs_rays[w + 1u]),
//                   uintBitsToFloat(rs_rays[w + 2u]));
//   r.tmin = uintBitsToFloat(rs_rays[w + 3u]);
//   r.direction = vec3(uintBitsToFloat(rs_rays[w + 4u]), uintBitsToFloat(rs_rays[w + 5u]),
//                      uintBitsToFloat(rs_rays[w + 6u]));
//   r.tmax = uintBitsToFloat(rs_rays[w + 7u]);
//   r.flags = rs_rays[w + 8u];
//   r.cull_mask = rs_rays[w + 9u];
//   r.sbt_offset = rs_rays[w + 10u];
//   r.sbt_stride = rs_rays[w + 11u];
//   r.miss = rs_rays[w + 12u];
//   return r;
// }
// #endif
//
// #ifdef RS_USE_RECORDS
// // The record words are reached through their device address, held by the
// // small buffer at RS_BINDING_RECORDS: a storage buffer binding is limited to
// // maxStorageBufferRange (128 MiB on lavapipe), and a launch of 2^20 rays
// // already needs more (the generator enables GL_EXT_buffer_reference).
// layout(buffer_reference, std430, buffer_reference_align = 4) buffer RsRecordWords {
//   uint words[];
// };
// #ifdef RS_EMPTY_LAYOUT
// // The words' address read as two uints, not as a reference: a reference
// // loaded through a PhysicalStorageBuffer pointer needs an 8-byte Aligned
// // operand that Debian 12's glslang does not give it (newer spirv-val:
// // VUID-StandaloneSpirv-PhysicalStorageBuffer64-06314).
// layout(buffer_reference, std430, buffer_reference_align = 8) readonly buffer RsRecordsRef {
//   uvec2 words_address;
// };
// #define rs_records RsRecordWords(RsRecordsRef(rs_address(RS_BINDING_RECORDS)).words_address).words
// #elif defined(RS_RECORDS_BOUND)
// // The words bound directly (the Amber export: a script cannot hand a shader an address).
// layout(set = 0, binding = RS_BINDING_RECORDS, std430) buffer RsRecordsBound {
//   uint rs_records_bound[];
// };
// #define rs_records rs_records_bound
// #else
// layout(set = 0, binding = RS_BINDING_RECORDS, std430) readonly buffer RsRecords {
//   RsRecordWords rs_records_ref;
// };
// #define rs_records rs_records_ref.words
// #endif
//
// // First word of this launch's record.
// uint rs_record_base() {
//   return rs_launch_index() * RS_RECORD_WORDS;
// }
//
// // Word 0 of a record: bit mask of the fields written.
// void rs_mark_written(uint bit) {
//   atomicOr(rs_records[rs_record_base()], 1u << bit);
// }
//
// void rs_record_uint(uint offset, uint bit, uint v) {
//   rs_records[rs_record_base() + offset] = v;
//   rs_mark_written(bit);
// }
//
// void rs_record_float(uint offset, uint bit, float v) {
//   rs_records[rs_record_base() + offset] = floatBitsToUint(v);
//   rs_mark_written(bit);
// }
//
// void rs_record_vec2(uint offset, uint bit, vec2 v) {
//   uint w = rs_record_base() + offset;
//   rs_records[w + 0u] = floatBitsToUint(v.x);
//   rs_records[w + 1u] = floatBitsToUint(v.y);
//   rs_mark_written(bit);
// }
//
// void rs_record_vec3(uint offset, uint bit, vec3 v) {
//   uint w = rs_record_base() + offset;
//   rs_records[w + 0u] = floatBitsToUint(v.x);
//   rs_records[w + 1u] = floatBitsToUint(v.y);
//   rs_records[w + 2u] = floatBitsToUint(v.z);
//   rs_mark_written(bit);
// }
//
// void rs_record_vec4(uint offset, uint bit, vec4 v) {
//   uint w = rs_record_base() + offset;
//   rs_records[w + 0u] = floatBitsToUint(v.x);
//   rs_records[w + 1u] = floatBitsToUint(v.y);
//   rs_records[w + 2u] = floatBitsToUint(v.z);
//   rs_records[w + 3u] = floatBitsToUint(v.w);
//   rs_mark_written(bit);
// }
//
// // Reads word i of a field of this launch's record (raygen, for images).
// uint rs_record_word(uint offset, uint i) {
//   return rs_records[rs_record_base() + offset + i];
// }
//
// // Automatic per-ray stage run count (raygen_runs, miss_runs, ...): +1.
// void rs_bump_runs(uint offset) {
//   atomicAdd(rs_records[rs_record_base() + offset], 1u);
// }
//
// // any-hit: the primitive's bit in any_hit_slots; in any_hit_repeats too when
// // it was set already (results/record_layout.h, anyHitSlot).
// void rs_mark_any_hit(uint slots_offset, uint repeats_offset, uint slot) {
//   uint bit = 1u << slot;
//   uint before = atomicOr(rs_records[rs_record_base() + slots_offset], bit);
//   if ((before & bit) != 0u) atomicOr(rs_records[rs_record_base() + repeats_offset], bit);
// }
// #endif
//
// #ifdef RS_USE_COUNTERS
// #ifdef RS_EMPTY_LAYOUT
// #define rs_counters RS_BOUND_WORDS(RS_BINDING_COUNTERS)
// #else
// layout(set = 0, binding = RS_BINDING_COUNTERS, std430) buffer RsCounters {
//   uint rs_counters[];
// };
// #endif
//
// // Global counter `index` (position of its name in the plan's counters): +1.
// void rs_count(uint index) {
//   atomicAdd(rs_counters[index], 1u);
// }
// #endif
//
// #ifdef RS_USE_SHADER_RECORD
// // Every SBT record carries RS_SHADER_RECORD_WORDS data words after its
// // handle (pipeline.sbt.record_data / 4, default 8; all zero unless the case
// // sets them); the parser keeps every read inside them.
// #ifndef RS_SHADER_RECORD_WORDS
// #define RS_SHADER_RECORD_WORDS 8
// #endif
// layout(shaderRecordEXT, std430) buffer RsShaderRecord {
//   uint words[RS_SHADER_RECORD_WORDS];
// } rs_shader_record;
//
// uint rs_shader_record_uint(uint i) {
//   return rs_shader_record.words[i];
// }
//
// float rs_shader_record_float(uint i) {
//   return uintBitsToFloat(rs_shader_record.words[i]);
// }
// #endif
// // ---- end of shaders/common.glsl ----
//
// // ---- shaders/payload.glsl ----
// // rayspec shared GLSL: the ray payload and the callable data.
// // Model counterpart: harness/model (the same fields, the same start values).
//
// // Payload of every trace (location 0 in raygen and as the incoming payload;
// // location 1 for a nested trace). A trace starts with the color and value its
// // statement gives (`trace: {payload: ...}`, 0 where not given) and depth = 1
// // from raygen, the caller's depth + 1 from a nested trace.
// struct RsPayload {
//   vec4 color;
//   uint value;
//   uint depth;
// };
//
// // Callable data of location L (pipeline.callable_data; declared at L in
// // raygen / closest-hit / miss, at L + 1 inside a callable, whose incoming data
// // is at location 0), RsCallDataW<N> when the type has N more words
// // (harness/glsl/emit_call_data.cpp). Fields a `call` does not give are zero.
// struct RsCallData {
//   vec4 color;
//   vec3 position;
//   uint value;
//   vec3 normal;
//   uint pad;
// };
// // ---- end of shaders/payload.glsl ----
//
// // ---- shaders/scene.glsl ----
// // rayspec shared GLSL: the scene data buffer read by intersection programs
// // (aabb_min, aabb_max, sphere_*). Layout, written by packSceneData
// // (harness/glsl/bindings.h), all indices are absolute word indices:
// //   word 0                 instance count N
// //   word 1 + i             geometry table of instance i's BLAS
// //                          (0xFFFFFFFF: null or triangle BLAS)
// //   table[g]               first word of geometry g's boxes
// //   box p of a geometry    6 float words: min xyz, max xyz
// // Assumes gl_InstanceID is the instance's position in the case's instance list.
// // Model counterpart: the model reads the same boxes from the Case.
// // The primitive is the current one's (gl_*), or what RS_HIT_INSTANCE,
// // RS_HIT_GEOMETRY and RS_HIT_PRIMITIVE name where they are defined first (a
// // ray query's candidate: harness/glsl/emit_ray_query.cpp).
// #ifndef RS_HIT_INSTANCE
// #define RS_HIT_INSTANCE uint(gl_InstanceID)
// #define RS_HIT_GEOMETRY uint(gl_GeometryIndexEXT)
// #define RS_HIT_PRIMITIVE uint(gl_PrimitiveID)
// #endif
//
// #ifdef RS_EMPTY_LAYOUT
// #define rs_scene RS_BOUND_WORDS(RS_BINDING_SCENE)
// #else
// layout(set = 0, binding = RS_BINDING_SCENE, std430) readonly buffer RsScene {
//   uint rs_scene[];
// };
// #endif
//
// // First word of the current primitive's box.
// uint rs_scene_box_word() {
//   uint table = rs_scene[1u + RS_HIT_INSTANCE];
//   uint first = rs_scene[table + RS_HIT_GEOMETRY];
//   return first + 6u * RS_HIT_PRIMITIVE;
// }
//
// vec3 rs_aabb_min() {
//   uint w = rs_scene_box_word();
//   return vec3(uintBitsToFloat(rs_scene[w + 0u]), uintBitsToFloat(rs_scene[w + 1u]),
//               uintBitsToFloat(rs_scene[w + 2u]));
// }
//
// vec3 rs_aabb_max() {
//   uint w = rs_scene_box_word();
//   return vec3(uintBitsToFloat(rs_scene[w + 3u]), uintBitsToFloat(rs_scene[w + 4u]),
//               uintBitsToFloat(rs_scene[w + 5u]));
// }
// // ---- end of shaders/scene.glsl ----
//
// // ---- interface of this stage ----
// hitAttributeEXT vec2 rs_attr;
//
// void main() {
//   rs_bump_runs(RS_FIELD_INTERSECTION_RUNS);
//   // ---- program ----
//   rs_attr = vec2(float(uint(gl_PrimitiveID)));
//   reportIntersectionEXT((gl_ObjectRayOriginEXT.z - rs_aabb_max().z), ((uint(gl_GeometryIndexEXT) * 2u) + uint(gl_PrimitiveID)));
// }
static const uint32_t rs_spirv_2[] = {
  0x07230203u, 0x00010400u, 0x0008000bu, 0x00000095u, 0x00000000u, 0x00020011u, 0x0000117fu, 0x00020011u,
  0x000014e3u, 0x0009000au, 0x5f565053u, 0x5f52484bu, 0x73796870u, 0x6c616369u, 0x6f74735fu, 0x65676172u,
  0x6675625fu, 0x00726566u, 0x0006000au, 0x5f565053u, 0x5f52484bu, 0x5f796172u, 0x63617274u, 0x00676e69u,
  0x0006000bu, 0x00000001u, 0x4c534c47u, 0x6474732eu, 0x3035342eu, 0x00000000u, 0x0003000eu, 0x000014e4u,
  0x00000001u, 0x000e000fu, 0x000014c2u, 0x00000004u, 0x6e69616du, 0x00000000u, 0x0000001au, 0x0000001fu,
  0x0000003au, 0x0000004au, 0x0000004cu, 0x00000055u, 0x0000005du, 0x00000080u, 0x00000086u, 0x00030003u,
  0x00000002u, 0x000001ccu, 0x00070004u, 0x455f4c47u, 0x625f5458u, 0x65666675u, 0x65725f72u, 0x65726566u,
  0x0065636eu, 0x00060004u, 0x455f4c47u, 0x725f5458u, 0x745f7961u, 0x69636172u, 0x0000676eu, 0x00040005u,
  0x00000004u, 0x6e69616du, 0x00000000u, 0x00070005u, 0x00000008u, 0x6c5f7372u, 0x636e7561u, 0x6e695f68u,
  0x28786564u, 0x00000000u, 0x00060005u, 0x0000000au, 0x725f7372u, 0x726f6365u, 0x61625f64u, 0x00286573u,
  0x00070005u, 0x0000000fu, 0x625f7372u, 0x5f706d75u, 0x736e7572u, 0x3b317528u, 0x00000000u, 0x00040005u,
  0x0000000eu, 0x7366666fu, 0x00007465u, 0x00070005u, 0x00000011u, 0x735f7372u, 0x656e6563u, 0x786f625fu,
  0x726f775fu, 0x00002864u, 0x00060005u, 0x00000016u, 0x615f7372u, 0x5f626261u, 0x2878616du, 0x00000000u,
  0x00060005u, 0x0000001au, 0x4c5f6c67u, 0x636e7561u, 0x45444968u, 0x00005458u, 0x00070005u, 0x0000001fu,
  0x4c5f6c67u, 0x636e7561u, 0x7a695368u, 0x54584565u, 0x00000000u, 0x00050005u, 0x00000036u, 0x65527352u,
  0x64726f63u, 0x00000073u, 0x00070006u, 0x00000036u, 0x00000000u, 0x725f7372u, 0x726f6365u, 0x725f7364u,
  0x00006665u, 0x00060005u, 0x00000038u, 0x65527352u, 0x64726f63u, 0x64726f57u, 0x00000073u, 0x00050006u,
  0x00000038u, 0x00000000u, 0x64726f77u, 0x00000073u, 0x00030005u, 0x0000003au, 0x00000000u, 0x00040005u,
  0x00000046u, 0x6c626174u, 0x00000065u, 0x00040005u, 0x00000048u, 0x63537352u, 0x00656e65u, 0x00060006u,
  0x00000048u, 0x00000000u, 0x735f7372u, 0x656e6563u, 0x00000000u, 0x00030005u, 0x0000004au, 0x00000000u,
  0x00060005u, 0x0000004cu, 0x495f6c67u, 0x6174736eu, 0x4965636eu, 0x00000044u, 0x00040005u, 0x00000053u,
  0x73726966u, 0x00000074u, 0x00070005u, 0x00000055u, 0x475f6c67u, 0x656d6f65u, 0x49797274u, 0x7865646eu,
  0x00545845u, 0x00060005u, 0x0000005du, 0x505f6c67u, 0x696d6972u, 0x65766974u, 0x00004449u, 0x00030005u,
  0x00000064u, 0x00000077u, 0x00040005u, 0x0000007cu, 0x61726170u, 0x0000006du, 0x00040005u, 0x00000080u,
  0x615f7372u, 0x00727474u, 0x00080005u, 0x00000086u, 0x4f5f6c67u, 0x63656a62u, 0x79615274u, 0x6769724fu,
  0x58456e69u, 0x00000054u, 0x00040047u, 0x0000001au, 0x0000000bu, 0x000014c7u, 0x00040047u, 0x0000001fu,
  0x0000000bu, 0x000014c8u, 0x00040048u, 0x00000036u, 0x00000000u, 0x00000018u, 0x00050048u, 0x00000036u,
  0x00000000u, 0x00000023u, 0x00000000u, 0x00030047u, 0x00000036u, 0x00000002u, 0x00040047u, 0x00000037u,
  0x00000006u, 0x00000004u, 0x00050048u, 0x00000038u, 0x00000000u, 0x00000023u, 0x00000000u, 0x00030047u,
  0x00000038u, 0x00000002u, 0x00040047u, 0x0000003au, 0x00000022u, 0x00000000u, 0x00040047u, 0x0000003au,
  0x00000021u, 0x00000002u, 0x00040047u, 0x00000047u, 0x00000006u, 0x00000004u, 0x00040048u, 0x00000048u,
  0x00000000u, 0x00000018u, 0x00050048u, 0x00000048u, 0x00000000u, 0x00000023u, 0x00000000u, 0x00030047u,
  0x00000048u, 0x00000002u, 0x00040047u, 0x0000004au, 0x00000022u, 0x00000000u, 0x00040047u, 0x0000004au,
  0x00000021u, 0x00000004u, 0x00040047u, 0x0000004cu, 0x0000000bu, 0x00000006u, 0x00040047u, 0x00000055u,
  0x0000000bu, 0x000014e8u, 0x00040047u, 0x0000005du, 0x0000000bu, 0x00000007u, 0x00040047u, 0x00000086u,
  0x0000000bu, 0x000014cbu, 0x00020013u, 0x00000002u, 0x00030021u, 0x00000003u, 0x00000002u, 0x00040015u,
  0x00000006u, 0x00000020u, 0x00000000u, 0x00030021u, 0x00000007u, 0x00000006u, 0x00040020u, 0x0000000cu,
  0x00000007u, 0x00000006u, 0x00040021u, 0x0000000du, 0x00000002u, 0x0000000cu, 0x00030016u, 0x00000013u,
  0x00000020u, 0x00040017u, 0x00000014u, 0x00000013u, 0x00000003u, 0x00030021u, 0x00000015u, 0x00000014u,
  0x00040017u, 0x00000018u, 0x00000006u, 0x00000003u, 0x00040020u, 0x00000019u, 0x00000001u, 0x00000018u,
  0x0004003bu, 0x00000019u, 0x0000001au, 0x00000001u, 0x0004002bu, 0x00000006u, 0x0000001bu, 0x00000002u,
  0x00040020u, 0x0000001cu, 0x00000001u, 0x00000006u, 0x0004003bu, 0x00000019u, 0x0000001fu, 0x00000001u,
  0x0004002bu, 0x00000006u, 0x00000020u, 0x00000001u, 0x0004002bu, 0x00000006u, 0x00000027u, 0x00000000u,
  0x0004002bu, 0x00000006u, 0x00000031u, 0x0000003du, 0x00030027u, 0x00000035u, 0x000014e5u, 0x0003001eu,
  0x00000036u, 0x00000035u, 0x0003001du, 0x00000037u, 0x00000006u, 0x0003001eu, 0x00000038u, 0x00000037u,
  0x00040020u, 0x00000035u, 0x000014e5u, 0x00000038u, 0x00040020u, 0x00000039u, 0x0000000cu, 0x00000036u,
  0x0004003bu, 0x00000039u, 0x0000003au, 0x0000000cu, 0x00040015u, 0x0000003bu, 0x00000020u, 0x00000001u,
  0x0004002bu, 0x0000003bu, 0x0000003cu, 0x00000000u, 0x00040020u, 0x0000003du, 0x0000000cu, 0x00000035u,
  0x00040020u, 0x00000043u, 0x000014e5u, 0x00000006u, 0x0003001du, 0x00000047u, 0x00000006u, 0x0003001eu,
  0x00000048u, 0x00000047u, 0x00040020u, 0x00000049u, 0x0000000cu, 0x00000048u, 0x0004003bu, 0x00000049u,
  0x0000004au, 0x0000000cu, 0x00040020u, 0x0000004bu, 0x00000001u, 0x0000003bu, 0x0004003bu, 0x0000004bu,
  0x0000004cu, 0x00000001u, 0x00040020u, 0x00000050u, 0x0000000cu, 0x00000006u, 0x0004003bu, 0x0000004bu,
  0x00000055u, 0x00000001u, 0x0004002bu, 0x00000006u, 0x0000005cu, 0x00000006u, 0x0004003bu, 0x0000004bu,
  0x0000005du, 0x00000001u, 0x0004002bu, 0x00000006u, 0x00000067u, 0x00000003u, 0x0004002bu, 0x00000006u,
  0x0000006du, 0x00000004u, 0x0004002bu, 0x00000006u, 0x00000073u, 0x00000005u, 0x0004002bu, 0x00000006u,
  0x0000007bu, 0x00000039u, 0x00040017u, 0x0000007eu, 0x00000013u, 0x00000002u, 0x00040020u, 0x0000007fu,
  0x000014dbu, 0x0000007eu, 0x0004003bu, 0x0000007fu, 0x00000080u, 0x000014dbu, 0x00040020u, 0x00000085u,
  0x00000001u, 0x00000014u, 0x0004003bu, 0x00000085u, 0x00000086u, 0x00000001u, 0x00040020u, 0x00000087u,
  0x00000001u, 0x00000013u, 0x00020014u, 0x00000093u, 0x00050036u, 0x00000002u, 0x00000004u, 0x00000000u,
  0x00000003u, 0x000200f8u, 0x00000005u, 0x0004003bu, 0x0000000cu, 0x0000007cu, 0x00000007u, 0x0003003eu,
  0x0000007cu, 0x0000007bu, 0x00050039u, 0x00000002u, 0x0000007du, 0x0000000fu, 0x0000007cu, 0x0004003du,
  0x0000003bu, 0x00000081u, 0x0000005du, 0x0004007cu, 0x00000006u, 0x00000082u, 0x00000081u, 0x00040070u,
  0x00000013u, 0x00000083u, 0x00000082u, 0x00050050u, 0x0000007eu, 0x00000084u, 0x00000083u, 0x00000083u,
  0x0003003eu, 0x00000080u, 0x00000084u, 0x00050041u, 0x00000087u, 0x00000088u, 0x00000086u, 0x0000001bu,
  0x0004003du, 0x00000013u, 0x00000089u, 0x00000088u, 0x00040039u, 0x00000014u, 0x0000008au, 0x00000016u,
  0x00050051u, 0x00000013u, 0x0000008bu, 0x0000008au, 0x00000002u, 0x00050083u, 0x00000013u, 0x0000008cu,
  0x00000089u, 0x0000008bu, 0x0004003du, 0x0000003bu, 0x0000008du, 0x00000055u, 0x0004007cu, 0x00000006u,
  0x0000008eu, 0x0000008du, 0x00050084u, 0x00000006u, 0x0000008fu, 0x0000008eu, 0x0000001bu, 0x0004003du,
  0x0000003bu, 0x00000090u, 0x0000005du, 0x0004007cu, 0x00000006u, 0x00000091u, 0x00000090u, 0x00050080u,
  0x00000006u, 0x00000092u, 0x0000008fu, 0x00000091u, 0x000514d6u, 0x00000093u, 0x00000094u, 0x0000008cu,
  0x00000092u, 0x000100fdu, 0x00010038u, 0x00050036u, 0x00000006u, 0x00000008u, 0x00000000u, 0x00000007u,
  0x000200f8u, 0x00000009u, 0x00050041u, 0x0000001cu, 0x0000001du, 0x0000001au, 0x0000001bu, 0x0004003du,
  0x00000006u, 0x0000001eu, 0x0000001du, 0x00050041u, 0x0000001cu, 0x00000021u, 0x0000001fu, 0x00000020u,
  0x0004003du, 0x00000006u, 0x00000022u, 0x00000021u, 0x00050084u, 0x00000006u, 0x00000023u, 0x0000001eu,
  0x00000022u, 0x00050041u, 0x0000001cu, 0x00000024u, 0x0000001au, 0x00000020u, 0x0004003du, 0x00000006u,
  0x00000025u, 0x00000024u, 0x00050080u, 0x00000006u, 0x00000026u, 0x00000023u, 0x00000025u, 0x00050041u,
  0x0000001cu, 0x00000028u, 0x0000001fu, 0x00000027u, 0x0004003du, 0x00000006u, 0x00000029u, 0x00000028u,
  0x00050084u, 0x00000006u, 0x0000002au, 0x00000026u, 0x00000029u, 0x00050041u, 0x0000001cu, 0x0000002bu,
  0x0000001au, 0x00000027u, 0x0004003du, 0x00000006u, 0x0000002cu, 0x0000002bu, 0x00050080u, 0x00000006u,
  0x0000002du, 0x0000002au, 0x0000002cu, 0x000200feu, 0x0000002du, 0x00010038u, 0x00050036u, 0x00000006u,
  0x0000000au, 0x00000000u, 0x00000007u, 0x000200f8u, 0x0000000bu, 0x00040039u, 0x00000006u, 0x00000030u,
  0x00000008u, 0x00050084u, 0x00000006u, 0x00000032u, 0x00000030u, 0x00000031u, 0x000200feu, 0x00000032u,
  0x00010038u, 0x00050036u, 0x00000002u, 0x0000000fu, 0x00000000u, 0x0000000du, 0x00030037u, 0x0000000cu,
  0x0000000eu, 0x000200f8u, 0x00000010u, 0x00050041u, 0x0000003du, 0x0000003eu, 0x0000003au, 0x0000003cu,
  0x0004003du, 0x00000035u, 0x0000003fu, 0x0000003eu, 0x00040039u, 0x00000006u, 0x00000040u, 0x0000000au,
  0x0004003du, 0x00000006u, 0x00000041u, 0x0000000eu, 0x00050080u, 0x00000006u, 0x00000042u, 0x00000040u,
  0x00000041u, 0x00060041u, 0x00000043u, 0x00000044u, 0x0000003fu, 0x0000003cu, 0x00000042u, 0x000700eau,
  0x00000006u, 0x00000045u, 0x00000044u, 0x00000020u, 0x00000027u, 0x00000020u, 0x000100fdu, 0x00010038u,
  0x00050036u, 0x00000006u, 0x00000011u, 0x00000000u, 0x00000007u, 0x000200f8u, 0x00000012u, 0x0004003bu,
  0x0000000cu, 0x00000046u, 0x00000007u, 0x0004003bu, 0x0000000cu, 0x00000053u, 0x00000007u, 0x0004003du,
  0x0000003bu, 0x0000004du, 0x0000004cu, 0x0004007cu, 0x00000006u, 0x0000004eu, 0x0000004du, 0x00050080u,
  0x00000006u, 0x0000004fu, 0x00000020u, 0x0000004eu, 0x00060041u, 0x00000050u, 0x00000051u, 0x0000004au,
  0x0000003cu, 0x0000004fu, 0x0004003du, 0x00000006u, 0x00000052u, 0x00000051u, 0x0003003eu, 0x00000046u,
  0x00000052u, 0x0004003du, 0x00000006u, 0x00000054u, 0x00000046u, 0x0004003du, 0x0000003bu, 0x00000056u,
  0x00000055u, 0x0004007cu, 0x00000006u, 0x00000057u, 0x00000056u, 0x00050080u, 0x00000006u, 0x00000058u,
  0x00000054u, 0x00000057u, 0x00060041u, 0x00000050u, 0x00000059u, 0x0000004au, 0x0000003cu, 0x00000058u,
  0x0004003du, 0x00000006u, 0x0000005au, 0x00000059u, 0x0003003eu, 0x00000053u, 0x0000005au, 0x0004003du,
  0x00000006u, 0x0000005bu, 0x00000053u, 0x0004003du, 0x0000003bu, 0x0000005eu, 0x0000005du, 0x0004007cu,
  0x00000006u, 0x0000005fu, 0x0000005eu, 0x00050084u, 0x00000006u, 0x00000060u, 0x0000005cu, 0x0000005fu,
  0x00050080u, 0x00000006u, 0x00000061u, 0x0000005bu, 0x00000060u, 0x000200feu, 0x00000061u, 0x00010038u,
  0x00050036u, 0x00000014u, 0x00000016u, 0x00000000u, 0x00000015u, 0x000200f8u, 0x00000017u, 0x0004003bu,
  0x0000000cu, 0x00000064u, 0x00000007u, 0x00040039u, 0x00000006u, 0x00000065u, 0x00000011u, 0x0003003eu,
  0x00000064u, 0x00000065u, 0x0004003du, 0x00000006u, 0x00000066u, 0x00000064u, 0x00050080u, 0x00000006u,
  0x00000068u, 0x00000066u, 0x00000067u, 0x00060041u, 0x00000050u, 0x00000069u, 0x0000004au, 0x0000003cu,
  0x00000068u, 0x0004003du, 0x00000006u, 0x0000006au, 0x00000069u, 0x0004007cu, 0x00000013u, 0x0000006bu,
  0x0000006au, 0x0004003du, 0x00000006u, 0x0000006cu, 0x00000064u, 0x00050080u, 0x00000006u, 0x0000006eu,
  0x0000006cu, 0x0000006du, 0x00060041u, 0x00000050u, 0x0000006fu, 0x0000004au, 0x0000003cu, 0x0000006eu,
  0x0004003du, 0x00000006u, 0x00000070u, 0x0000006fu, 0x0004007cu, 0x00000013u, 0x00000071u, 0x00000070u,
  0x0004003du, 0x00000006u, 0x00000072u, 0x00000064u, 0x00050080u, 0x00000006u, 0x00000074u, 0x00000072u,
  0x00000073u, 0x00060041u, 0x00000050u, 0x00000075u, 0x0000004au, 0x0000003cu, 0x00000074u, 0x0004003du,
  0x00000006u, 0x00000076u, 0x00000075u, 0x0004007cu, 0x00000013u, 0x00000077u, 0x00000076u, 0x00060050u,
  0x00000014u, 0x00000078u, 0x0000006bu, 0x00000071u, 0x00000077u, 0x000200feu, 0x00000078u, 0x00010038u,
};
static const rs_shader rs_shaders[] = {
  {VK_SHADER_STAGE_RAYGEN_BIT_KHR, rs_spirv_0, sizeof rs_spirv_0},
  {VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR, rs_spirv_1, sizeof rs_spirv_1},
  {VK_SHADER_STAGE_INTERSECTION_BIT_KHR, rs_spirv_2, sizeof rs_spirv_2},
};
/* Shader groups: raygens, miss shaders, hit groups, callables (rayspec's group order). */
static const rs_group rs_groups[] = {
  {VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR, 0u, RS_NONE, RS_NONE, RS_NONE},
  {VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR, RS_NONE, 1u, RS_NONE, 2u},
};
#define RS_SHADER_COUNT 3
#define RS_GROUP_COUNT 2
#define RS_MAX_RECURSION 1u
#define RS_NEEDS_RAY_QUERY 0
#define RS_NEEDS_SCALAR_LAYOUT 0
#define RS_COMPUTE 0
#define RS_COMPUTE_GROUPS_X 0u
#define RS_COMPUTE_GROUPS_Y 0u
#define RS_COMPUTE_GROUPS_Z 0u

/* The shader binding table: each record's group (in the order above) and data. */
static const rs_record rs_raygen_record = {0u, 0u, {0}};
static const rs_record rs_miss_records[] = {
  {RS_NONE, 0, {0}},
};
static const rs_record rs_hit_records[] = {
  {1u, 0u, {0}},
};
#define RS_MISS_RECORDS 0
#define RS_HIT_RECORDS 1
#define RS_RECORD_DATA_BYTES 32
#define RS_MISS_PADDING 0
#define RS_HIT_PADDING 0
static const rs_record rs_callable_records[] = {
  {RS_NONE, 0, {0}},
};
#define RS_CALLABLE_RECORDS 0
#define RS_CALLABLE_PADDING 0

/* The rays as rayspec uploads them (16 words each), the launch, the descriptor bindings. */
static const uint32_t rs_rays[] = {
  0xbf400000u, 0x3f000000u, 0x40a00000u, 0x00000000u, 0x00000000u, 0x00000000u, 0xbf800000u, 0x7149f2cau,
  0x00000000u, 0x000000ffu, 0x00000000u, 0x00000001u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u,
};
#define RS_LAUNCH_WIDTH 1u
#define RS_LAUNCH_HEIGHT 1u
#define RS_LAUNCH_DEPTH 1u
#define RS_RAY_COUNT 1u
static const uint32_t rs_binding4_words[] = {
  0x00000001u, 0x00000002u, 0x00000003u, 0xbfc00000u, 0xbfc00000u, 0xc0000000u, 0x3fc00000u, 0x3fc00000u,
  0x00000000u, 0xbf800000u, 0xbf800000u, 0xbf800000u, 0x3f800000u, 0x3f800000u, 0x3f800000u,
};
static const rs_binding rs_bindings[] = {
  {0, RS_BIND_TLAS, NULL, 0},
  {1, RS_BIND_RAYS, NULL, 0},
  {2, RS_BIND_RECORDS, NULL, 0},
  {4, RS_BIND_WORDS, rs_binding4_words, sizeof rs_binding4_words},
};
#define RS_BINDING_COUNT 4u

/* What rayspec's reference model (exact tier) expects: each ray's record, 61 words (a written mask, the fields, the stage run counts), the fields compared. */
#define RS_RECORD_WORDS 61u
#define RS_RECORDS_JUDGED 1
static const uint32_t rs_expected[] = {
  0x00000080u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u,
  0x3f800000u, 0x3f800000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u,
  0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u,
  0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u,
  0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u,
  0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u,
  0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000000u, 0x00000001u, 0x00000000u, 0x00000001u,
  0x00000000u, 0x00000001u, 0x00000000u, 0x00000000u, 0x00000000u,
};
static const rs_field rs_fields[] = {
  {"barycentrics", "R-BUILTIN", 8, 2, 1, 0, 7, 0, 0.0001, 0},
  {"raygen_runs", "R-BUILTIN", 53, 1, 0, 1, 32, 0, 0, 0},
  {"miss_runs", "R-MISS-XOR-CHIT", 54, 1, 0, 1, 33, 0, 0, 0},
  {"closest_hit_runs", "R-MISS-XOR-CHIT", 55, 1, 0, 1, 34, 0, 0, 0},
  {"callable_runs", "R-CALLABLE", 58, 1, 0, 1, 37, 0, 0, 0},
};
#define RS_FIELD_COUNT (sizeof rs_fields / sizeof rs_fields[0])
/* Rays whose behaviour is undefined (R-UB): not judged. */
static const uint8_t rs_undefined[] = {
  0x00,
};
/* Numerically ambiguous rays: the record must be one of the legal answers' records,
   each replayed by the model through the launch ray; or one of the answers the judge
   accepts with a QualityWarning (R-WATERTIGHT, a "should": a double hit or a leak
   at a shared edge or vertex), each with the judge's words (rs_warning_notes); and, where
   the judge tells a double hit by any-hit runs, the most a watertight device runs. */
static const uint32_t rs_replays[] = {
  0
};
static const rs_ambiguous rs_ambiguous_rays[] = {
  {0, 0, 0, 0, 0, RS_NONE, "", ""},
};
#define RS_AMBIGUOUS_COUNT 0u
static const char* const rs_warning_notes[] = {
  "",
};
/* A double hit told by any-hit runs (rs_ambiguous.ahit_limit): */
#define RS_ANY_HIT_DOUBLE_HIT "R-WATERTIGHT: double hit: any-hit ran for more than one of the triangles sharing an edge or vertex"
#define RS_ANY_HIT_RUNS_WORD 56u
/* Rays a device that runs any-hit more than once for a primitive may change
   (R-AHIT-DUP), with the fields it may change: those not judged (an ambiguous one
   not at all). */
static const rs_repeat rs_repeat_rays[] = {
  {0, 0},
};
#define RS_REPEAT_COUNT 0u
/* Rays whose t, object-space origin or hit position the model bounds more widely
   than the field's tolerance (R-PREC), and the widest of them where the case carries
   them into a free field (a colour of hit_t): the bound widens the field's abs. */
static const rs_bound rs_bounds[] = {
  {0, {0, 0, 0, 0, 0}},
};
#define RS_BOUND_COUNT 0u
/* Counters, in the order the shaders count them, with the range the judge allows
   (the model's count, as far as the legal answers of ambiguous rays move it). */
static const rs_counter rs_counters[] = {
  {"", "", 0, 0},
};
#define RS_COUNTER_COUNT 0u

/* The storage images (outputs.images), one texel a ray (r32ui, or rgba32f for a float
   field), at bindings from RS_FIRST_IMAGE_BINDING: each compared with the model's
   texels within the field's tolerance times the image's scale, the pixels of
   ambiguous and undefined rays left out, at most max_failing pixels differing. */
#define RS_IMAGE_WIDTH 1u
#define RS_IMAGE_HEIGHT 1u
#define RS_FIRST_IMAGE_BINDING 6u
#define RS_IMAGE_COUNT 0u
#define RS_IMAGE_SLOTS 1
static const uint32_t rs_image_none[] = {
  0
};
static const rs_image rs_images[] = {
  {"", "", 0, 0, 0, 0, 0u, RS_NONE, 0, 0u, 0u, 0u, 0, rs_image_none},
};



/* ---- Instance, device selection, device functions ----------------------- */

static PFN_vkGetAccelerationStructureBuildSizesKHR rs_build_sizes;
static PFN_vkCreateAccelerationStructureKHR rs_create_as;
static PFN_vkCmdBuildAccelerationStructuresKHR rs_cmd_build;
static PFN_vkGetAccelerationStructureDeviceAddressKHR rs_as_address;
static PFN_vkCreateRayTracingPipelinesKHR rs_create_pipelines;
static PFN_vkGetRayTracingShaderGroupHandlesKHR rs_group_handles;
static PFN_vkCmdTraceRaysKHR rs_cmd_trace;
static PFN_vkCmdWriteAccelerationStructuresPropertiesKHR rs_cmd_write_properties;
static PFN_vkCmdCopyAccelerationStructureKHR rs_cmd_copy;
static PFN_vkCmdCopyAccelerationStructureToMemoryKHR rs_cmd_copy_to_memory;
static PFN_vkCmdCopyMemoryToAccelerationStructureKHR rs_cmd_copy_from_memory;
static PFN_vkGetDeviceAccelerationStructureCompatibilityKHR rs_compatibility;

static VkInstance rs_instance_handle;
static VkPhysicalDevice rs_physical;
static VkDevice rs_device;
static VkQueue rs_queue;
static uint32_t rs_queue_family;
static VkCommandPool rs_pool;

static void rs_check(VkResult r, const char* what) {
  if (r == VK_SUCCESS) return;
  fprintf(stderr, "Vulkan error %d in %s\n", (int)r, what);
  exit(2);
}

static void rs_unsupported(const char* what) {
  printf("NotSupported: %s\n", what);
  exit(77);
}

static int rs_has_extension(VkPhysicalDevice p, const char* name) {
  uint32_t n = 0, i;
  int found = 0;
  VkExtensionProperties* props;
  vkEnumerateDeviceExtensionProperties(p, NULL, &n, NULL);
  props = calloc(n ? n : 1, sizeof *props);
  vkEnumerateDeviceExtensionProperties(p, NULL, &n, props);
  for (i = 0; i < n; ++i) found = found || strcmp(props[i].extensionName, name) == 0;
  free(props);
  return found;
}

static int rs_has_layer(const char* name) {
  uint32_t n = 0, i;
  int found = 0;
  VkLayerProperties* props;
  vkEnumerateInstanceLayerProperties(&n, NULL);
  props = calloc(n ? n : 1, sizeof *props);
  vkEnumerateInstanceLayerProperties(&n, props);
  for (i = 0; i < n; ++i) found = found || strcmp(props[i].layerName, name) == 0;
  free(props);
  return found;
}

static void rs_create_instance(void) {
  VkApplicationInfo app = {VK_STRUCTURE_TYPE_APPLICATION_INFO};
  VkInstanceCreateInfo info = {VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  const char* layer = "VK_LAYER_KHRONOS_validation";
  app.pApplicationName = "rayspec-export";
  app.apiVersion = VK_API_VERSION_1_2;
  info.pApplicationInfo = &app;
#ifdef RAYSPEC_VALIDATION
  if (rs_has_layer(layer)) {
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &layer;
  } else {
    fprintf(stderr, "note: %s is not installed; running without it\n", layer);
  }
#else
  (void)layer;
  (void)rs_has_layer;
#endif
  rs_check(vkCreateInstance(&info, NULL, &rs_instance_handle), "vkCreateInstance");
}

/* The device argv names (an index, or a part of its name), else the first
 * with VK_KHR_ray_tracing_pipeline. */
static void rs_pick_device(int argc, char** argv) {
  uint32_t n = 0, i;
  VkPhysicalDevice* all;
  const char* want = argc > 1 ? argv[1] : NULL;
  char* end = NULL;
  long index = want ? strtol(want, &end, 10) : -1;
  int by_index = want && end && *end == 0;
  vkEnumeratePhysicalDevices(rs_instance_handle, &n, NULL);
  all = calloc(n ? n : 1, sizeof *all);
  vkEnumeratePhysicalDevices(rs_instance_handle, &n, all);
  for (i = 0; i < n && !rs_physical; ++i) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(all[i], &p);
    if (by_index ? (long)i != index : want && !strstr(p.deviceName, want)) continue;
    if (!rs_has_extension(all[i], VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME)) {
      if (want) rs_unsupported("the device named has no VK_KHR_ray_tracing_pipeline");
      continue;
    }
    rs_physical = all[i];
    printf("device: %s\n", p.deviceName);
  }
  free(all);
  if (!rs_physical) rs_unsupported("no device with VK_KHR_ray_tracing_pipeline (or none named so)");
}

/* VK_KHR_ray_query's rayQuery chained onto `on`, where the case's stages run
 * ray queries; NotSupported where the device lacks it. */
static void rs_chain_ray_query(VkPhysicalDeviceRayQueryFeaturesKHR* on_rq,
                               VkPhysicalDeviceFeatures2* on) {
  VkPhysicalDeviceRayQueryFeaturesKHR rq = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  VkPhysicalDeviceFeatures2 have = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &rq};
  if (!RS_NEEDS_RAY_QUERY) return;
  if (!rs_has_extension(rs_physical, VK_KHR_RAY_QUERY_EXTENSION_NAME))
    rs_unsupported("ray queries: the device lacks VK_KHR_ray_query");
  vkGetPhysicalDeviceFeatures2(rs_physical, &have);
  if (!rq.rayQuery) rs_unsupported("ray queries: the device lacks VK_KHR_ray_query's rayQuery");
  on_rq->rayQuery = VK_TRUE;
  on_rq->pNext = on->pNext;
  on->pNext = on_rq;
}

/* VK_KHR_ray_tracing_maintenance1's feature chained onto `on`, where the
 * case queries a structure's size or its bottom-level pointers; NotSupported
 * where the device lacks it. */
static void rs_chain_maintenance1(VkPhysicalDeviceRayTracingMaintenance1FeaturesKHR* on_m1,
                                  VkPhysicalDeviceFeatures2* on) {
  VkPhysicalDeviceRayTracingMaintenance1FeaturesKHR m1 = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_MAINTENANCE_1_FEATURES_KHR};
  VkPhysicalDeviceFeatures2 have = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &m1};
  if (!RS_NEEDS_MAINTENANCE1) return;
  if (!rs_has_extension(rs_physical, VK_KHR_RAY_TRACING_MAINTENANCE_1_EXTENSION_NAME))
    rs_unsupported(
        "scene.build.queries size, bottom_level_pointers: the device lacks "
        "VK_KHR_ray_tracing_maintenance1");
  vkGetPhysicalDeviceFeatures2(rs_physical, &have);
  if (!m1.rayTracingMaintenance1)
    rs_unsupported("scene.build.queries size, bottom_level_pointers: rayTracingMaintenance1");
  on_m1->rayTracingMaintenance1 = VK_TRUE;
  on_m1->pNext = on->pNext;
  on->pNext = on_m1;
}

static void rs_create_device(void) {
  VkPhysicalDeviceAccelerationStructureFeaturesKHR as = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR, &as};
  VkPhysicalDeviceVulkan12Features v12 = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                          &rt};
  VkPhysicalDeviceFeatures2 have = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v12};
  VkPhysicalDeviceAccelerationStructureFeaturesKHR as_on = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
  VkPhysicalDeviceRayTracingPipelineFeaturesKHR rt_on = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_FEATURES_KHR, &as_on};
  VkPhysicalDeviceVulkan12Features v12_on = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                             &rt_on};
  VkPhysicalDeviceFeatures2 on = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v12_on};
  VkPhysicalDeviceRayQueryFeaturesKHR rq_on = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
  VkPhysicalDeviceRayTracingMaintenance1FeaturesKHR m1_on = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_MAINTENANCE_1_FEATURES_KHR};
  const char* extensions[5] = {VK_KHR_RAY_TRACING_PIPELINE_EXTENSION_NAME,
                               VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                               VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};
  uint32_t extension_count = 3;
  float priority = 1.0f;
  VkDeviceQueueCreateInfo queue = {VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  VkDeviceCreateInfo info = {VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &on};
  VkQueueFamilyProperties families[16];
  uint32_t count = 16;
  vkGetPhysicalDeviceFeatures2(rs_physical, &have);
  if (!rt.rayTracingPipeline) rs_unsupported("rayTracingPipeline");
  if (!as.accelerationStructure) rs_unsupported("accelerationStructure");
  if (!v12.bufferDeviceAddress) rs_unsupported("bufferDeviceAddress");
  rt_on.rayTracingPipeline = as_on.accelerationStructure = v12_on.bufferDeviceAddress = VK_TRUE;
  if (RS_NEEDS_SCALAR_LAYOUT && !v12.scalarBlockLayout)
    rs_unsupported(
        "pipeline.sbt.record_layout: a scalar shader record block needs "
        "scalarBlockLayout");
  v12_on.scalarBlockLayout = v12.scalarBlockLayout;
  v12_on.vulkanMemoryModel = v12.vulkanMemoryModel;
  v12_on.vulkanMemoryModelDeviceScope = v12.vulkanMemoryModelDeviceScope;
  on.features.shaderInt64 = have.features.shaderInt64;
  /* the sized scalars a case's locals may use (harness/program/sized_types.h) */
  on.features.shaderInt16 = have.features.shaderInt16;
  on.features.shaderFloat64 = have.features.shaderFloat64;
  v12_on.shaderInt8 = v12.shaderInt8;
  v12_on.shaderFloat16 = v12.shaderFloat16;
  rs_chain_ray_query(&rq_on, &on);
  rs_chain_maintenance1(&m1_on, &on);
  if (RS_NEEDS_RAY_QUERY) extensions[extension_count++] = VK_KHR_RAY_QUERY_EXTENSION_NAME;
  if (RS_NEEDS_MAINTENANCE1)
    extensions[extension_count++] = VK_KHR_RAY_TRACING_MAINTENANCE_1_EXTENSION_NAME;
  vkGetPhysicalDeviceQueueFamilyProperties(rs_physical, &count, families);
  for (rs_queue_family = 0; rs_queue_family < count; ++rs_queue_family)
    if (families[rs_queue_family].queueFlags & VK_QUEUE_COMPUTE_BIT) break;
  if (rs_queue_family == count) rs_unsupported("a queue family with compute");
  queue.queueFamilyIndex = rs_queue_family;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = extension_count;
  info.ppEnabledExtensionNames = extensions;
  rs_check(vkCreateDevice(rs_physical, &info, NULL, &rs_device), "vkCreateDevice");
  vkGetDeviceQueue(rs_device, rs_queue_family, 0, &rs_queue);
}

#define RS_PROC(var, type, name)                    \
  var = (type)vkGetDeviceProcAddr(rs_device, name); \
  if (!var) rs_unsupported(name)

/* The commands that copy structures (scene.build.copy) and ask their sizes. */
static void rs_load_copy_functions(void) {
  RS_PROC(rs_cmd_write_properties, PFN_vkCmdWriteAccelerationStructuresPropertiesKHR,
          "vkCmdWriteAccelerationStructuresPropertiesKHR");
  RS_PROC(rs_cmd_copy, PFN_vkCmdCopyAccelerationStructureKHR, "vkCmdCopyAccelerationStructureKHR");
  RS_PROC(rs_cmd_copy_to_memory, PFN_vkCmdCopyAccelerationStructureToMemoryKHR,
          "vkCmdCopyAccelerationStructureToMemoryKHR");
  RS_PROC(rs_cmd_copy_from_memory, PFN_vkCmdCopyMemoryToAccelerationStructureKHR,
          "vkCmdCopyMemoryToAccelerationStructureKHR");
  RS_PROC(rs_compatibility, PFN_vkGetDeviceAccelerationStructureCompatibilityKHR,
          "vkGetDeviceAccelerationStructureCompatibilityKHR");
}

static void rs_load_functions(void) {
  VkCommandPoolCreateInfo pool = {VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  RS_PROC(rs_build_sizes, PFN_vkGetAccelerationStructureBuildSizesKHR,
          "vkGetAccelerationStructureBuildSizesKHR");
  RS_PROC(rs_create_as, PFN_vkCreateAccelerationStructureKHR, "vkCreateAccelerationStructureKHR");
  RS_PROC(rs_cmd_build, PFN_vkCmdBuildAccelerationStructuresKHR,
          "vkCmdBuildAccelerationStructuresKHR");
  RS_PROC(rs_as_address, PFN_vkGetAccelerationStructureDeviceAddressKHR,
          "vkGetAccelerationStructureDeviceAddressKHR");
  RS_PROC(rs_create_pipelines, PFN_vkCreateRayTracingPipelinesKHR,
          "vkCreateRayTracingPipelinesKHR");
  RS_PROC(rs_group_handles, PFN_vkGetRayTracingShaderGroupHandlesKHR,
          "vkGetRayTracingShaderGroupHandlesKHR");
  RS_PROC(rs_cmd_trace, PFN_vkCmdTraceRaysKHR, "vkCmdTraceRaysKHR");
  rs_load_copy_functions();
  pool.queueFamilyIndex = rs_queue_family;
  rs_check(vkCreateCommandPool(rs_device, &pool, NULL, &rs_pool), "vkCreateCommandPool");
}

/* ---- Buffers and command submission ------------------------------------- */

/* Every buffer host-visible and coherent, with a device address. */
typedef struct {
  VkBuffer buffer;
  VkDeviceMemory memory;
  void* mapped;
  VkDeviceAddress address;
} rs_buffer;

static uint32_t rs_memory_type(uint32_t bits, VkMemoryPropertyFlags want) {
  VkPhysicalDeviceMemoryProperties mp;
  uint32_t i;
  vkGetPhysicalDeviceMemoryProperties(rs_physical, &mp);
  for (i = 0; i < mp.memoryTypeCount; ++i)
    if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return i;
  rs_unsupported("host-visible coherent memory for a buffer");
  return 0;
}

static rs_buffer rs_make_buffer(VkDeviceSize bytes, VkBufferUsageFlags usage, const void* data) {
  rs_buffer b;
  VkBufferCreateInfo info = {VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  VkMemoryAllocateFlagsInfo flags = {VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
  VkMemoryAllocateInfo alloc = {VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, &flags};
  VkBufferDeviceAddressInfo where = {VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
  VkMemoryRequirements req;
  info.size = bytes ? bytes : 16;
  info.usage = usage | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  rs_check(vkCreateBuffer(rs_device, &info, NULL, &b.buffer), "vkCreateBuffer");
  vkGetBufferMemoryRequirements(rs_device, b.buffer, &req);
  flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex =
      rs_memory_type(req.memoryTypeBits,
                     VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  rs_check(vkAllocateMemory(rs_device, &alloc, NULL, &b.memory), "vkAllocateMemory");
  rs_check(vkBindBufferMemory(rs_device, b.buffer, b.memory, 0), "vkBindBufferMemory");
  rs_check(vkMapMemory(rs_device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
  memset(b.mapped, 0, (size_t)info.size);
  if (data && bytes) memcpy(b.mapped, data, (size_t)bytes);
  where.buffer = b.buffer;
  b.address = vkGetBufferDeviceAddress(rs_device, &where);
  return b;
}

/* Everything before (earlier submissions included) made visible to `stage`. */
static void rs_barrier(VkCommandBuffer cmd, VkPipelineStageFlags stage, VkAccessFlags access) {
  VkMemoryBarrier m = {VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  m.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  m.dstAccessMask = access;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, stage, 0, 1, &m, 0, NULL, 0, NULL);
}

static VkCommandBuffer rs_begin(void) {
  VkCommandBufferAllocateInfo alloc = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  VkCommandBufferBeginInfo begin = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  VkCommandBuffer cmd;
  alloc.commandPool = rs_pool;
  alloc.commandBufferCount = 1;
  rs_check(vkAllocateCommandBuffers(rs_device, &alloc, &cmd), "vkAllocateCommandBuffers");
  rs_check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  rs_barrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
             VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
  return cmd;
}

static void rs_submit(VkCommandBuffer cmd) {
  VkSubmitInfo submit = {VK_STRUCTURE_TYPE_SUBMIT_INFO};
  rs_barrier(cmd, VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
  rs_check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  rs_check(vkQueueSubmit(rs_queue, 1, &submit, VK_NULL_HANDLE), "vkQueueSubmit");
  rs_check(vkQueueWaitIdle(rs_queue), "vkQueueWaitIdle");
}

/* ---- Storage images (outputs.images) ------------------------------------ */

/* One image: the storage image, its view, and the host buffer it is copied into. */
typedef struct {
  VkImage image;
  VkImageView view;
  rs_buffer readback;
} rs_image_target;

static uint32_t rs_image_extent[2]; /* every image's width and height */
/* The count as a variable: a loop up to a count of 0 draws no warning. */
static const uint32_t rs_image_count = RS_IMAGE_COUNT;

/* The images' extent, as rayspec's: the launch's, or where that is wider than
   maxImageDimension2D, the rays in order folded into rows as wide as allowed. */
static void rs_choose_image_extent(void) {
  VkPhysicalDeviceProperties p;
  uint64_t rays = (uint64_t)RS_IMAGE_WIDTH * RS_IMAGE_HEIGHT, most, rows;
  vkGetPhysicalDeviceProperties(rs_physical, &p);
  most = p.limits.maxImageDimension2D;
  rs_image_extent[0] = RS_IMAGE_WIDTH;
  rs_image_extent[1] = RS_IMAGE_HEIGHT;
  if (RS_IMAGE_WIDTH <= most && RS_IMAGE_HEIGHT <= most) return;
  rows = (rays + most - 1) / most;
  if (rows > most) rs_unsupported("an image of the launch's rays within maxImageDimension2D");
  rs_image_extent[0] = (uint32_t)most;
  rs_image_extent[1] = (uint32_t)rows;
}

static rs_image_target rs_make_image(const rs_image* im) {
  VkImageCreateInfo info = {VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  VkImageViewCreateInfo view = {VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  VkMemoryAllocateInfo alloc = {VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  VkMemoryRequirements req;
  VkDeviceMemory memory;
  rs_image_target t;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = im->is_float ? VK_FORMAT_R32G32B32A32_SFLOAT : VK_FORMAT_R32_UINT;
  info.extent.width = rs_image_extent[0];
  info.extent.height = rs_image_extent[1];
  info.extent.depth = 1;
  info.mipLevels = info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
               VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  rs_check(vkCreateImage(rs_device, &info, NULL, &t.image), "vkCreateImage");
  vkGetImageMemoryRequirements(rs_device, t.image, &req);
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = rs_memory_type(req.memoryTypeBits, 0);
  rs_check(vkAllocateMemory(rs_device, &alloc, NULL, &memory), "vkAllocateMemory");
  rs_check(vkBindImageMemory(rs_device, t.image, memory, 0), "vkBindImageMemory");
  view.image = t.image;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = info.format;
  view.subresourceRange.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
  view.subresourceRange.levelCount = view.subresourceRange.layerCount = 1;
  rs_check(vkCreateImageView(rs_device, &view, NULL, &t.view), "vkCreateImageView");
  t.readback = rs_make_buffer(
      (VkDeviceSize)rs_image_extent[0] * rs_image_extent[1] * (im->is_float ? 16 : 4),
      VK_BUFFER_USAGE_TRANSFER_DST_BIT, NULL);
  return t;
}

static const VkImageSubresourceRange rs_whole_image = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};

/* Before the launch: each image in the general layout, cleared to zero. */
static void rs_clear_images(VkCommandBuffer cmd, const rs_image_target* images) {
  const VkClearColorValue zero = {{0, 0, 0, 0}};
  uint32_t i;
  for (i = 0; i < rs_image_count; ++i) {
    VkImageMemoryBarrier b = {VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    b.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = images[i].image;
    b.subresourceRange = rs_whole_image;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                         0, NULL, 0, NULL, 1, &b);
    vkCmdClearColorImage(cmd, images[i].image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &rs_whole_image);
  }
  rs_barrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
             VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
}

/* After the launch: each image copied into its host buffer (tightly packed rows). */
static void rs_copy_images(VkCommandBuffer cmd, const rs_image_target* images) {
  uint32_t i;
  rs_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  for (i = 0; i < rs_image_count; ++i) {
    VkBufferImageCopy copy;
    memset(&copy, 0, sizeof copy);
    copy.imageSubresource.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
    copy.imageSubresource.layerCount = 1;
    copy.imageExtent.width = rs_image_extent[0];
    copy.imageExtent.height = rs_image_extent[1];
    copy.imageExtent.depth = 1;
    vkCmdCopyImageToBuffer(cmd, images[i].image, VK_IMAGE_LAYOUT_GENERAL, images[i].readback.buffer,
                           1, &copy);
  }
}

/* ---- Acceleration structures -------------------------------------------- */

/* The structures of one level, bottom or top, as rayspec's builds make them
   (harness/vulkan/level_builds.cpp): each built from the scene as
   first built, then updated to each later state (scene.update) and copied
   (scene.build.copy) where the case orders it. */
#define RS_MAX_LEVEL (RS_BLAS_COUNT > RS_TLAS_COUNT ? RS_BLAS_COUNT : RS_TLAS_COUNT)
typedef struct {
  VkAccelerationStructureGeometryKHR geos[RS_MAX_GEOMETRIES];
  VkAccelerationStructureBuildRangeInfoKHR ranges[RS_MAX_GEOMETRIES];
  uint32_t count;
} rs_inputs;
typedef struct {
  VkAccelerationStructureTypeKHR type;
  const char* name;             /* "BLAS", "TLAS" */
  uint32_t count;               /* its structures */
  uint32_t index[RS_MAX_LEVEL]; /* each one's BLAS or top level */
  VkAccelerationStructureKHR handle[RS_MAX_LEVEL];
  VkDeviceSize built[RS_MAX_LEVEL]; /* accelerationStructureSize as first built */
  VkDeviceSize size[RS_MAX_LEVEL];  /* the size the current structure was created with */
  VkDeviceSize room[RS_MAX_LEVEL];  /* room for a build: 0 in a compacted copy */
  VkDeviceSize build_scratch[RS_MAX_LEVEL], update_scratch[RS_MAX_LEVEL];
  /* the inputs of structure `index` in state `state` (0: as first built) */
  void (*describe)(uint32_t state, uint32_t index, rs_inputs* in);
} rs_level;

/* Each BLAS's address once the bottom levels are final (0: not built). */
static VkDeviceAddress rs_blas_address[RS_BLAS_COUNT];

/* A structure of `size` bytes over a buffer of its own. */
static VkAccelerationStructureKHR rs_create_structure(VkAccelerationStructureTypeKHR type,
                                                      VkDeviceSize size) {
  VkAccelerationStructureCreateInfoKHR create = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
  VkAccelerationStructureKHR as;
  rs_buffer storage =
      rs_make_buffer(size, VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR, NULL);
  create.buffer = storage.buffer;
  create.size = size;
  create.type = type;
  rs_check(rs_create_as(rs_device, &create, NULL, &as), "vkCreateAccelerationStructureKHR");
  return as;
}

static VkDeviceAddress rs_structure_address(VkAccelerationStructureKHR as) {
  VkAccelerationStructureDeviceAddressInfoKHR where = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
  where.accelerationStructure = as;
  return rs_as_address(rs_device, &where);
}

static VkAccelerationStructureBuildGeometryInfoKHR rs_build_info(
    VkAccelerationStructureTypeKHR type, const rs_inputs* in) {
  VkAccelerationStructureBuildGeometryInfoKHR info = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  info.type = type;
  info.flags = RS_BUILD_FLAGS;
  info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  info.geometryCount = in->count;
  info.pGeometries = in->geos;
  return info;
}

/* One build (src VK_NULL_HANDLE) or update (MODE_UPDATE from src) into dst,
   by its own submission, in scratch of scratch_size bytes. */
static void rs_build_into(VkAccelerationStructureTypeKHR type, VkAccelerationStructureKHR src,
                          VkAccelerationStructureKHR dst, const rs_inputs* in,
                          VkDeviceSize scratch_size) {
  VkAccelerationStructureBuildGeometryInfoKHR info = rs_build_info(type, in);
  const VkAccelerationStructureBuildRangeInfoKHR* ranges = in->ranges;
  rs_buffer scratch = rs_make_buffer(scratch_size + 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, NULL);
  VkCommandBuffer cmd;
  if (src != VK_NULL_HANDLE) info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_UPDATE_KHR;
  info.srcAccelerationStructure = src;
  info.dstAccelerationStructure = dst;
  info.scratchData.deviceAddress = (scratch.address + 255) & ~(VkDeviceAddress)255;
  cmd = rs_begin();
  rs_cmd_build(cmd, 1, &info, &ranges);
  rs_submit(cmd);
}

/* Structure i of the level built from the first state: created at the size
   the device asks for, its scratch sizes kept for its updates. */
static void rs_build_first(rs_level* l, uint32_t i) {
  VkAccelerationStructureBuildSizesInfoKHR sizes = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
  VkAccelerationStructureBuildGeometryInfoKHR info;
  uint32_t max_primitives[RS_MAX_GEOMETRIES], g;
  rs_inputs in;
  l->describe(0, l->index[i], &in);
  for (g = 0; g < in.count; ++g) max_primitives[g] = in.ranges[g].primitiveCount;
  info = rs_build_info(l->type, &in);
  rs_build_sizes(rs_device, VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info, max_primitives,
                 &sizes);
  l->built[i] = l->size[i] = l->room[i] = sizes.accelerationStructureSize;
  l->build_scratch[i] = sizes.buildScratchSize;
  l->update_scratch[i] = sizes.updateScratchSize;
  l->handle[i] = rs_create_structure(l->type, sizes.accelerationStructureSize);
  rs_build_into(l->type, VK_NULL_HANDLE, l->handle[i], &in, sizes.buildScratchSize);
}

/* Structure i updated to `state` (R-AS-UPDATE): in place, or into a new
   structure (scene.build.update_into other); a top level rebuilt instead
   (scene.build.tlas_update rebuild, MODE_BUILD), into a new structure of its
   build size where it has no room for a build (a compacted copy). */
static void rs_update(rs_level* l, uint32_t state, uint32_t i) {
  const int rebuild = RS_TLAS_REBUILT && l->type == VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
  VkAccelerationStructureKHR dst = l->handle[i];
  rs_inputs in;
  l->describe(state, l->index[i], &in);
  if (RS_UPDATE_INTO_OTHER || (rebuild && l->room[i] < l->built[i])) {
    dst = rs_create_structure(l->type, l->built[i]);
    l->size[i] = l->room[i] = l->built[i];
  }
  rs_build_into(l->type, rebuild ? VK_NULL_HANDLE : l->handle[i], dst, &in,
                rebuild ? l->build_scratch[i] : l->update_scratch[i]);
  l->handle[i] = dst;
}

static const VkBufferUsageFlags rs_input_usage =
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR;

static VkDeviceAddress rs_input(const uint8_t* bytes, size_t n) {
  return n ? rs_make_buffer(n, rs_input_usage, bytes).address : 0;
}

/* ---- Copies of acceleration structures (scene.build.copy, R-AS-COPY) ---- */

static void rs_copy_failed(const rs_level* l, uint32_t i, const char* what,
                           unsigned long long bytes) {
  printf("FAIL: R-AS-COPY: %s %u: %s (%llu bytes)\n", l->name, (unsigned)l->index[i], what, bytes);
  exit(1);
}

/* A property of each structure of the level written into a new query pool
   (vkCmdWriteAccelerationStructuresPropertiesKHR) after the builds. */
static VkQueryPool rs_write_properties(const rs_level* l, VkQueryType type) {
  VkQueryPoolCreateInfo info = {VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  VkQueryPool pool;
  VkCommandBuffer cmd;
  info.queryType = type;
  info.queryCount = l->count;
  rs_check(vkCreateQueryPool(rs_device, &info, NULL, &pool), "vkCreateQueryPool");
  cmd = rs_begin();
  vkCmdResetQueryPool(cmd, pool, 0, l->count);
  rs_cmd_write_properties(cmd, l->count, l->handle, type, pool, 0);
  rs_submit(cmd);
  return pool;
}

/* The pool's `count` results, 64-bit, waited for: `words` words each (2:
   the value and, with VK_QUERY_RESULT_WITH_AVAILABILITY_BIT in flags, its
   availability). */
static void rs_pool_results(VkQueryPool pool, uint32_t count, uint32_t words,
                            VkQueryResultFlags flags, uint64_t* out) {
  rs_check(vkGetQueryPoolResults(rs_device, pool, 0, count, (size_t)count * words * 8, out,
                                 (VkDeviceSize)words * 8,
                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT | flags),
           "vkGetQueryPoolResults");
}

/* A size of each structure of the level as the device reports it
   (compacted or serialized). */
static void rs_query_sizes(const rs_level* l, VkQueryType type, VkDeviceSize* out) {
  uint64_t values[RS_MAX_LEVEL];
  uint32_t i;
  rs_pool_results(rs_write_properties(l, type), l->count, 1, 0, values);
  for (i = 0; i < l->count; ++i) out[i] = values[i];
}

/* Clones at each structure's size, or compacted copies at the compacted
   size the device reports (R-AS-COPY), by one submission. */
static void rs_copy_level(rs_level* l, int compact) {
  VkCopyAccelerationStructureInfoKHR copy = {
      VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR};
  VkAccelerationStructureKHR to[RS_MAX_LEVEL];
  VkDeviceSize sizes[RS_MAX_LEVEL];
  VkCommandBuffer cmd;
  uint32_t i;
  if (compact)
    rs_query_sizes(l, VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR, sizes);
  else
    memcpy(sizes, l->size, sizeof sizes);
  for (i = 0; i < l->count; ++i) {
    if (sizes[i] == 0 || sizes[i] > l->size[i])
      rs_copy_failed(l, i, "compacted size outside (0, the structure's size]",
                     (unsigned long long)sizes[i]);
    to[i] = rs_create_structure(l->type, sizes[i]);
  }
  cmd = rs_begin();
  copy.mode = compact ? VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR
                      : VK_COPY_ACCELERATION_STRUCTURE_MODE_CLONE_KHR;
  for (i = 0; i < l->count; ++i) {
    copy.src = l->handle[i];
    copy.dst = to[i];
    rs_cmd_copy(cmd, &copy);
  }
  rs_submit(cmd);
  for (i = 0; i < l->count; ++i) {
    l->handle[i] = to[i];
    l->size[i] = sizes[i];
    l->room[i] = compact ? 0 : sizes[i];
  }
}

/* Serialized data: the two UUIDs, then 64-bit sizes (serialized, deserialized). */
#define RS_SERIAL_HEADER (2 * VK_UUID_SIZE + 16)

/* The serialized data checked as rayspec checks it before deserializing:
   the device calls it compatible, its size is the one the query gave. */
static VkDeviceSize rs_check_serialized(const rs_level* l, uint32_t i, const uint8_t* data,
                                        VkDeviceSize queried) {
  VkAccelerationStructureVersionInfoKHR version = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_VERSION_INFO_KHR};
  VkAccelerationStructureCompatibilityKHR compatible =
      VK_ACCELERATION_STRUCTURE_COMPATIBILITY_INCOMPATIBLE_KHR;
  uint64_t serialized, deserialized;
  version.pVersionData = data;
  rs_compatibility(rs_device, &version, &compatible);
  if (compatible != VK_ACCELERATION_STRUCTURE_COMPATIBILITY_COMPATIBLE_KHR)
    rs_copy_failed(l, i, "the device calls its own serialized data incompatible",
                   (unsigned long long)queried);
  memcpy(&serialized, data + 2 * VK_UUID_SIZE, 8);
  memcpy(&deserialized, data + 2 * VK_UUID_SIZE + 8, 8);
  if (serialized != queried)
    rs_copy_failed(l, i, "serialized data names another size than the query gave",
                   (unsigned long long)serialized);
  return deserialized;
}

/* A level's structures serialized into host-visible memory, each at the
   size the query reports and at a 256-byte aligned address. */
typedef struct {
  rs_buffer memory;
  VkDeviceAddress at[RS_MAX_LEVEL]; /* each one's address */
  VkDeviceSize sizes[RS_MAX_LEVEL]; /* each one's serialization size */
} rs_serialized;

static const uint8_t* rs_serialized_data(const rs_serialized* s, uint32_t i) {
  return (const uint8_t*)s->memory.mapped + (s->at[i] - s->memory.address);
}

/* The serialization sizes asked (each at least the header, else a FAIL:
   rayspec stops there before anything is written past a region), then every
   structure serialized, readable by the host once this returns. */
static void rs_serialize(const rs_level* l, rs_serialized* s) {
  VkCopyAccelerationStructureToMemoryInfoKHR out = {
      VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_TO_MEMORY_INFO_KHR};
  VkDeviceSize offsets[RS_MAX_LEVEL], total = 0;
  VkDeviceAddress base;
  VkCommandBuffer cmd;
  uint32_t i;
  rs_query_sizes(l, VK_QUERY_TYPE_ACCELERATION_STRUCTURE_SERIALIZATION_SIZE_KHR, s->sizes);
  for (i = 0; i < l->count; ++i) {
    if (s->sizes[i] < RS_SERIAL_HEADER)
      rs_copy_failed(l, i,
                     "the serialization size query gave less than the header every serialized "
                     "structure holds",
                     (unsigned long long)s->sizes[i]);
    offsets[i] = total;
    total += (s->sizes[i] + 255) & ~(VkDeviceSize)255;
  }
  s->memory =
      rs_make_buffer(total + 256, rs_input_usage | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, NULL);
  base = (s->memory.address + 255) & ~(VkDeviceAddress)255;
  cmd = rs_begin();
  out.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_SERIALIZE_KHR;
  for (i = 0; i < l->count; ++i) {
    s->at[i] = base + offsets[i];
    out.src = l->handle[i];
    out.dst.deviceAddress = s->at[i];
    rs_cmd_copy_to_memory(cmd, &out);
  }
  rs_submit(cmd);
}

/* Each structure serialized, checked, and deserialized into a new structure
   of the size its data names. */
static void rs_serialize_level(rs_level* l) {
  VkCopyMemoryToAccelerationStructureInfoKHR back = {
      VK_STRUCTURE_TYPE_COPY_MEMORY_TO_ACCELERATION_STRUCTURE_INFO_KHR};
  static rs_serialized s;
  VkCommandBuffer cmd;
  uint32_t i;
  rs_serialize(l, &s);
  cmd = rs_begin();
  back.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_DESERIALIZE_KHR;
  for (i = 0; i < l->count; ++i) {
    l->size[i] = l->room[i] = rs_check_serialized(l, i, rs_serialized_data(&s, i), s.sizes[i]);
    l->handle[i] = rs_create_structure(l->type, l->size[i]);
    back.src.deviceAddress = s.at[i];
    back.dst = l->handle[i];
    rs_cmd_copy_from_memory(cmd, &back);
  }
  rs_submit(cmd);
}

/* The level's structures replaced by their copies (scene.build.copy). */
static void rs_copy_structures(rs_level* l) {
  if (!l->count) return;
  if (RS_COPY == RS_COPY_SERIALIZE)
    rs_serialize_level(l);
  else if (RS_COPY != RS_COPY_NONE)
    rs_copy_level(l, RS_COPY == RS_COPY_COMPACT);
}

/* ---- Structure queries (scene.build.queries) held to the specification -- */

/* Each answer that breaks a guarantee: printed, counted into the verdict. */
static int rs_structure_failures;

static void rs_query_finding(const rs_level* l, uint32_t i, const char* rule, const char* what) {
  printf("FAIL: %s: %s %u: %s\n", rule, l->name, (unsigned)l->index[i], what);
  ++rs_structure_failures;
}

/* A finding with the value observed and what it is held to. */
static void rs_query_numbers(const rs_level* l, uint32_t i, const char* rule, const char* what,
                             unsigned long long observed, unsigned long long against) {
  rs_query_finding(l, i, rule, what);
  printf("  observed %llu, against %llu\n", observed, against);
}

/* R-AS-QUERY-AVAILABILITY: each query available after the wait, its value
   the same read with the availability word; R-AS-QUERY-COMPACTED and
   R-AS-QUERY-SIZE: nonzero, at most the size the structure was created with. */
static void rs_check_query(const rs_level* l, VkQueryType type, uint64_t* values) {
  VkQueryPool pool = rs_write_properties(l, type);
  uint64_t pairs[2 * RS_MAX_LEVEL];
  const int sized = type == VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR ||
                    type == VK_QUERY_TYPE_ACCELERATION_STRUCTURE_SIZE_KHR;
  const char* rule = type == VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR
                         ? "R-AS-QUERY-COMPACTED"
                         : "R-AS-QUERY-SIZE";
  uint32_t i;
  rs_pool_results(pool, l->count, 1, 0, values);
  rs_pool_results(pool, l->count, 2, VK_QUERY_RESULT_WITH_AVAILABILITY_BIT, pairs);
  for (i = 0; i < l->count; ++i) {
    if (pairs[2 * i + 1] == 0)
      rs_query_numbers(l, i, "R-AS-QUERY-AVAILABILITY",
                       "the availability word after VK_QUERY_RESULT_WAIT_BIT is 0 (query type)",
                       type, 0);
    if (pairs[2 * i] != values[i])
      rs_query_numbers(l, i, "R-AS-QUERY-AVAILABILITY",
                       "the value read with the availability word differs from the one without",
                       pairs[2 * i], values[i]);
    if (sized && (values[i] == 0 || values[i] > l->size[i]))
      rs_query_numbers(l, i, rule, "queried size outside (0, the size it was created with]",
                       values[i], l->size[i]);
  }
}

/* The device's VkPhysicalDeviceIDProperties::driverUUID. */
static void rs_driver_uuid(uint8_t* uuid) {
  VkPhysicalDeviceIDProperties id = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ID_PROPERTIES};
  VkPhysicalDeviceProperties2 p = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &id};
  vkGetPhysicalDeviceProperties2(rs_physical, &p);
  memcpy(uuid, id.driverUUID, VK_UUID_SIZE);
}

static void rs_print_uuid(const char* what, const uint8_t* uuid) {
  uint32_t k;
  printf("  %s ", what);
  for (k = 0; k < VK_UUID_SIZE; ++k) printf("%02x", uuid[k]);
  printf("\n");
}

/* R-AS-SERIAL-HEADER: the header's driverUUID the device's, its UUIDs
   compatible, its serialized size the queried one. */
static void rs_check_header(const rs_level* l, uint32_t i, const uint8_t* data, uint64_t queried) {
  VkAccelerationStructureVersionInfoKHR version = {
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_VERSION_INFO_KHR};
  VkAccelerationStructureCompatibilityKHR compatible =
      VK_ACCELERATION_STRUCTURE_COMPATIBILITY_INCOMPATIBLE_KHR;
  uint8_t uuid[VK_UUID_SIZE];
  uint64_t serialized;
  rs_driver_uuid(uuid);
  if (memcmp(uuid, data, VK_UUID_SIZE) != 0) {
    rs_query_finding(l, i, "R-AS-SERIAL-HEADER",
                     "serialized header's driverUUID is not the device's driverUUID");
    rs_print_uuid("header driverUUID", data);
    rs_print_uuid("device driverUUID", uuid);
  }
  version.pVersionData = data;
  rs_compatibility(rs_device, &version, &compatible);
  if (compatible != VK_ACCELERATION_STRUCTURE_COMPATIBILITY_COMPATIBLE_KHR)
    rs_query_finding(l, i, "R-AS-SERIAL-HEADER",
                     "the device calls its own serialized header's UUIDs incompatible");
  memcpy(&serialized, data + 2 * VK_UUID_SIZE, 8);
  if (serialized != queried)
    rs_query_numbers(l, i, "R-AS-SERIAL-HEADER",
                     "the header's serialized size is not the serialization size query's",
                     serialized, queried);
}

/* R-AS-SERIAL-POINTERS of top level i: its handle count the pointers
   query's (when asked), each handle the address of a BLAS it references. */
static void rs_check_pointers(const rs_level* l, uint32_t i, const uint8_t* data, uint64_t bytes,
                              const uint64_t* queried) {
  uint64_t count, k, handle;
  uint32_t b;
  memcpy(&count, data + RS_SERIAL_HEADER, 8);
  if (queried && count != *queried)
    rs_query_numbers(l, i, "R-AS-SERIAL-POINTERS",
                     "the header's handle count is not the bottom-level pointers query's", count,
                     *queried);
  if (bytes < RS_SERIAL_HEADER + 8 || count > (bytes - RS_SERIAL_HEADER - 8) / 8) {
    rs_query_numbers(l, i, "R-AS-SERIAL-POINTERS",
                     "the header's handle count is more than the serialized bytes hold", count,
                     bytes);
    return;
  }
  for (k = 0; k < count; ++k) {
    int known = 0;
    memcpy(&handle, data + RS_SERIAL_HEADER + 8 + 8 * k, 8);
    for (b = 0; b < RS_BLAS_COUNT; ++b)
      if (rs_referenced[l->index[i] * RS_BLAS_COUNT + b] && rs_blas_address[b] == handle) known = 1;
    if (!known)
      rs_query_numbers(l, i, "R-AS-SERIAL-POINTERS",
                       "a handle of the header (its index, its value) is no address of a BLAS "
                       "its instances reference",
                       k, handle);
  }
}

/* scene.build.queries of the level's structures, in the case's order (the
   bottom-level pointers of top levels only); then, where a serialization
   size or the pointers were asked, each structure serialized and its header
   checked (rayspec's vulkan/structure_queries.cpp). */
static void rs_query_level(const rs_level* l) {
  uint64_t values[RS_MAX_LEVEL], sizes[RS_MAX_LEVEL], pointers[RS_MAX_LEVEL];
  int top = l->type == VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, serialize = 0, counted = 0;
  static rs_serialized s;
  uint32_t q, i;
  if (!l->count) return;
  for (q = 0; q < rs_query_count; ++q) {
    const VkQueryType type = rs_queries[q];
    const int is_pointers =
        type == VK_QUERY_TYPE_ACCELERATION_STRUCTURE_SERIALIZATION_BOTTOM_LEVEL_POINTERS_KHR;
    if (is_pointers && !top) continue; /* VUID-...-12425: top levels only */
    rs_check_query(l, type, values);
    if (type == VK_QUERY_TYPE_ACCELERATION_STRUCTURE_SERIALIZATION_SIZE_KHR) {
      serialize = 1;
      memcpy(sizes, values, sizeof sizes);
    }
    if (is_pointers) {
      counted = 1;
      memcpy(pointers, values, sizeof pointers);
    }
  }
  if (!serialize && !counted) return;
  rs_serialize(l, &s);
  for (i = 0; i < l->count; ++i) {
    rs_check_header(l, i, rs_serialized_data(&s, i), serialize ? sizes[i] : s.sizes[i]);
    if (top)
      rs_check_pointers(l, i, rs_serialized_data(&s, i), s.sizes[i], counted ? &pointers[i] : NULL);
  }
}

/* ---- The scene built: bottom levels, then the top levels over them ------ */

static void rs_describe_triangles(VkAccelerationStructureGeometryTrianglesDataKHR* t,
                                  const rs_geometry* g) {
  t->sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
  t->vertexFormat = g->format;
  t->vertexStride = g->stride;
  t->maxVertex = g->max_vertex;
  t->indexType = g->index_type;
  t->vertexData.deviceAddress = rs_input(g->vertices, g->vertex_bytes);
  t->indexData.deviceAddress = rs_input(g->indices, g->index_bytes);
  t->transformData.deviceAddress = rs_input(g->transform, g->transform_bytes);
}

static void rs_describe_aabbs(VkAccelerationStructureGeometryAabbsDataKHR* a,
                              const rs_geometry* g) {
  a->sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR;
  a->stride = g->stride;
  a->data.deviceAddress = rs_input(g->vertices, g->vertex_bytes);
}

/* BLAS b's geometries in `state`. */
static void rs_describe_blas(uint32_t state, uint32_t b, rs_inputs* in) {
  const rs_blas* blas = &rs_blases[state * RS_BLAS_COUNT + b];
  uint32_t i;
  memset(in, 0, sizeof *in);
  in->count = blas->geometry_count;
  for (i = 0; i < blas->geometry_count; ++i) {
    const rs_geometry* g = &rs_geometries[blas->first_geometry + i];
    in->geos[i].sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR;
    in->geos[i].geometryType = g->type;
    in->geos[i].flags = g->flags;
    if (g->type == VK_GEOMETRY_TYPE_AABBS_KHR)
      rs_describe_aabbs(&in->geos[i].geometry.aabbs, g);
    else
      rs_describe_triangles(&in->geos[i].geometry.triangles, g);
    in->ranges[i] = g->range;
  }
}

/* Top level `level` in `state`: every instance of the state in order, those
   of the other levels (and those without a BLAS) with reference 0. */
static void rs_describe_tlas(uint32_t state, uint32_t level, rs_inputs* in) {
  VkAccelerationStructureInstanceKHR instances[RS_INSTANCE_COUNT];
  uint32_t i;
  memset(instances, 0, sizeof instances);
  for (i = 0; i < RS_INSTANCE_COUNT; ++i) {
    const rs_instance* inst = &rs_instances[state * RS_INSTANCE_COUNT + i];
    memcpy(&instances[i].transform, inst->transform, sizeof inst->transform);
    instances[i].instanceCustomIndex = inst->custom_index;
    instances[i].mask = inst->mask;
    instances[i].instanceShaderBindingTableRecordOffset = inst->sbt_offset;
    instances[i].flags = inst->flags;
    instances[i].accelerationStructureReference =
        inst->tlas == level && inst->blas != RS_NONE ? rs_blas_address[inst->blas] : 0;
  }
  memset(in, 0, sizeof *in);
  in->count = 1;
  in->geos[0].sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR;
  in->geos[0].geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  in->geos[0].geometry.instances.sType =
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
  in->geos[0].geometry.instances.data.deviceAddress =
      rs_input((const uint8_t*)instances, sizeof instances);
  in->ranges[0].primitiveCount = RS_INSTANCE_COUNT;
}

/* One level: built, then each update in turn, the queries and the copy where
   scene.build.order puts them (RS_QUERY_AT, RS_COPY_AT: before that update;
   after the last: RS_STATE_COUNT - 1). */
static void rs_run_level(rs_level* l) {
  uint32_t i, k;
  for (i = 0; i < l->count; ++i) rs_build_first(l, i);
  for (k = 0; k < RS_STATE_COUNT; ++k) {
    if (k == RS_QUERY_AT) rs_query_level(l);
    if (k == RS_COPY_AT) rs_copy_structures(l);
    if (k + 1 == RS_STATE_COUNT) break;
    for (i = 0; i < l->count; ++i) rs_update(l, k + 1, i);
  }
}

/* NotSupported where the device cannot build from a geometry's vertex format. */
static void rs_check_vertex_formats(void) {
  uint32_t i;
  for (i = 0; i < sizeof rs_geometries / sizeof rs_geometries[0]; ++i) {
    VkFormatProperties p;
    if (rs_geometries[i].type != VK_GEOMETRY_TYPE_TRIANGLES_KHR) continue;
    vkGetPhysicalDeviceFormatProperties(rs_physical, rs_geometries[i].format, &p);
    if (p.bufferFeatures & VK_FORMAT_FEATURE_ACCELERATION_STRUCTURE_VERTEX_BUFFER_BIT_KHR) continue;
    printf(
        "NotSupported: triangles.vertex_format %s: the device cannot build acceleration "
        "structures from it\n",
        rs_geometries[i].format_name);
    exit(77);
  }
}

/* The BLASes some instance of the first state references, then the top
   levels over them as they end up (copied, updated): the top levels'
   structures into `tlas`. */
static void rs_build_scene(VkAccelerationStructureKHR* tlas) {
  static rs_level bottom, top;
  uint32_t i;
  rs_check_vertex_formats();
  bottom.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
  bottom.name = "BLAS";
  bottom.describe = rs_describe_blas;
  for (i = 0; i < RS_BLAS_COUNT; ++i)
    if (rs_blases[i].reached) bottom.index[bottom.count++] = i;
  rs_run_level(&bottom);
  for (i = 0; i < bottom.count; ++i)
    rs_blas_address[bottom.index[i]] = rs_structure_address(bottom.handle[i]);
  top.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
  top.name = "TLAS";
  top.describe = rs_describe_tlas;
  for (i = 0; i < RS_TLAS_COUNT; ++i) top.index[top.count++] = i;
  rs_run_level(&top);
  for (i = 0; i < RS_TLAS_COUNT; ++i) tlas[i] = top.handle[i];
}

/* ---- The ray tracing pipeline ------------------------------------------- */

/* NotSupported where the case recurses deeper than the device allows. */
static void rs_check_recursion(void) {
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rt = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
  VkPhysicalDeviceProperties2 props = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &rt};
  vkGetPhysicalDeviceProperties2(rs_physical, &props);
  if (RS_MAX_RECURSION > rt.maxRayRecursionDepth) {
    printf("NotSupported: max_recursion %u > device maxRayRecursionDepth %u\n",
           (unsigned)RS_MAX_RECURSION, (unsigned)rt.maxRayRecursionDepth);
    exit(77);
  }
}

static VkPipeline rs_create_pipeline(VkPipelineLayout layout) {
  VkPipelineShaderStageCreateInfo stages[RS_SHADER_COUNT];
  VkRayTracingShaderGroupCreateInfoKHR groups[RS_GROUP_COUNT];
  VkRayTracingPipelineCreateInfoKHR info = {VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
  VkPipeline pipeline;
  uint32_t i;
  rs_check_recursion();
  for (i = 0; i < RS_SHADER_COUNT; ++i) {
    VkShaderModuleCreateInfo module = {VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    memset(&stages[i], 0, sizeof stages[i]);
    module.codeSize = rs_shaders[i].bytes;
    module.pCode = rs_shaders[i].code;
    stages[i].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stages[i].stage = rs_shaders[i].stage;
    stages[i].pName = "main";
    rs_check(vkCreateShaderModule(rs_device, &module, NULL, &stages[i].module),
             "vkCreateShaderModule");
  }
  for (i = 0; i < RS_GROUP_COUNT; ++i) {
    memset(&groups[i], 0, sizeof groups[i]);
    groups[i].sType = VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR;
    groups[i].type = rs_groups[i].type;
    groups[i].generalShader =
        rs_groups[i].general == RS_NONE ? VK_SHADER_UNUSED_KHR : rs_groups[i].general;
    groups[i].closestHitShader =
        rs_groups[i].closest_hit == RS_NONE ? VK_SHADER_UNUSED_KHR : rs_groups[i].closest_hit;
    groups[i].anyHitShader =
        rs_groups[i].any_hit == RS_NONE ? VK_SHADER_UNUSED_KHR : rs_groups[i].any_hit;
    groups[i].intersectionShader =
        rs_groups[i].intersection == RS_NONE ? VK_SHADER_UNUSED_KHR : rs_groups[i].intersection;
  }
  info.stageCount = RS_SHADER_COUNT;
  info.pStages = stages;
  info.groupCount = RS_GROUP_COUNT;
  info.pGroups = groups;
  info.maxPipelineRayRecursionDepth = RS_MAX_RECURSION;
  info.layout = layout;
  rs_check(
      rs_create_pipelines(rs_device, VK_NULL_HANDLE, VK_NULL_HANDLE, 1, &info, NULL, &pipeline),
      "vkCreateRayTracingPipelinesKHR");
  return pipeline;
}

/* Raygen as a compute shader (pipeline.traces: ray_query_compute): a compute
   pipeline of the one stage. */
static VkPipeline rs_create_compute_pipeline(VkPipelineLayout layout) {
  VkShaderModuleCreateInfo module = {VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  VkComputePipelineCreateInfo info = {VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  VkPipeline pipeline;
  module.codeSize = rs_shaders[0].bytes;
  module.pCode = rs_shaders[0].code;
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.pName = "main";
  rs_check(vkCreateShaderModule(rs_device, &module, NULL, &info.stage.module),
           "vkCreateShaderModule");
  info.layout = layout;
  rs_check(vkCreateComputePipelines(rs_device, VK_NULL_HANDLE, 1, &info, NULL, &pipeline),
           "vkCreateComputePipelines");
  return pipeline;
}

/* ---- The shader binding table ------------------------------------------- */

static VkDeviceSize rs_align(VkDeviceSize v, VkDeviceSize a) {
  return (v + a - 1) / a * a;
}

typedef struct {
  VkStridedDeviceAddressRegionKHR raygen, miss, hit, callable;
} rs_regions;

/* Writes one region's records at `offset` of the table; the region it makes. */
static VkStridedDeviceAddressRegionKHR rs_region(uint8_t* table, VkDeviceAddress base,
                                                 VkDeviceSize offset, VkDeviceSize stride,
                                                 const rs_record* records, uint32_t count,
                                                 const uint8_t* handles, uint32_t handle_size) {
  VkStridedDeviceAddressRegionKHR r = {0, 0, 0};
  uint32_t i;
  if (!count) return r;
  for (i = 0; i < count; ++i) {
    uint8_t* at = table + offset + i * stride;
    if (records[i].group == RS_NONE) continue;
    memcpy(at, handles + (size_t)records[i].group * handle_size, handle_size);
    memcpy(at + handle_size, records[i].data, records[i].data_words * 4u);
  }
  r.deviceAddress = base + offset;
  r.stride = stride;
  r.size = stride * count;
  return r;
}

/* The regions in table order (raygen, miss, hit, callable): each one's
   records and padding. The raygen region holds one record, unpadded. */
typedef struct {
  const rs_record* records;
  uint32_t count, padding;
} rs_region_records;

static rs_regions rs_write_sbt(VkPipeline pipeline) {
  VkPhysicalDeviceRayTracingPipelinePropertiesKHR rt = {
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_TRACING_PIPELINE_PROPERTIES_KHR};
  VkPhysicalDeviceProperties2 props = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &rt};
  const rs_region_records regions[4] = {
      {&rs_raygen_record, 1, 0},
      {rs_miss_records, RS_MISS_RECORDS, RS_MISS_PADDING},
      {rs_hit_records, RS_HIT_RECORDS, RS_HIT_PADDING},
      {rs_callable_records, RS_CALLABLE_RECORDS, RS_CALLABLE_PADDING}};
  VkStridedDeviceAddressRegionKHR* made[4];
  VkDeviceSize stride[4], at[4], end = 0;
  rs_regions out;
  uint8_t *handles, *bytes;
  VkDeviceAddress base;
  rs_buffer table;
  uint32_t r;
  vkGetPhysicalDeviceProperties2(rs_physical, &props);
  handles = malloc((size_t)RS_GROUP_COUNT * rt.shaderGroupHandleSize);
  rs_check(rs_group_handles(rs_device, pipeline, 0, RS_GROUP_COUNT,
                            (size_t)RS_GROUP_COUNT * rt.shaderGroupHandleSize, handles),
           "vkGetRayTracingShaderGroupHandlesKHR");
  for (r = 0; r < 4; ++r) {
    stride[r] = rs_align(rt.shaderGroupHandleSize + RS_RECORD_DATA_BYTES + regions[r].padding,
                         rt.shaderGroupHandleAlignment);
    if (r && stride[r] > rt.maxShaderGroupStride)
      rs_unsupported("an SBT stride within maxShaderGroupStride");
    at[r] = rs_align(end, rt.shaderGroupBaseAlignment);
    end = at[r] + stride[r] * regions[r].count;
  }
  table = rs_make_buffer(end + rt.shaderGroupBaseAlignment,
                         VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR, NULL);
  base = rs_align(table.address, rt.shaderGroupBaseAlignment);
  bytes = (uint8_t*)table.mapped + (base - table.address);
  made[0] = &out.raygen;
  made[1] = &out.miss;
  made[2] = &out.hit;
  made[3] = &out.callable;
  for (r = 0; r < 4; ++r)
    *made[r] = rs_region(bytes, base, at[r], stride[r], regions[r].records, regions[r].count,
                         handles, rt.shaderGroupHandleSize);
  free(handles);
  return out;
}

/* ---- The descriptor set: the top level and the buffers bound ------------ */

typedef struct {
  rs_buffer rays, records, records_ref, counters;
  rs_buffer words[RS_BINDING_COUNT];      /* each RS_BIND_WORDS binding's, by its index */
  rs_image_target images[RS_IMAGE_SLOTS]; /* in rs_images' order */
} rs_io;

/* The buffers the descriptor set binds: the rays, the records (by address),
   the counters and each binding of fixed words; and the storage images. */
static rs_io rs_make_io(void) {
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  rs_io io;
  uint32_t i;
  memset(&io, 0, sizeof io);
  io.rays = rs_make_buffer(sizeof rs_rays, storage, rs_rays);
  io.records = rs_make_buffer((VkDeviceSize)RS_RAY_COUNT * RS_RECORD_WORDS * 4, storage, NULL);
  io.records_ref = rs_make_buffer(8, storage, &io.records.address);
  io.counters = rs_make_buffer(4 * (RS_COUNTER_COUNT ? RS_COUNTER_COUNT : 1), storage, NULL);
  for (i = 0; i < RS_BINDING_COUNT; ++i)
    if (rs_bindings[i].kind == RS_BIND_WORDS)
      io.words[i] = rs_make_buffer(rs_bindings[i].bytes, storage, rs_bindings[i].words);
  if (rs_image_count) rs_choose_image_extent();
  for (i = 0; i < rs_image_count; ++i) io.images[i] = rs_make_image(&rs_images[i]);
  return io;
}

/* The buffer binding i reads (the top level's binding: none). */
static const rs_buffer* rs_bound_buffer(uint32_t i, const rs_io* io) {
  switch (rs_bindings[i].kind) {
    case RS_BIND_RAYS:
      return &io->rays;
    case RS_BIND_RECORDS:
      return &io->records_ref;
    case RS_BIND_COUNTERS:
      return &io->counters;
    case RS_BIND_WORDS:
      return &io->words[i];
    case RS_BIND_TLAS:
    case RS_BIND_IMAGE:
      break;
  }
  return NULL;
}

static VkDescriptorType rs_descriptor_type(enum rs_binding_kind kind) {
  if (kind == RS_BIND_TLAS) return VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
  return kind == RS_BIND_IMAGE ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE
                               : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

/* The set: the top levels (an array where there are several) and the buffers. */
static VkDescriptorSet rs_bind(VkDescriptorSetLayout* set_layout,
                               const VkAccelerationStructureKHR* tlas, const rs_io* io) {
  VkDescriptorSetLayoutBinding b[RS_BINDING_COUNT];
  VkWriteDescriptorSet w[RS_BINDING_COUNT];
  VkDescriptorBufferInfo buffers[RS_BINDING_COUNT];
  VkDescriptorImageInfo images[RS_BINDING_COUNT];
  VkWriteDescriptorSetAccelerationStructureKHR as = {
      VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
  VkDescriptorPoolSize sizes[3] = {{VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, RS_TLAS_COUNT},
                                   {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, RS_BINDING_COUNT},
                                   {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, RS_BINDING_COUNT}};
  VkDescriptorSetLayoutCreateInfo layout = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  VkDescriptorPoolCreateInfo pool = {VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  VkDescriptorSetAllocateInfo alloc = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  VkDescriptorPool pool_handle;
  VkDescriptorSet set;
  uint32_t i;
  as.accelerationStructureCount = RS_TLAS_COUNT;
  as.pAccelerationStructures = tlas;
  for (i = 0; i < RS_BINDING_COUNT; ++i) {
    const rs_buffer* src = rs_bound_buffer(i, io);
    int is_tlas = rs_bindings[i].kind == RS_BIND_TLAS;
    int is_image = rs_bindings[i].kind == RS_BIND_IMAGE;
    memset(&b[i], 0, sizeof b[i]);
    memset(&w[i], 0, sizeof w[i]);
    b[i].binding = w[i].dstBinding = rs_bindings[i].binding;
    b[i].descriptorType = w[i].descriptorType = rs_descriptor_type(rs_bindings[i].kind);
    b[i].descriptorCount = w[i].descriptorCount = is_tlas ? RS_TLAS_COUNT : 1;
    b[i].stageFlags = VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR |
                      VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR | VK_SHADER_STAGE_ANY_HIT_BIT_KHR |
                      VK_SHADER_STAGE_INTERSECTION_BIT_KHR | VK_SHADER_STAGE_CALLABLE_BIT_KHR |
                      VK_SHADER_STAGE_COMPUTE_BIT;
    w[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    buffers[i].buffer = src ? src->buffer : VK_NULL_HANDLE;
    buffers[i].offset = 0;
    buffers[i].range = VK_WHOLE_SIZE;
    memset(&images[i], 0, sizeof images[i]);
    if (is_image) {
      images[i].imageView = io->images[rs_bindings[i].binding - RS_FIRST_IMAGE_BINDING].view;
      images[i].imageLayout = VK_IMAGE_LAYOUT_GENERAL;
    }
    if (is_tlas)
      w[i].pNext = &as;
    else if (is_image)
      w[i].pImageInfo = &images[i];
    else
      w[i].pBufferInfo = &buffers[i];
  }
  layout.bindingCount = RS_BINDING_COUNT;
  layout.pBindings = b;
  rs_check(vkCreateDescriptorSetLayout(rs_device, &layout, NULL, set_layout),
           "vkCreateDescriptorSetLayout");
  pool.maxSets = 1;
  pool.poolSizeCount = 3;
  pool.pPoolSizes = sizes;
  rs_check(vkCreateDescriptorPool(rs_device, &pool, NULL, &pool_handle), "vkCreateDescriptorPool");
  alloc.descriptorPool = pool_handle;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = set_layout;
  rs_check(vkAllocateDescriptorSets(rs_device, &alloc, &set), "vkAllocateDescriptorSets");
  for (i = 0; i < RS_BINDING_COUNT; ++i) w[i].dstSet = set;
  vkUpdateDescriptorSets(rs_device, RS_BINDING_COUNT, w, 0, NULL);
  return set;
}

/* ---- The comparison ----------------------------------------------------- */

static float rs_float(uint32_t w) {
  float f;
  memcpy(&f, &w, 4);
  return f;
}

static double rs_abs(double v) {
  return v < 0 ? -v : v;
}
static int rs_nan(float v) {
  return v != v;
}

static int rs_written(const uint32_t* rec, const rs_field* f) {
  return f->automatic || ((rec[f->bit / 32] >> (f->bit % 32)) & 1u);
}

/* What a ray's fields are compared under: the fields left out (bit
   rs_field.bit) and the ray's bounds (rs_bound.by). */
typedef struct {
  uint64_t skip;
  const float* widen;
} rs_ray_rules;

/* One field of a record as the expected one has it (the judge's sameField):
   floats within the field's tolerance, its abs widened to the ray's bound. */
static int rs_same(const rs_field* f, const uint32_t* d, const uint32_t* m, const float* widen) {
  const double abs = f->abs > widen[f->bound] ? f->abs : (double)widen[f->bound];
  uint32_t k;
  if (rs_written(d, f) != rs_written(m, f)) return 0;
  if (!rs_written(d, f)) return 1;
  for (k = 0; k < f->words; ++k) {
    uint32_t dw = d[f->offset + k], mw = m[f->offset + k];
    if (!f->is_float) {
      if (dw != mw) return 0;
    } else {
      float df = rs_float(dw), mf = rs_float(mw);
      double diff = rs_abs((double)df - (double)mf), scale = rs_abs((double)mf);
      if (rs_nan(df) || rs_nan(mf)) {
        if (!(rs_nan(df) && rs_nan(mf))) return 0;
      } else if (df != mf && diff > abs + f->rel * (scale > 1.0 ? scale : 1.0)) {
        return 0;
      }
    }
  }
  return 1;
}

static void rs_print_value(const rs_field* f, const uint32_t* rec) {
  uint32_t k;
  if (!rs_written(rec, f)) {
    printf("(not written)");
    return;
  }
  for (k = 0; k < f->words; ++k) {
    if (f->is_float)
      printf(k ? " %.9g" : "%.9g", (double)rs_float(rec[f->offset + k]));
    else
      printf(k ? " %u" : "%u", rec[f->offset + k]);
  }
}

/* The counts as variables: a loop up to a count of 0 draws no warning. */
static const uint32_t rs_ambiguous_count = RS_AMBIGUOUS_COUNT;
static const uint32_t rs_counter_count = RS_COUNTER_COUNT;
static const uint32_t rs_ray_count = RS_RECORDS_JUDGED ? RS_RAY_COUNT : 0; /* rays judged */
static const uint32_t rs_repeat_count = RS_REPEAT_COUNT;
static const uint32_t rs_bound_count = RS_BOUND_COUNT;

static const rs_ambiguous* rs_ambiguity(uint32_t ray) {
  uint32_t i;
  for (i = 0; i < rs_ambiguous_count; ++i)
    if (rs_ambiguous_rays[i].ray == ray) return &rs_ambiguous_rays[i];
  return NULL;
}

/* The ray's rules: the fields a repeated any-hit may change (R-AHIT-DUP),
   not judged, and the model's wider bounds of its t, origin and position. */
static rs_ray_rules rs_rules_of(uint32_t ray) {
  static const float none[5] = {0, 0, 0, 0, 0};
  rs_ray_rules r;
  uint32_t i;
  r.skip = 0;
  r.widen = none;
  for (i = 0; i < rs_repeat_count; ++i)
    if (rs_repeat_rays[i].ray == ray) r.skip = rs_repeat_rays[i].fields;
  for (i = 0; i < rs_bound_count; ++i)
    if (rs_bounds[i].ray == ray) r.widen = rs_bounds[i].by;
  return r;
}

/* The first field of `d` that differs from `m` under `r`, or NULL. */
static const rs_field* rs_differs(const uint32_t* d, const uint32_t* m, rs_ray_rules r) {
  uint32_t i;
  for (i = 0; i < RS_FIELD_COUNT; ++i)
    if (!((r.skip >> rs_fields[i].bit) & 1u) && !rs_same(&rs_fields[i], d, m, r.widen))
      return &rs_fields[i];
  return NULL;
}

static void rs_print_difference(const rs_field* f, const uint32_t* expected, const uint32_t* d) {
  printf("field '%s': expected ", f->name);
  rs_print_value(f, expected);
  printf(", observed ");
  rs_print_value(f, d);
  printf("\n");
}

/* The rays the judge warns of (R-WATERTIGHT, a "should": a double hit or a
   leak at a shared edge or vertex): the first few printed, every one counted. */
#define RS_WARNINGS_PRINTED 8u
static uint32_t rs_warned_rays = 0;

static void rs_warn(uint32_t ray, const rs_ambiguous* a, const char* what) {
  if (rs_warned_rays++ < RS_WARNINGS_PRINTED)
    printf("WARNING: ray %u (numerically ambiguous: %s): %s\n", ray, a->reason, what);
}

/* The one of the ray's answers the judge accepts with a warning that `d` is,
   its words; NULL for none. */
static const char* rs_warned_answer(const uint32_t* d, const rs_ambiguous* a, rs_ray_rules r) {
  uint32_t i;
  for (i = 0; i < a->warnings; ++i)
    if (!rs_differs(d, rs_replays + (size_t)(a->first_replay + a->replays + i) * RS_RECORD_WORDS,
                    r))
      return rs_warning_notes[a->first_warning + i];
  return NULL;
}

/* Whether `d` is one of the ray's legal answers; else, one the judge accepts
   with a warning (given in *warning). */
static int rs_legal_answer(const uint32_t* d, const rs_ambiguous* a, rs_ray_rules r,
                           const char** warning) {
  uint32_t i;
  for (i = 0; i < a->replays; ++i)
    if (!rs_differs(d, rs_replays + (size_t)(a->first_replay + i) * RS_RECORD_WORDS, r)) return 1;
  *warning = rs_warned_answer(d, a, r);
  return *warning != NULL;
}

/* An ambiguous ray whose record is none of its answers: FAIL, 0. */
static int rs_none_of(uint32_t ray, const uint32_t* d, const rs_ambiguous* a, rs_ray_rules r) {
  const uint32_t* m = rs_replays + (size_t)a->first_replay * RS_RECORD_WORDS;
  printf(
      "FAIL: %s: ray %u (numerically ambiguous: %s): the record is none of its %u legal answers "
      "(nor of the %u accepted with a warning); of the first: ",
      a->rule, ray, a->reason, a->replays, a->warnings);
  rs_print_difference(rs_differs(d, m, r), m, d);
  return 0;
}

static int rs_check_ray(uint32_t ray, const uint32_t* d) {
  const rs_ambiguous* a = rs_ambiguity(ray);
  rs_ray_rules r = rs_rules_of(ray);
  const uint32_t* m = rs_expected + (size_t)ray * RS_RECORD_WORDS;
  const rs_field* f;
  const char* warning = NULL;
  int doubled;
  if (!a) {
    f = rs_differs(d, m, r);
    if (!f) return 1;
    printf("FAIL: %s: ray %u: ", f->rule, ray);
    rs_print_difference(f, m, d);
    return 0;
  }
  /* A double hit by any-hit runs: a warning whatever the record. */
  doubled = a->ahit_limit != RS_NONE && d[RS_ANY_HIT_RUNS_WORD] > a->ahit_limit;
  if (doubled) rs_warn(ray, a, RS_ANY_HIT_DOUBLE_HIT);
  if (r.skip) return 1; /* its legal answers and what repetition changes: not judged */
  if (!rs_legal_answer(d, a, r, &warning)) return rs_none_of(ray, d, a, r);
  if (warning && !doubled) rs_warn(ray, a, warning);
  return 1;
}

static int rs_compare(const uint32_t* records, const uint32_t* counters) {
  uint32_t ray, i;
  int failures = 0;
  for (ray = 0; ray < rs_ray_count; ++ray)
    if (!rs_undefined[ray] && !rs_check_ray(ray, records + (size_t)ray * RS_RECORD_WORDS))
      ++failures;
  for (i = 0; i < rs_counter_count; ++i) {
    const rs_counter* c = &rs_counters[i];
    if (counters[i] >= c->lo && counters[i] <= c->hi) continue;
    printf("FAIL: %s: counter '%s': expected %llu..%llu, observed %u\n", c->rule, c->name,
           (unsigned long long)c->lo, (unsigned long long)c->hi, counters[i]);
    ++failures;
  }
  return failures;
}

/* ---- The images against the model's ------------------------------------- */

static const uint32_t rs_image_rays = RS_RAY_COUNT; /* a texel a ray */

/* Whether a ray's pixel is left out of image `im`, as the judge leaves it out:
   an ambiguous ray (its legal answers differ by design), a ray with undefined
   behaviour (R-UB), or one whose field a repeated any-hit may change (R-AHIT-DUP). */
static int rs_pixel_left_out(const rs_image* im, uint32_t ray) {
  return rs_undefined[ray] || rs_ambiguity(ray) ||
         (im->has_field && ((rs_rules_of(ray).skip >> im->bit) & 1u));
}

/* How far an observed texel is from the expected one, in allowances (the
   judge's prepareImagePair; above 1 fails): ids 2 where they differ; floats
   |observed - expected| over the field's tolerance times the image's scale, NaN
   equal only to NaN. */
static float rs_texel_error(const rs_image* im, uint32_t d, uint32_t m) {
  float df = rs_float(d), mf = rs_float(m);
  double allowance, error;
  if (d == m) return 0.0f;
  if (!im->is_float) return 2.0f;
  if (rs_nan(df) || rs_nan(mf)) return rs_nan(df) && rs_nan(mf) ? 0.0f : 1e30f;
  if (df == mf) return 0.0f;
  allowance =
      (im->abs + im->rel * (rs_abs((double)mf) > 1.0 ? rs_abs((double)mf) : 1.0)) * im->scale;
  error = rs_abs((double)df - (double)mf) / allowance;
  return (float)(error < 1e30 ? error : 1e30);
}

static void rs_print_texel(const rs_image* im, uint32_t t) {
  if (im->is_float)
    printf("%.9g", (double)rs_float(t));
  else
    printf("%u", t);
}

/* The pixels of image i that differ from the model's beyond the tolerance
   (the left-out ones aside); FAIL printed when more than the case allows. */
static int rs_check_image(uint32_t i, const uint32_t* texels) {
  const rs_image* im = &rs_images[i];
  const uint32_t channels = im->is_float ? 4 : 1;
  uint32_t ray, k, failing = 0, first = 0, first_channel = 0;
  for (ray = 0; ray < rs_image_rays; ++ray) {
    int fails = 0;
    if (rs_pixel_left_out(im, ray)) continue;
    for (k = 0; k < channels && !fails; ++k) {
      const size_t at = (size_t)ray * channels + k;
      fails = rs_texel_error(im, texels[at], im->expected[at]) > 1.0f;
      if (fails && !failing) first = ray, first_channel = k;
    }
    failing += fails ? 1u : 0u;
  }
  if (failing <= im->max_failing) return 1;
  printf(
      "FAIL: image: image '%s' differs from the model in %u pixels (%u allowed); first: "
      "pixel %u, channel %u: expected ",
      im->name, failing, im->max_failing, first, first_channel);
  rs_print_texel(im, im->expected[(size_t)first * channels + first_channel]);
  printf(", observed ");
  rs_print_texel(im, texels[(size_t)first * channels + first_channel]);
  printf(" ('%s')\n", im->field);
  return 0;
}

/* On the ambiguous rays, image i shows the device's own record of its field
   (the judge's compareImagesToRecords): the first ray where it does not, or RS_NONE. */
static uint32_t rs_image_unlike_records(uint32_t i, const uint32_t* texels,
                                        const uint32_t* records) {
  const rs_image* im = &rs_images[i];
  const uint32_t channels = im->is_float ? 4 : 1;
  const uint32_t shown = im->words < channels ? im->words : channels;
  uint32_t a, k;
  if (!RS_RECORDS_JUDGED || !im->has_field) return RS_NONE;
  for (a = 0; a < rs_ambiguous_count; ++a) {
    const uint32_t ray = rs_ambiguous_rays[a].ray;
    const uint32_t* rec = records + (size_t)ray * RS_RECORD_WORDS;
    if (!im->automatic && !((rec[im->bit / 32] >> (im->bit % 32)) & 1u)) continue;
    for (k = 0; k < shown; ++k)
      if (texels[(size_t)ray * channels + k] != rec[im->offset + k]) return ray;
  }
  return RS_NONE;
}

/* Images the case declares equal (equal_to) are equal texel for texel. */
static int rs_check_equal_images(uint32_t i, const rs_image_target* targets) {
  const rs_image* im = &rs_images[i];
  const size_t words = (size_t)rs_image_rays * (im->is_float ? 4 : 1);
  if (im->equal_to == RS_NONE) return 1;
  if (!memcmp(targets[i].readback.mapped, targets[im->equal_to].readback.mapped, words * 4))
    return 1;
  printf("FAIL: image: images '%s' and '%s' differ on the device (equal_to: texel for texel)\n",
         im->name, rs_images[im->equal_to].name);
  return 0;
}

static int rs_compare_images(const rs_image_target* targets, const uint32_t* records) {
  uint32_t i, ray;
  int failures = 0;
  for (i = 0; i < rs_image_count; ++i) {
    const uint32_t* texels = (const uint32_t*)targets[i].readback.mapped;
    failures += !rs_check_image(i, texels);
    failures += !rs_check_equal_images(i, targets);
    ray = rs_image_unlike_records(i, texels, records);
    if (ray == RS_NONE) continue;
    printf(
        "FAIL: image: ray %u (numerically ambiguous): image '%s' shows another value than "
        "the device's own record of '%s'\n",
        ray, rs_images[i].name, rs_images[i].field);
    ++failures;
  }
  return failures;
}

/* ---- main: build, trace (or dispatch), read back, compare --------------- */

/* The ray tracing pipeline, its SBT and the trace, recorded into cmd. */
static void rs_record_trace(VkCommandBuffer cmd, VkPipelineLayout layout, VkDescriptorSet set) {
  VkPipeline pipeline = rs_create_pipeline(layout);
  rs_regions sbt = rs_write_sbt(pipeline);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR, layout, 0, 1, &set, 0, NULL);
  rs_cmd_trace(cmd, &sbt.raygen, &sbt.miss, &sbt.hit, &sbt.callable, RS_LAUNCH_WIDTH,
               RS_LAUNCH_HEIGHT, RS_LAUNCH_DEPTH);
}

/* Raygen's compute pipeline and the dispatch that covers the launch (RS_COMPUTE). */
static void rs_record_dispatch(VkCommandBuffer cmd, VkPipelineLayout layout, VkDescriptorSet set) {
  VkPipeline pipeline = rs_create_compute_pipeline(layout);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0, NULL);
  if (RS_COMPUTE_GROUPS_X)
    vkCmdDispatch(cmd, RS_COMPUTE_GROUPS_X, RS_COMPUTE_GROUPS_Y, RS_COMPUTE_GROUPS_Z);
}

/* The verdict printed, and the exit status: FAIL (1); a QualityWarning (0, as
   rayspec exits on it: R-WATERTIGHT, a "should", broken; no failure); PASS (0). */
static int rs_verdict(int failures) {
  if (failures) {
    printf("FAIL: %d of the checks differ from the reference model\n", failures);
    return 1;
  }
  if (rs_warned_rays) {
    /* rayspec's QualityWarning: a "should" broken, not a failure (exit 0). */
    printf(
        "QualityWarning: R-WATERTIGHT: %u rays on a shared edge or vertex leaked or hit twice "
        "(a \"should\" of the specification, not a failure); the rest as the reference model "
        "expects\n",
        (unsigned)rs_warned_rays);
    return 0;
  }
  printf("PASS: %u rays, %u counters and %u images as the reference model expects\n",
         (unsigned)rs_ray_count, (unsigned)RS_COUNTER_COUNT, (unsigned)RS_IMAGE_COUNT);
  return 0;
}

int main(int argc, char** argv) {
  rs_io io;
  VkAccelerationStructureKHR tlas[RS_TLAS_COUNT];
  VkDescriptorSetLayout set_layout;
  VkPipelineLayoutCreateInfo layout_info = {VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  VkPipelineLayout layout;
  VkDescriptorSet set;
  VkCommandBuffer cmd;
  int failures;
  printf("case: %s\n", RS_CASE_NAME);
  rs_create_instance();
  rs_pick_device(argc, argv);
  rs_create_device();
  rs_load_functions();
  rs_build_scene(tlas);
  io = rs_make_io();
  set = rs_bind(&set_layout, tlas, &io);
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &set_layout;
  rs_check(vkCreatePipelineLayout(rs_device, &layout_info, NULL, &layout),
           "vkCreatePipelineLayout");
  cmd = rs_begin();
  rs_clear_images(cmd, io.images);
  if (RS_COMPUTE)
    rs_record_dispatch(cmd, layout, set);
  else
    rs_record_trace(cmd, layout, set);
  rs_copy_images(cmd, io.images);
  rs_submit(cmd);
  failures = rs_compare((const uint32_t*)io.records.mapped, (const uint32_t*)io.counters.mapped);
  failures += rs_compare_images(io.images, (const uint32_t*)io.records.mapped);
  failures += rs_structure_failures;
  vkDeviceWaitIdle(rs_device);
  return rs_verdict(failures);
}
