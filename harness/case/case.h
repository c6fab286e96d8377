// A parsed case: the scene, the rays, the pipeline with its stage programs, and
// what to keep. Produced by case/parse_case (from YAML); consumed by the plan,
// the GLSL generator, the Vulkan backend and the model. No expected values.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/affine.h"
#include "base/enum_names.h"
#include "base/source_loc.h"
#include "base/vec3.h"
#include "case/bit_widths.h"
#include "case/structure_queries.h"
#include "case/vertex_format.h"
#include "program/payload_words.h"
#include "program/program.h"
#include "program/stage_interface.h"
#include "results/undefined_reason.h"

namespace rayspec {

// Vec3 (float positions and directions) and Transform (row-major 3x4, as
// VkTransformMatrixKHR): base/vec3.h and base/affine.h.

// Vulkan geometry flags (VkGeometryFlagBitsKHR values).
enum GeometryFlag : uint32_t {
  kGeometryOpaque = 0x1,             // "opaque"
  kGeometryNoDuplicateAnyHit = 0x2,  // "no_duplicate_any_hit"
};

// Vulkan instance flags (VkGeometryInstanceFlagBitsKHR values).
enum InstanceFlag : uint32_t {
  kInstanceFacingCullDisable = 0x1,  // "triangle_facing_cull_disable"
  kInstanceFlipFacing = 0x2,         // "triangle_flip_facing"
  kInstanceForceOpaque = 0x4,        // "force_opaque"
  kInstanceForceNoOpaque = 0x8,      // "force_no_opaque"
  // VK_EXT_opacity_micromap: no rayspec geometry has a micromap, so they
  // change nothing traversal sees; a device without the extension runs a
  // case that sets them as NotSupported.
  kInstanceForceOpacityMicromap2State = 0x10,  // "force_opacity_micromap_2_state"
  kInstanceDisableOpacityMicromaps = 0x20,     // "disable_opacity_micromaps"
};
constexpr uint32_t kInstanceOpacityMicromapFlags =
    kInstanceForceOpacityMicromap2State | kInstanceDisableOpacityMicromaps;

// Vulkan ray flags (gl_RayFlags*EXT values), written in cases by the names
// opaque, no_opaque, terminate_on_first_hit, skip_closest_hit, cull_back_facing,
// cull_front_facing, cull_opaque, cull_no_opaque, skip_triangles, skip_aabbs.
enum RayFlag : uint32_t {
  kRayOpaque = 0x1,
  kRayNoOpaque = 0x2,
  kRayTerminateOnFirstHit = 0x4,
  kRaySkipClosestHit = 0x8,
  kRayCullBackFacing = 0x10,
  kRayCullFrontFacing = 0x20,
  kRayCullOpaque = 0x40,
  kRayCullNoOpaque = 0x80,
  kRaySkipTriangles = 0x100,
  kRaySkipAabbs = 0x200,
};

struct Geometry {
  enum class Kind { Triangles, Aabbs };
  Kind kind = Kind::Triangles;
  uint32_t flags = 0;  // GeometryFlag bits
  // Triangles: vertices (float32, NaN allowed), indices (uint32) or empty for
  // non-indexed (each 3 consecutive vertices one triangle).
  std::vector<Vec3> vertices;  // as the vertex format stores them (storedVertex)
  std::vector<uint32_t> indices;
  VertexFormat vertex_format = VertexFormat::Float3;  // R-VERTEX-FORMAT
  bool index16 = false;                               // VK_INDEX_TYPE_UINT16
  std::vector<Vec3> written;           // the positions as written, where the format rounds them
  std::optional<Transform> transform;  // optional geometry transform (triangles)
  // Aabbs: min x,y,z, max x,y,z per primitive.
  std::vector<std::array<float, 6>> aabbs;
  SourceLoc loc;
  uint32_t primitiveCount() const {
    if (kind == Kind::Aabbs) return static_cast<uint32_t>(aabbs.size());
    return static_cast<uint32_t>((indices.empty() ? vertices.size() : indices.size()) / 3);
  }
};

struct Blas {
  std::string name;
  std::vector<Geometry> geometries;  // all Triangles or all Aabbs
  SourceLoc loc;
};

struct Instance {
  std::optional<uint32_t> blas;  // index into Scene::blases; empty = null reference (inactive)
  Transform transform = kIdentity;
  uint32_t mask = kVisibilityMask;  // 8 bits
  uint32_t custom_index = 0;        // 24 bits
  uint32_t sbt_offset = 0;          // 24 bits
  uint32_t flags = 0;               // InstanceFlag bits
  // The top level it belongs to (0 .. kMaxTlases - 1). Every top level holds
  // all instances in this list's order, those of the other levels inactive
  // (a null BLAS reference), so gl_InstanceID is the position in this list
  // whichever level a trace traverses.
  uint32_t tlas = 0;
  SourceLoc loc;
};

constexpr uint32_t kMaxTlases = 8;

// Totals a case is held to, checked while it is read, before the parent
// allocates beyond them (each a CaseError naming the field and the limit;
// docs/robustness.md, "Limits"): primitives of all geometries together (one grid
// alone may hold 2^23), instances, and the bytes of the per-ray records and
// images a launch writes.
constexpr uint64_t kMaxScenePrimitives = 1ull << 24;
constexpr uint64_t kMaxInstances = 1ull << 20;
constexpr uint64_t kMaxOutputBytes = 1ull << 30;

// How every acceleration structure is built (scene.build): its build flags
// (VkBuildAccelerationStructureFlagsKHR, default PREFER_FAST_TRACE), and a
// copy (R-AS-COPY) the traces use instead of what was built: clone
// (vkCmdCopyAccelerationStructureKHR, CLONE) or compact (COMPACT, at the
// compacted size the device reports). Shaders observe the same either way.
// serialize: to memory and back (vkCmdCopyAccelerationStructureToMemoryKHR,
// vkCmdCopyMemoryToAccelerationStructureKHR).
#define RAYSPEC_AS_COPIES(X) \
  X(None, "none") X(Clone, "clone") X(Compact, "compact") X(Serialize, "serialize")
enum class AsCopy { RAYSPEC_AS_COPIES(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(AsCopy, RAYSPEC_AS_COPIES);
const char* asCopyName(AsCopy c);  // none, clone, compact, serialize
// scene.build.command: how every build and update is recorded. device:
// vkCmdBuildAccelerationStructuresKHR. indirect:
// vkCmdBuildAccelerationStructuresIndirectKHR, each build's ranges read from
// a device buffer (accelerationStructureIndirectBuild). host:
// vkBuildAccelerationStructuresKHR on the host (accelerationStructureHostCommands).
#define RAYSPEC_BUILD_COMMANDS(X) X(Device, "device") X(Indirect, "indirect") X(Host, "host")
enum class BuildCommand { RAYSPEC_BUILD_COMMANDS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(BuildCommand, RAYSPEC_BUILD_COMMANDS);
// scene.build.generic: which levels' structures are created with
// VK_ACCELERATION_STRUCTURE_TYPE_GENERIC_KHR (their copies and update
// targets too); every build still names the real type, bottom or top.
#define RAYSPEC_GENERIC_LEVELS(X) X(None, "none") X(Bottom, "bottom") X(Top, "top") X(Both, "both")
enum class GenericLevels { RAYSPEC_GENERIC_LEVELS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(GenericLevels, RAYSPEC_GENERIC_LEVELS);
// scene.build.sparse: the buffers of the builds in sparse-bound memory.
// structures: every structure's buffer (the CTS's sparse_binding_structures);
// scratch: the scratch buffer; instances: each top level's instance buffer;
// geometry: the buffer of every BLAS's vertices, indices, transforms and
// boxes. The last two are filled by a copy from a host buffer.
// The names, each the member it sets (parse/parse_scene.cpp reads them).
#define RAYSPEC_SPARSE_BUFFERS(X) \
  X(structures, "structures")     \
  X(scratch, "scratch") X(instances, "instances") X(geometry, "geometry")
struct SparseBuffers {
  bool structures = false, scratch = false, instances = false, geometry = false;
  bool any() const { return structures || scratch || instances || geometry; }
  bool all() const { return structures && scratch && instances && geometry; }
  static SparseBuffers every() { return {true, true, true, true}; }
};
// scene.build.storage: where the structures' memory lies. own: each in a
// buffer of its own. shared: one after another in a few large buffers, each
// at a multiple of 256 bytes with its guard between it and the next (as the
// CTS's pooled BLASes). reused: shared, and every structure created over
// memory a destroyed one used (a decoy scene, every position moved, built
// there first, then destroyed), then another structure created over each
// built one and never built (the CTS's reuse_creation_buffer): creating it
// must leave the memory as it is (R-AS-CREATE).
#define RAYSPEC_STRUCTURE_STORAGES(X) X(Own, "own") X(Shared, "shared") X(Reused, "reused")
enum class StructureStorage { RAYSPEC_STRUCTURE_STORAGES(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(StructureStorage, RAYSPEC_STRUCTURE_STORAGES);
struct AsBuild {
  uint32_t flags = 0x4;
  BuildCommand command = BuildCommand::Device;
  AsCopy copy = AsCopy::None;
  // scene.build.order: how many of the updates (scene.update) run before the
  // copy; the rest update the copies. Default: every update, then the copy.
  std::optional<uint32_t> updates_before_copy;
  // How the build inputs are laid out in memory (vulkan/build_layout.h);
  // shaders observe the same scene either way. instances_as_pointers: the
  // TLAS reads an array of pointers (arrayOfPointers) to instances placed in
  // reverse order with gaps. data_offsets: every input sits behind junk at a
  // nonzero primitiveOffset / transformOffset. first_vertex: this many junk
  // vertices before each geometry's own, skipped by firstVertex (its own
  // field: lavapipe 25.0.7 applies firstVertex twice, see the baseline).
  // vertex_stride, aabb_stride: bytes from one vertex / box to the next (0:
  // tightly packed), the padding filled with junk.
  bool instances_as_pointers = false;
  bool data_offsets = false;
  uint32_t first_vertex = 0;
  uint32_t vertex_stride = 0;
  uint32_t aabb_stride = 0;
  // scene.build.one_by_one: every build and update in a
  // vkCmdBuildAccelerationStructuresKHR of its own, in sequence, all in the
  // same scratch memory (the largest build's), a barrier between each (the
  // default: each level's builds in one command, each its own scratch).
  bool one_by_one = false;
  // scene.build.update_into: other: each update (scene.update) writes a new
  // structure from the one before (source and destination differ); the
  // traces use the last. Not with a copy (scene.build.copy).
  bool update_into_other = false;
  // scene.build.tlas_update: rebuild: after each update the top levels are
  // built anew (MODE_BUILD) over the updated BLASes and new instances, not
  // updated.
  bool tlas_rebuilt = false;
  GenericLevels generic = GenericLevels::None;
  // scene.build.sparse: which buffers of the builds are created with
  // SPARSE_BINDING and bound page by page through vkQueueBindSparse, out of
  // order over two allocations, their contents across a page boundary
  // (vulkan/sparse_buffer.h; sparseBinding).
  SparseBuffers sparse;
  StructureStorage storage = StructureStorage::Own;
  // scene.build.queries, query_command (case/structure_queries.h).
  StructureQueries queries;
  bool customLayout() const {
    return instances_as_pointers || data_offsets || first_vertex || vertex_stride || aabb_stride;
  }
};

// scene.build.vertex_stride and aabb_stride: at most this many bytes.
constexpr uint32_t kMaxInputStride = 1024;
// scene.build.first_vertex: at most this many junk vertices.
constexpr uint32_t kMaxFirstVertex = 16;

// At most this many updates in one scene (scene.update as a list).
constexpr uint32_t kMaxUpdates = 4;

struct Scene {
  std::vector<Blas> blases;
  std::vector<Instance> instances;
  AsBuild build;
  // R-AS-UPDATE (scene.update): the scene as first built, then as each update
  // but the last left it; this Scene is the one after the last update, what
  // the traces see. The device builds earlier.front() with ALLOW_UPDATE and
  // updates it in place into each later state in turn.
  std::vector<std::shared_ptr<const Scene>> earlier;
  size_t updates() const { return earlier.size(); }
  // The updates that run before the copy (build.updates_before_copy, at most
  // every update).
  size_t updatesBeforeCopy() const {
    return std::min<size_t>(build.updates_before_copy.value_or(updates()), updates());
  }
  // How many top levels the scene has: one past the highest Instance::tlas
  // (a level no instance names is built empty); at least 1.
  uint32_t tlasCount() const {
    uint32_t n = 1;
    for (const Instance& i : instances) n = std::max(n, i.tlas + 1);
    return n;
  }
};

// One ray of the launch, exactly as uploaded to the device (float32).
struct Ray {
  Vec3 origin{}, direction{};
  float tmin = 0.0f, tmax = 1e30f;
  uint32_t flags = 0, cull_mask = kVisibilityMask, sbt_offset = 0, sbt_stride = 1, miss = 0;
};

// The command that launches the rays (R-INDIRECT): vkCmdTraceRaysKHR, or
// vkCmdTraceRaysIndirectKHR with the launch size in a buffer, or
// vkCmdTraceRaysIndirect2KHR with the SBT regions in it too. Shaders observe
// the same whichever it is.
#define RAYSPEC_TRACE_COMMANDS(X) \
  X(Direct, "trace_rays") X(Indirect, "indirect") X(Indirect2, "indirect2")
enum class TraceCommand { RAYSPEC_TRACE_COMMANDS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(TraceCommand, RAYSPEC_TRACE_COMMANDS);
const char* traceCommandName(TraceCommand c);  // trace_rays, indirect, indirect2

// The most launch ids whose rays a case lists or the model traces one by one
// (2^24), and the most a rays.same launch may have (2^30, the spec's minimum
// maxRayDispatchInvocationCount): above 2^24 no program may read the launch
// id, and the model traces one id for all (model/uniform_launch.h).
constexpr uint64_t kMaxTracedLaunchIds = uint64_t{1} << 24;
constexpr uint64_t kMaxSameLaunchIds = uint64_t{1} << 30;

struct Rays {
  // The records' shape: width = launch[0], height = launch[1] x launch[2]
  // (a 3D launch's z layers one below the other); width*height == launchRays().
  uint32_t width = 1, height = 1;
  // The launch size the trace command gets (rays.launch, R-LAUNCH-3D; when
  // not given, width x height x 1). The rays are in launch order: x fastest,
  // then y, then z. A zero dimension launches nothing: then there are no rays.
  std::optional<std::array<uint32_t, 3>> launch;
  std::array<uint32_t, 3> launchSize() const {
    return launch ? *launch : std::array<uint32_t, 3>{width, height, 1};
  }
  TraceCommand command = TraceCommand::Direct;
  std::vector<Ray> rays;  // row-major, index = y * width + x
  // rays.same: every launch id traces rays[0], the one ray kept (a launch
  // too wide to list, up to kMaxSameLaunchIds; zero ids keep none).
  bool same = false;
  const Ray& launchRay(size_t index) const { return same ? rays.front() : rays[index]; }
  size_t launchRays() const { return same ? static_cast<size_t>(width) * height : rays.size(); }
  Ray defaults;                      // tmin/tmax/flags/... used for camera rays and nested traces
  SourceLoc defaults_loc;            // the `rays` map
  std::vector<SourceLoc> list_locs;  // `list` form: where each ray is written (empty otherwise)
};

// One record of an SBT region: a group index, or all-zero, plus record data.
struct SbtRecord {
  std::optional<uint32_t> group;  // empty = all-zero record (R-SBT-ZERO)
  std::vector<uint32_t> data;     // up to record_data / 4 words of shader record data
};

// The shape of every SBT record (pipeline.sbt.record_data / padding): the
// group handle, then `record_data` bytes of shader record data (what the
// case's data and its shaders' shader_record_* reads may use), then the
// region's padding bytes. A region's stride is
// alignUp(handleSize + record_data + padding, shaderGroupHandleAlignment);
// the raygen region (one record) has no padding.
constexpr uint32_t kMaxShaderRecordDataBytes = 32;  // 8 words
constexpr uint32_t kMaxSbtPaddingBytes = 65536;
// A case or sweep file larger than this is refused unread (the largest in
// cases/ holds 16 KB; tests run lists of 40000 rays, 2 MB).
constexpr uint64_t kMaxCaseFileBytes = 64u << 20;
struct SbtPadding {
  uint32_t miss = 0, hit = 0, callable = 0;  // bytes
};

struct HitGroup {
  std::optional<Program> closest_hit, any_hit, intersection;
  uint32_t payload = 0;  // its incoming payload has the type of this location (Pipeline::payloads)
  SourceLoc loc;
};

// Payload types (pipeline.payloads), by the location a trace names: color,
// value and depth, then `words` more uint words (payload.word0 ..). At most
// kMaxPayloadLocations locations; the largest type is 24 + 4 * 58 = 256 bytes
// (a pipeline linked from libraries declares the case's largest:
// vulkan/pipeline.h interfacePayloadBytes).
constexpr uint32_t kMaxPayloadLocations = 4;
// The hit attribute's bytes every device allows (maxRayHitAttributeSize's
// minimum): pipeline.hit_attribute's vec2, words and sized members.
constexpr uint32_t kMaxAttributeBytes = 32;
constexpr uint32_t kMaxPayloadWords = kPayloadWordNames;
constexpr uint32_t kPayloadBaseBytes = 24;   // RsPayload (shaders/payload.glsl)
constexpr uint32_t kCallDataBaseBytes = 48;  // RsCallData
constexpr uint32_t kMaxDataTypeBytes = kPayloadBaseBytes + 4 * kMaxPayloadWords;  // 256

// Callable data types (pipeline.callable_data), by the location a call
// names: RsCallData (color, position, value, normal: 48 bytes), then `words`
// more uint words (call.word0 ..), up to 48 + 4 * 52 = 256 bytes.
constexpr uint32_t kMaxCallDataLocations = 4;
constexpr uint32_t kMaxCallDataWords = (kMaxDataTypeBytes - kCallDataBaseBytes) / 4;

// A pipeline library (VK_KHR_pipeline_library): the groups it holds, by
// index into Pipeline::miss / hit_groups / callables, and the libraries it
// links in turn. A group no library holds is the linked pipeline's own
// (raygen always is).
struct PipelineLibrary {
  std::vector<uint32_t> miss, hit_groups, callables;
  std::vector<PipelineLibrary> libraries;
  SourceLoc loc;
};

// At most this many libraries in one case, counting nested ones.
constexpr size_t kMaxPipelineLibraries = 16;

// Callables nested this deep fit the default pipeline stack size, which holds
// two callable frames (Vulkan, "Ray Tracing Pipeline Stack": ... + 2 x
// callableStackMax). pipeline.callable_depth sets a stack size for up to
// kMaxCallableDepth (R-STACK).
constexpr uint32_t kDefaultCallableDepth = 2;
constexpr uint32_t kMaxCallableDepth = 16;

// pipeline.deferred: at most this many threads join one deferred operation.
constexpr uint32_t kMaxDeferredThreads = 64;

struct Pipeline {
  uint32_t max_recursion = 1;
  // Set: every pipeline object of the case (each library and the linked or
  // only pipeline) is created through a VkDeferredOperationKHR
  // (VK_KHR_deferred_host_operations) joined by this many threads; 0: as
  // many as vkGetDeferredOperationMaxConcurrencyKHR answers, at most
  // kMaxDeferredThreads (pipeline.deferred, --through deferred, R-DEFERRED).
  // Shaders observe the same.
  std::optional<uint32_t> deferred_threads;
  // Empty: the default stack size (kDefaultCallableDepth callable frames).
  // Set: the pipeline has the dynamic stack size state and the trace sets a
  // size that covers callables nested this deep (R-STACK).
  std::optional<uint32_t> callable_depth;
  uint32_t callableDepth() const { return callable_depth.value_or(kDefaultCallableDepth); }
  uint32_t flags = 0;  // pipeline flags: skip_triangles / skip_aabbs (VkPipelineCreateFlags values
                       // 0x1000 / 0x2000)
  Program raygen;      // default: [trace: {}]; the raygen the launch runs
  // Every trace is a ray query loop in raygen that runs the hit group and
  // miss programs inlined (pipeline.traces: ray_query, --through ray-query,
  // R-RQ-EQUIV, glsl/emit_ray_query.h); the other stages stay in the
  // pipeline, unrun.
  bool ray_query = false;
  // With ray_query: raygen runs as a compute shader (pipeline.traces:
  // ray_query_compute, --through ray-query-compute): gl_LaunchIDEXT and
  // gl_LaunchSizeEXT are read from the dispatch (glsl/emit_compute.h), no ray
  // tracing pipeline is made, and the launch is one vkCmdDispatch.
  bool from_compute = false;
  // Raygen keeps traceRayEXT; each trace of a closest-hit or miss is a ray
  // query loop in that stage running the programs inlined, as above
  // (pipeline.traces: ray_query_in_hit, --through ray-query-in-hit).
  bool ray_query_in_hit = false;
  // pipeline.tlas_function: every traceRayEXT and rayQueryInitializeEXT is
  // made inside a function that takes the top level as an
  // accelerationStructureEXT parameter (glsl/emit_trace.h), the caller
  // passing rs_tlas, rs_tlas[k] or rs_tlas[nonuniformEXT(i)]. What is traced
  // is the same: the model runs the case as it is.
  bool tlas_function = false;
  // pipeline.layout: empty (R-EMPTY-LAYOUT): the pipeline is created with a
  // pipeline layout of no descriptor set and no push constant, binds nothing,
  // and its shaders reach the case's buffers and top level through their
  // device addresses (glsl/bindings.h); they observe the same.
  bool empty_layout = false;
  // Several raygen groups (pipeline.raygens): `raygen` is group raygen_group,
  // other_raygens the rest in group order. The raygen region's record
  // selects raygen_group (R-RAYGEN-REGION); the others never run.
  uint32_t raygen_group = 0;
  std::vector<Program> other_raygens;
  uint32_t raygenGroupCount() const { return 1 + static_cast<uint32_t>(other_raygens.size()); }
  // Raygen group g's program.
  const Program& raygenOfGroup(uint32_t g) const {
    return g == raygen_group ? raygen : other_raygens[g < raygen_group ? g : g - 1];
  }
  std::vector<uint32_t> raygen_data;  // raygen shader record data
  std::vector<Program> miss;
  std::vector<uint32_t> miss_payload;  // per miss shader: the location whose payload type it takes
  uint32_t missPayload(size_t i) const { return i < miss_payload.size() ? miss_payload[i] : 0; }
  std::vector<HitGroup> hit_groups;
  // Extra words of each location's payload type; default one location, none.
  std::vector<uint32_t> payload_words{0};
  // Extra words of a location's payload type (0 for a location not declared).
  uint32_t payloadWords(size_t location) const {
    return location < payload_words.size() ? payload_words[location] : 0;
  }
  // The sized members of each location's payload type (pipeline.payloads[].sized).
  std::vector<SizedMembers> payload_sized{{}};
  const SizedMembers& payloadSized(size_t location) const {
    static const SizedMembers kNone;
    return location < payload_sized.size() ? payload_sized[location] : kNone;
  }
  // Every location's sized members: those of raygen's payload and a stage's
  // child, which hold any trace's result.
  SizedMembers allPayloadSized() const {
    SizedMembers all;
    for (const SizedMembers& m : payload_sized) all = sizedMembersUnion(all, m);
    return all;
  }
  // Bytes of a data type: its fixed members and words, then its sized
  // members: an upper bound under any alignment rule (each member at most
  // 32 bytes, aligned to at most 32), what a library's interface declares.
  static uint32_t dataBytes(uint32_t base, uint32_t words, const SizedMembers& sized) {
    const uint32_t fixed = base + 4 * words;
    if (sized.empty()) return fixed;
    return (fixed + 31) / 32 * 32 + 32 * static_cast<uint32_t>(sized.size());
  }
  // Bytes of a location's payload type: RsPayload (vec4, uint, uint) + 4 per
  // word, then its sized members.
  uint32_t payloadBytes(size_t location) const {
    return dataBytes(kPayloadBaseBytes, payloadWords(location), payloadSized(location));
  }
  uint32_t maxPayloadWords() const {
    uint32_t n = 0;
    for (uint32_t w : payload_words) n = std::max(n, w);
    return n;
  }
  std::vector<Program> callables;
  std::vector<uint32_t> callable_data;  // per callable: the location whose data type it takes
  uint32_t callableData(size_t i) const { return i < callable_data.size() ? callable_data[i] : 0; }
  // Extra words of each location's callable data type; default one location, none.
  std::vector<uint32_t> call_data_words{0};
  uint32_t callDataWords(size_t location) const {
    return location < call_data_words.size() ? call_data_words[location] : 0;
  }
  // The sized members of each location's callable data type
  // (pipeline.callable_data[].sized).
  std::vector<SizedMembers> call_data_sized{{}};
  const SizedMembers& callDataSized(size_t location) const {
    static const SizedMembers kNone;
    return location < call_data_sized.size() ? call_data_sized[location] : kNone;
  }
  // Every location's sized members: those of a stage's callee.
  SizedMembers allCallDataSized() const {
    SizedMembers all;
    for (const SizedMembers& m : call_data_sized) all = sizedMembersUnion(all, m);
    return all;
  }
  // Bytes of callable data with that many words and sized members:
  // RsCallData (48 bytes) + 4 per word, then the members.
  static uint32_t callDataBytes(uint32_t words, const SizedMembers& sized = {}) {
    return dataBytes(kCallDataBaseBytes, words, sized);
  }
  uint32_t maxCallDataWords() const {
    uint32_t n = 0;
    for (uint32_t w : call_data_words) n = std::max(n, w);
    return n;
  }
  // The words an indexed read or write of `which` ranges over in a stage whose
  // incoming payload or callable data has the type of `incoming_location`
  // (program/payload_words.h): the incoming type's for Payload (outside
  // raygen) and Call; the largest type's for raygen's Payload, Child and
  // Callee, which hold any trace's or call's result.
  uint32_t indexedWords(WordArray which, Stage stage, uint32_t incoming_location) const {
    switch (which) {
      case WordArray::Payload:
        return stage == Stage::Raygen ? maxPayloadWords() : payloadWords(incoming_location);
      case WordArray::Child:
        return maxPayloadWords();
      case WordArray::Call:
        return callDataWords(incoming_location);
      case WordArray::Callee:
        return maxCallDataWords();
    }
    return 0;
  }
  // Extra uint words of the hit attribute after its vec2
  // (pipeline.hit_attribute.words, 0..kMaxAttributeWords).
  uint32_t attribute_words = 0;
  // Its sized members after the words (pipeline.hit_attribute.sized); the
  // whole attribute, as Vulkan counts it (hitAttributeBytes), within
  // kMaxAttributeBytes.
  SizedMembers attribute_sized;
  uint32_t attributeBytes() const { return hitAttributeBytes(attribute_words, attribute_sized); }
  // Specialization constants (pipeline.constants), and the values some
  // shaders take (pipeline.specialize, by GeneratedShader name: "raygen",
  // "miss0", "hit1.any_hit", "callable2", ...), by constant index.
  std::vector<SpecConstant> constants;
  std::map<std::string, std::map<size_t, double>> specialize;
  // A shader's name, as GLSL generation, pipeline.specialize and `rayspec
  // show` use it: "raygen", "raygen.other<i>", "miss<i>",
  // "hit<i>.closest_hit" / ".any_hit" / ".intersection", "callable<i>" (i: the
  // other raygen, miss shader, hit group or callable).
  static std::string shaderName(Stage stage, size_t i, bool other_raygen = false) {
    const std::string n = std::to_string(i);
    switch (stage) {
      case Stage::Raygen:
        return other_raygen ? "raygen.other" + n : "raygen";
      case Stage::Miss:
        return "miss" + n;
      case Stage::Callable:
        return "callable" + n;
      default:
        return "hit" + n + "." + stageName(stage);
    }
  }
  // Constant k's value in shader `shader`.
  double constantIn(const std::string& shader, size_t k) const {
    const auto s = specialize.find(shader);
    if (s != specialize.end())
      if (const auto v = s->second.find(k); v != s->second.end()) return v->second;
    return k < constants.size() ? constants[k].value : 0.0;
  }
  // SBT regions. Default when not written: one record per shader / group, in order.
  std::vector<SbtRecord> sbt_miss, sbt_hit, sbt_callable;
  uint32_t sbt_record_data =
      kMaxShaderRecordDataBytes;  // bytes of data per record: 0..32, multiple of 4
  SbtPadding sbt_padding;
  // The shader record block's members (pipeline.sbt.record_layout); none
  // declared: shader_record_uint / _float read its words.
  ShaderRecordLayout record_layout;
  // Empty: one pipeline. Otherwise the pipeline is linked from these
  // libraries and its own groups (R-LIBRARY); shaders observe the same.
  std::vector<PipelineLibrary> libraries;
};

struct ImageOutput {
  std::string name;
  std::string field;  // a record field: Uint fields -> r32ui, Float fields -> rgba32f
  SourceLoc loc;
  double tolerance = 1.0;           // scale of the field's tolerance (float images)
  uint32_t max_failing_pixels = 0;  // pixels allowed to differ before the image fails
  std::string equal_to;             // another image this one must equal texel for texel,
                                    // on the device and in the model (empty: none)
};

struct Outputs {
  std::vector<std::string> counters;  // every counter a `count` statement names
  // Comparison modes a case declares for some counters (`{anyhit: at_least}`):
  // exact, at_least, at_most or informational; the others are derived
  // (compare/counter_modes.h).
  std::map<std::string, std::string> counter_modes;
  std::map<std::string, SourceLoc> counter_mode_locs;  // where each declared mode is written
  std::vector<std::string> per_ray;                    // every field a `record` statement writes
  std::vector<ImageOutput> images;
};

// Undefined behaviour (R-UB) the parser finds where the values are constants:
// a ray parameter, an SBT index beyond its region. An error in a case that
// does not claim R-UB; kept here in a robustness probe, which does.
struct StaticUndefined {
  UndefinedReason reason = UndefinedReason::RayParameters;
  SourceLoc loc;
  std::string message;
};

// A shader the case expects the compiler to reject (expect_rejected,
// R-STAGE-INTERFACE): its name (Pipeline::shaderName) and the uses of an
// interface its stage cannot declare that the checker found in it
// (program/stage_interface.h).
struct ExpectedRejection {
  std::string shader;
  std::vector<InterfaceUse> uses;
  SourceLoc loc;
};

// A case name's family: its first folder ("anyhit" of
// "anyhit/ignore-odd-primitives"); none ("") for a name of one part, a file
// outside the cases folder named by its stem.
std::string caseFamily(const std::string& name);

struct Case {
  std::string name;  // e.g. "anyhit/ignore-odd-primitives"
  std::string file;  // path of the YAML file
  uint64_t source_hash =
      0;  // contentHash of the text parsed (a sweep: the variant's); --permute mixes in its seed
  std::string family;              // caseFamily(name): "anyhit"; "" for a file outside cases/
  std::vector<std::string> rules;  // rule labels (references/spec-rules.yaml)
  std::string description;
  Scene scene;
  Rays rays;
  Pipeline pipeline;
  Outputs outputs;
  std::vector<StaticUndefined> static_undefined;  // only in a case that claims R-UB
  // Shaders the compiler must reject; a case with any runs no launch: it is
  // judged by compiling them (run/judge_rejections.h).
  std::vector<ExpectedRejection> expected_rejections;
  bool claims(const std::string& rule) const {
    for (const std::string& r : rules)
      if (r == rule) return true;
    return false;
  }
};

}  // namespace rayspec
