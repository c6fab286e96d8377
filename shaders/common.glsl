// rayspec shared GLSL: buffers and helpers of set 0 (see harness/glsl/bindings.h).
// Every number below comes from #defines the generator writes before this
// file (RS_BINDING_*, RS_RAY_WORDS, RS_RECORD_WORDS, RS_FIELD_<NAME> word
// offsets, RS_BIT_<NAME> written-mask bits); none is retyped here.
// RS_LAUNCH_ID and RS_LAUNCH_SIZE are gl_LaunchIDEXT and gl_LaunchSizeEXT, or
// in raygen run as a compute shader the launch id and size it derives from
// the dispatch (harness/glsl/emit_compute.h).
// Optional parts, switched on by the generator only where the stage needs them:
//   RS_USE_RAYS           the rays buffer (raygen)
//   RS_USE_TLAS           the acceleration structure (stages that trace)
//   RS_USE_RECORDS        the per-ray record buffer
//   RS_USE_COUNTERS       the counter buffer
//   RS_USE_SHADER_RECORD  this stage's shader record data (8 words)
// Model counterpart: harness/model (records, counters, shader record data).

#ifdef RS_EMPTY_LAYOUT
// pipeline.layout: empty. The pipeline layout has no descriptor set (and no
// push constant): every buffer of set 0 below is reached through its device
// address instead, the address of binding b being word pair b of the address
// table, whose own address the specialization constants RS_TABLE_LO_ID and
// RS_TABLE_HI_ID hold (harness/vulkan/address_table.h); the top level is
// made from its address (accelerationStructureEXT(uvec2)).
layout(constant_id = RS_TABLE_LO_ID) const uint rs_table_lo = 0u;
layout(constant_id = RS_TABLE_HI_ID) const uint rs_table_hi = 0u;
layout(buffer_reference, std430, buffer_reference_align = 8) readonly buffer RsAddressTable {
  uvec2 address[];
};
uvec2 rs_address(uint binding) {
  return RsAddressTable(uvec2(rs_table_lo, rs_table_hi)).address[binding];
}
// The uint words of the buffer of a binding.
layout(buffer_reference, std430, buffer_reference_align = 4) buffer RsBoundWords {
  uint words[];
};
#define RS_BOUND_WORDS(binding) RsBoundWords(rs_address(binding)).words
#endif

// Launch index of this ray: (z * height + y) * width + x (a 3D launch's z
// layers one below the other).
uint rs_launch_index() {
  return (RS_LAUNCH_ID.z * RS_LAUNCH_SIZE.y + RS_LAUNCH_ID.y) * RS_LAUNCH_SIZE.x + RS_LAUNCH_ID.x;
}

// The texel of this launch's ray in an image `width` texels wide: the
// launch's rays in row-major order, so a launch wider than the device's
// largest image (a long ray list) folds into rows. For an image of the
// launch's own size it is gl_LaunchIDEXT.xy. Device side only (the model
// keeps images at the launch's size); harness/vulkan/case_buffers.h.
ivec2 rs_image_texel(int width) {
  const uint i = rs_launch_index();
  return ivec2(int(i % uint(width)), int(i / uint(width)));
}

#ifdef RS_USE_TLAS
#if defined(RS_EMPTY_LAYOUT)
#define rs_tlas accelerationStructureEXT(rs_address(RS_BINDING_TLAS))
#elif defined(RS_TLAS_COUNT)
// Several top levels (scene.instances[].tlas): a trace names one by a constant.
layout(set = 0, binding = RS_BINDING_TLAS) uniform accelerationStructureEXT rs_tlas[RS_TLAS_COUNT];
#else
layout(set = 0, binding = RS_BINDING_TLAS) uniform accelerationStructureEXT rs_tlas;
#endif
#endif

#ifdef RS_USE_RAYS
#ifdef RS_EMPTY_LAYOUT
#define rs_rays RS_BOUND_WORDS(RS_BINDING_RAYS)
#else
layout(set = 0, binding = RS_BINDING_RAYS, std430) readonly buffer RsRays {
  uint rs_rays[];
};
#endif

// One ray of the launch, as packed by packRays (RS_RAY_WORDS words).
struct RsRay {
  vec3 origin;
  float tmin;
  vec3 direction;
  float tmax;
  uint flags, cull_mask, sbt_offset, sbt_stride, miss;
};

RsRay rs_load_ray(uint index) {
  uint w = index * RS_RAY_WORDS;
  RsRay r;
  r.origin = vec3(uintBitsToFloat(rs_rays[w + 0u]), uintBitsToFloat(rs_rays[w + 1u]),
                  uintBitsToFloat(rs_rays[w + 2u]));
  r.tmin = uintBitsToFloat(rs_rays[w + 3u]);
  r.direction = vec3(uintBitsToFloat(rs_rays[w + 4u]), uintBitsToFloat(rs_rays[w + 5u]),
                     uintBitsToFloat(rs_rays[w + 6u]));
  r.tmax = uintBitsToFloat(rs_rays[w + 7u]);
  r.flags = rs_rays[w + 8u];
  r.cull_mask = rs_rays[w + 9u];
  r.sbt_offset = rs_rays[w + 10u];
  r.sbt_stride = rs_rays[w + 11u];
  r.miss = rs_rays[w + 12u];
  return r;
}
#endif

#ifdef RS_USE_RECORDS
// The record words are reached through their device address, held by the
// small buffer at RS_BINDING_RECORDS: a storage buffer binding is limited to
// maxStorageBufferRange (128 MiB on lavapipe), and a launch of 2^20 rays
// already needs more (the generator enables GL_EXT_buffer_reference).
layout(buffer_reference, std430, buffer_reference_align = 4) buffer RsRecordWords {
  uint words[];
};
#ifdef RS_EMPTY_LAYOUT
// The words' address read as two uints, not as a reference: a reference
// loaded through a PhysicalStorageBuffer pointer needs an 8-byte Aligned
// operand that Debian 12's glslang does not give it (newer spirv-val:
// VUID-StandaloneSpirv-PhysicalStorageBuffer64-06314).
layout(buffer_reference, std430, buffer_reference_align = 8) readonly buffer RsRecordsRef {
  uvec2 words_address;
};
#define rs_records RsRecordWords(RsRecordsRef(rs_address(RS_BINDING_RECORDS)).words_address).words
#elif defined(RS_RECORDS_BOUND)
// The words bound directly (the Amber export: a script cannot hand a shader an address).
layout(set = 0, binding = RS_BINDING_RECORDS, std430) buffer RsRecordsBound {
  uint rs_records_bound[];
};
#define rs_records rs_records_bound
#else
layout(set = 0, binding = RS_BINDING_RECORDS, std430) readonly buffer RsRecords {
  RsRecordWords rs_records_ref;
};
#define rs_records rs_records_ref.words
#endif

// First word of this launch's record.
uint rs_record_base() {
  return rs_launch_index() * RS_RECORD_WORDS;
}

// Word 0 of a record: bit mask of the fields written.
void rs_mark_written(uint bit) {
  atomicOr(rs_records[rs_record_base()], 1u << bit);
}

void rs_record_uint(uint offset, uint bit, uint v) {
  rs_records[rs_record_base() + offset] = v;
  rs_mark_written(bit);
}

void rs_record_float(uint offset, uint bit, float v) {
  rs_records[rs_record_base() + offset] = floatBitsToUint(v);
  rs_mark_written(bit);
}

void rs_record_vec2(uint offset, uint bit, vec2 v) {
  uint w = rs_record_base() + offset;
  rs_records[w + 0u] = floatBitsToUint(v.x);
  rs_records[w + 1u] = floatBitsToUint(v.y);
  rs_mark_written(bit);
}

void rs_record_vec3(uint offset, uint bit, vec3 v) {
  uint w = rs_record_base() + offset;
  rs_records[w + 0u] = floatBitsToUint(v.x);
  rs_records[w + 1u] = floatBitsToUint(v.y);
  rs_records[w + 2u] = floatBitsToUint(v.z);
  rs_mark_written(bit);
}

void rs_record_vec4(uint offset, uint bit, vec4 v) {
  uint w = rs_record_base() + offset;
  rs_records[w + 0u] = floatBitsToUint(v.x);
  rs_records[w + 1u] = floatBitsToUint(v.y);
  rs_records[w + 2u] = floatBitsToUint(v.z);
  rs_records[w + 3u] = floatBitsToUint(v.w);
  rs_mark_written(bit);
}

// Reads word i of a field of this launch's record (raygen, for images).
uint rs_record_word(uint offset, uint i) {
  return rs_records[rs_record_base() + offset + i];
}

// Automatic per-ray stage run count (raygen_runs, miss_runs, ...): +1.
void rs_bump_runs(uint offset) {
  atomicAdd(rs_records[rs_record_base() + offset], 1u);
}

// any-hit: the primitive's bit in any_hit_slots; in any_hit_repeats too when
// it was set already (results/record_layout.h, anyHitSlot).
void rs_mark_any_hit(uint slots_offset, uint repeats_offset, uint slot) {
  uint bit = 1u << slot;
  uint before = atomicOr(rs_records[rs_record_base() + slots_offset], bit);
  if ((before & bit) != 0u) atomicOr(rs_records[rs_record_base() + repeats_offset], bit);
}
#endif

#ifdef RS_USE_COUNTERS
#ifdef RS_EMPTY_LAYOUT
#define rs_counters RS_BOUND_WORDS(RS_BINDING_COUNTERS)
#else
layout(set = 0, binding = RS_BINDING_COUNTERS, std430) buffer RsCounters {
  uint rs_counters[];
};
#endif

// Global counter `index` (position of its name in the plan's counters): +1.
void rs_count(uint index) {
  atomicAdd(rs_counters[index], 1u);
}
#endif

#ifdef RS_USE_SHADER_RECORD
// Every SBT record carries RS_SHADER_RECORD_WORDS data words after its
// handle (pipeline.sbt.record_data / 4, default 8; all zero unless the case
// sets them); the parser keeps every read inside them.
#ifndef RS_SHADER_RECORD_WORDS
#define RS_SHADER_RECORD_WORDS 8
#endif
layout(shaderRecordEXT, std430) buffer RsShaderRecord {
  uint words[RS_SHADER_RECORD_WORDS];
} rs_shader_record;

uint rs_shader_record_uint(uint i) {
  return rs_shader_record.words[i];
}

float rs_shader_record_float(uint i) {
  return uintBitsToFloat(rs_shader_record.words[i]);
}
#endif
