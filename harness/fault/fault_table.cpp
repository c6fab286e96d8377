// Every planted fault: its name, its kind and the rule break it stands for.
#include <algorithm>

#include "fault/fault_impl.h"

namespace rayspec {

namespace {

// Edits of the device's own records.
std::vector<FaultImpl> recordEdits() {
  using K = FaultKind;
  return {
      // Record edits of the device's own results.
      {"drop-miss", K::RecordEdit, "a clear ray that missed runs no miss shader", dropMiss},
      {"stage-interface-accepted", K::RecordEdit,
       "the compiler accepts a payload in an intersection shader and a hit attribute in a miss "
       "shader",
       stageInterfaceAccepted},
      {"swap-primitive-id", K::RecordEdit, "two clear hit rays report each other's primitive id",
       swapPrimitiveId},
      {"chit-after-ignore", K::RecordEdit,
       "a clear ray that missed (its candidates ignored) runs closest-hit", chitAfterIgnore},
      {"shift-t", K::RecordEdit, "a clear hit's t is 1e-3 further", shiftT},
      {"duplicate-any-hit", K::RecordEdit,
       "any-hit runs twice for a NO_DUPLICATE_ANY_HIT primitive", duplicateAnyHit},
      {"leak-edge", K::RecordEdit,
       "a ray through a shared edge or vertex misses every triangle sharing it", leakEdge},
      {"double-hit-edge", K::RecordEdit,
       "a ray through a shared edge or vertex hits every triangle sharing it", doubleHitEdge},
      {"miss-after-closest-hit", K::RecordEdit, "a clear hit ray runs the miss shader too",
       missAfterClosestHit},
      {"hit-kind-flipped", K::RecordEdit,
       "triangle hits report the other face's hit kind (0xFE <-> 0xFF)", hitKindFlipped},
      {"inactive-renumbered", K::RecordEdit,
       "inactive primitives and null instances do not count for the ids of the others",
       inactiveRenumbered},
      {"tmax-view-initial", K::RecordEdit,
       "gl_RayTmaxEXT in intersection, any-hit and closest-hit reads the tmax the trace started "
       "with",
       tmaxViewInitial},
      {"builtin-wrong", K::RecordEdit, "a built-in a stage reads is off by one on a clear ray",
       builtinWrong},
      {"indirect-launch-short", K::RecordEdit,
       "an indirect trace reads the launch height as one less: the last row never runs",
       indirectLaunchShort},
      {"launch-depth-lost", K::RecordEdit,
       "a 3D launch runs only its first z layer: raygen never runs for z >= 1", launchDepthLost},
      {"zero-launch-runs", K::RecordEdit,
       "a launch with a zero dimension runs raygen once (its counter counts 1)", zeroLaunchRuns},
      {"launch-row-repeated", K::RecordEdit,
       "a launch of ids all alike (rays.same, counters only) runs its last row of ids twice",
       launchRowRepeated},
      {"launch-row-lost", K::RecordEdit,
       "a launch of ids all alike (rays.same, counters only) never runs its last row of ids",
       launchRowLost},
      {"library-handle-differs", K::RecordEdit,
       "a group handle read from a pipeline library differs from its handle in the linked "
       "pipeline",
       libraryHandleDiffers},
      {"memory-guard-overwritten", K::RecordEdit,
       "a build writes past the accelerationStructureSize it reported: the guard after the "
       "first structure changed (the finding the device side's guards make; "
       "build-writes-past-size makes it on a live device)",
       memoryGuardOverwritten},
      {"tie-answered-neither", K::RecordEdit,
       "a hit tied with another at the committed t (or at an interval end) is answered with "
       "neither: a miss",
       tieAnsweredNeither},
  };
}

// Case mutations of the scene and the flags.
std::vector<FaultImpl> sceneAndFlagMutations() {
  using K = FaultKind;
  return {
      // Case mutations: the scene as a breaking device sees it.
      {"instance-mask-ignored", K::CaseMutation,
       "instance masks are ignored (every instance visible)", nullptr, instanceMaskIgnored},
      {"facing-inverted", K::CaseMutation, "facing has the opposite sign (front and back swapped)",
       nullptr, facingInverted},
      {"world-space-facing", K::CaseMutation,
       "facing is decided in world space (a mirroring instance transform flips it)", nullptr,
       worldSpaceFacing},
      {"cull-disable-ignored", K::CaseMutation, "TRIANGLE_FACING_CULL_DISABLE is ignored", nullptr,
       cullDisableIgnored},
      {"instance-opacity-ignored", K::CaseMutation,
       "FORCE_OPAQUE / FORCE_NO_OPAQUE instance flags are ignored", nullptr,
       instanceOpacityIgnored},
      {"any-hit-on-opaque", K::CaseMutation, "any-hit runs on opaque candidates", nullptr,
       anyHitOnOpaque},
      {"instance-transform-inverted", K::CaseMutation,
       "the ray is taken into object space by the instance transform instead of its inverse",
       nullptr, instanceTransformInverted},
      {"inactive-revived", K::CaseMutation,
       "inactive primitives and null instances are hit (NaN X read as 0)", nullptr,
       inactiveRevived},
      {"inactive-hides-last-active", K::CaseMutation,
       "with k of n instances (null or mask 0x00) or primitives inactive, active ones at index n - "
       "k or later are lost (Mesa 26.2.6 lavapipe)",
       nullptr, inactiveHidesLastActive},
      {"degenerate-hit", K::CaseMutation, "degenerate triangles (lines, points) are hit", nullptr,
       degenerateHit},
      {"box-entered-from-inside-missed", K::CaseMutation,
       "a box the ray starts inside never runs its intersection shader", nullptr,
       boxEnteredFromInsideMissed},
      {"zero-length-ray-box-missed", K::CaseMutation,
       "a ray whose tmin equals its tmax is offered no box, even one holding its point", nullptr,
       zeroLengthRayBoxMissed},
      {"closest-box-skipped", K::CaseMutation,
       "the closest box a ray crosses never runs its intersection shader", nullptr,
       closestBoxSkipped},
      // Case mutations: ray and pipeline flags.
      {"facing-cull-ignored", K::CaseMutation, "CullBackFacing / CullFrontFacing are ignored",
       nullptr, facingCullIgnored},
      {"ray-opacity-ignored", K::CaseMutation, "the Opaque / NoOpaque ray flags are ignored",
       nullptr, rayOpacityIgnored},
      {"opacity-cull-ignored", K::CaseMutation, "CullOpaque / CullNoOpaque are ignored", nullptr,
       opacityCullIgnored},
      {"first-hit-flag-ignored", K::CaseMutation,
       "TerminateOnFirstHit is ignored (by a device finding candidates far to near)", nullptr,
       firstHitFlagIgnored},
      {"skip-closest-hit-ignored", K::CaseMutation, "SkipClosestHit is ignored", nullptr,
       skipClosestHitIgnored},
      {"skip-triangles-ignored", K::CaseMutation, "SkipTriangles (ray or pipeline flag) is ignored",
       nullptr, skipTrianglesIgnored},
      {"skip-aabbs-ignored", K::CaseMutation, "SkipAABBs (ray or pipeline flag) is ignored",
       nullptr, skipAabbsIgnored},
      {"incoming-flags-with-pipeline-skip", K::CaseMutation,
       "gl_IncomingRayFlagsEXT holds the pipeline's SKIP_TRIANGLES / SKIP_AABBS as ray flags",
       nullptr, incomingFlagsWithPipelineSkip},
  };
}

// Case mutations of the stage programs.
std::vector<FaultImpl> programMutations() {
  using K = FaultKind;
  return {
      // Case mutations: stage programs.
      {"ignore-accepts", K::CaseMutation, "ignoreIntersectionEXT accepts the candidate", nullptr,
       ignoreAccepts},
      {"code-after-ignore-runs", K::CaseMutation, "the statements after ignoreIntersectionEXT run",
       nullptr, codeAfterIgnoreRuns},
      {"terminate-continues", K::CaseMutation, "terminateRayEXT accepts but traversal goes on",
       nullptr, terminateContinues},
      {"code-after-terminate-runs", K::CaseMutation,
       "the statements after terminateRayEXT (and after the report it ends) run", nullptr,
       codeAfterTerminateRuns},
      {"report-return-inverted", K::CaseMutation,
       "reportIntersectionEXT returns the opposite of what it did", nullptr, reportReturnInverted},
      {"report-kind-dropped", K::CaseMutation, "reportIntersectionEXT's hit kind is lost (reads 0)",
       nullptr, reportKindDropped},
      {"closest-any-hit-skipped", K::CaseMutation,
       "any-hit never runs (the closest hit's included)", nullptr, closestAnyHitSkipped},
      {"ignore-discards-writes", K::CaseMutation,
       "an any-hit that ignores its candidate loses its counts and record writes made before "
       "the ignore (as a fragment discard)",
       nullptr, ignoreDiscardsWrites},
      {"unused-any-hit-ignores", K::CaseMutation,
       "a hit group without any-hit (or all-zero) ignores candidates", nullptr,
       unusedAnyHitIgnores},
      {"payload-writes-lost", K::CaseMutation,
       "payload writes of miss, closest-hit and any-hit never reach the caller", nullptr,
       payloadWritesLost},
      {"payload-start-lost", K::CaseMutation,
       "every trace starts with a zero payload, whatever the caller wrote into it", nullptr,
       payloadStartLost},
      {"payload-words-lost", K::CaseMutation,
       "only the first 24 bytes of a payload come back: writes to its words "
       "(pipeline.payloads), named or indexed, are lost",
       nullptr, payloadWordsLost},
      {"no-null-shaders-dropped", K::CaseMutation,
       "a pipeline with no_null_* flags runs as if every shader of those kinds were absent",
       nullptr, noNullShadersDropped},
      {"cull-mask-builtin-default", K::CaseMutation,
       "gl_CullMaskEXT reads 0xFF whatever cull mask the trace passed", nullptr,
       cullMaskBuiltinDefault},
      {"hit-attributes-lost", K::CaseMutation,
       "the attribute an intersection shader reports is lost (reads 0)", nullptr,
       hitAttributesLost},
      {"callable-data-not-returned", K::CaseMutation,
       "a callable's writes to its data never reach the caller", nullptr, callableDataNotReturned},
      {"call-data-words-lost", K::CaseMutation,
       "only the first 48 bytes of callable data come back: a callable's writes to its words "
       "(pipeline.callable_data), named or indexed, are lost",
       nullptr, callDataWordsLost},
      {"nested-trace-dropped", K::CaseMutation,
       "traces from closest-hit and miss do nothing (no recursion)", nullptr, nestedTraceDropped},
      {"nested-trace-clobbers-hit", K::CaseMutation,
       "after a nested trace that hits, the closest-hit that made it reads the nested hit's "
       "built-ins (a nested ray query sharing its caller's query)",
       nullptr, nestedTraceClobbersHit},
      {"any-hit-runs-twice", K::CaseMutation,
       "legal: any-hit runs twice in a row for a primitive whose geometry lacks "
       "no_duplicate_any_hit",
       nullptr, anyHitRunsTwice},
      {"intersection-runs-twice", K::CaseMutation,
       "legal: every intersection shader runs twice in a row for its primitive", nullptr,
       intersectionRunsTwice},
  };
}

// Case mutations of the shader binding table, the candidate order and the interval.
std::vector<FaultImpl> sbtAndOrderMutations() {
  using K = FaultKind;
  return {
      {"hit-record-shifted", K::CaseMutation,
       "closest-hit of the wrong SBT record (record i runs record i+1's group)", nullptr,
       hitRecordShifted},
      {"instance-sbt-offset-ignored", K::CaseMutation, "the instance SBT record offset is ignored",
       nullptr, instanceSbtOffsetIgnored},
      {"miss-record-shifted", K::CaseMutation, "the miss shader of the wrong SBT record runs",
       nullptr, missRecordShifted},
      {"callable-record-shifted", K::CaseMutation, "executeCallableEXT(i) runs callable record i+1",
       nullptr, callableRecordShifted},
      {"callable-index-ignored", K::CaseMutation,
       "executeCallableEXT(i) runs callable record 0 whatever i", nullptr, callableIndexIgnored},
      {"custom-index-truncated", K::CaseMutation, "instanceCustomIndex keeps 16 of its 24 bits",
       nullptr, customIndexTruncated},
      {"zero-record-runs-group-0", K::CaseMutation,
       "an all-zero SBT record runs the shaders of group 0", nullptr, zeroRecordRunsGroup0},
      {"shader-record-data-zeroed", K::CaseMutation,
       "shaders read zeros instead of their shader record data", nullptr, shaderRecordDataZeroed},
      {"record-layout-swapped", K::CaseMutation,
       "the shader record block is laid out by the other rule (std430 for scalar, scalar for "
       "std430)",
       nullptr, recordLayoutSwapped},
      // Case mutations: candidate order (a model option).
      {"reverse-order", K::CaseMutation, "legal: candidates are found far to near", nullptr,
       reverseOrder},
      {"permuted-order-1", K::CaseMutation,
       "legal: candidates are found in a fixed shuffle (seed 1), whatever their t", nullptr,
       permutedOrder<1>},
      {"permuted-order-2", K::CaseMutation,
       "legal: candidates are found in a fixed shuffle (seed 2), whatever their t", nullptr,
       permutedOrder<2>},
      {"permuted-order-3", K::CaseMutation,
       "legal: candidates are found in a fixed shuffle (seed 3), whatever their t", nullptr,
       permutedOrder<3>},
      {"pass-between-edges", K::CaseMutation,
       "rays through a shared edge or vertex pass between its triangles (to what lies behind, or "
       "a miss)",
       nullptr, passBetweenEdges},
      {"build-order-first-hit", K::CaseMutation,
       "the answer depends on the order: the first confirmed candidate in build order wins",
       nullptr, buildOrderFirstHit},
      // Case mutations: the interval ends, judged the wrong way where they are exact.
      {"closed-triangle-interval", K::CaseMutation,
       "a triangle at exactly tmin or tmax is a candidate", nullptr, closedTriangleInterval},
      {"open-aabb-interval", K::CaseMutation,
       "reportIntersectionEXT at exactly tmin or the current tmax returns false", nullptr,
       openAabbInterval},
  };
}

// Faults of how the pipeline and the top levels are built.
std::vector<FaultImpl> pipelineMutations() {
  using K = FaultKind;
  return {
      {"library-groups-lost", K::CaseMutation,
       "the groups a pipeline library holds do nothing once linked (their shaders run empty, "
       "any-hit and intersection absent)",
       nullptr, libraryGroupsLost},
      {"deferred-groups-lost", K::CaseMutation,
       "a pipeline created through a deferred operation is used before the operation completed: "
       "its miss, hit and callable groups do nothing (shaders empty, any-hit and intersection "
       "absent)",
       nullptr, deferredGroupsLost},
      {"raygen-group-ignored", K::CaseMutation,
       "the launch runs raygen group 0, whichever group the raygen region's record holds", nullptr,
       raygenGroupIgnored},
      {"tlas-ignored", K::CaseMutation,
       "every trace and ray query traverses the first top level, whichever one it names (a "
       "constant or a dynamic index)",
       nullptr, tlasIgnored},
      {"tlas-index-off-by-one", K::CaseMutation,
       "a dynamically indexed array of top levels is read one element on: tlas: expr traverses "
       "level (expr + 1) % the levels (a descriptor stride or base misread)",
       nullptr, tlasIndexOffByOne},
      {"stack-size-ignored", K::CaseMutation,
       "the pipeline stack size a trace sets is ignored: callables nested deeper than the "
       "default stack's two frames do nothing",
       nullptr, stackSizeIgnored},
  };
}

// Faults of acceleration structure copies, updates and vertex formats.
std::vector<FaultImpl> structureMutations() {
  using K = FaultKind;
  return {
      {"copy-drops-instance", K::CaseMutation,
       "a cloned or compacted top level loses its last active instance", nullptr,
       copyDropsInstance},
      {"update-ignored", K::CaseMutation,
       "an acceleration structure update changes nothing: traces see the scene as first built",
       nullptr, updateIgnored},
      {"later-updates-ignored", K::CaseMutation,
       "only the first update of a structure takes effect: a second update changes nothing",
       nullptr, laterUpdatesIgnored},
      {"update-degenerate-lost", K::CaseMutation,
       "triangles and boxes degenerate when first built are left out and stay out when an "
       "update makes them whole",
       nullptr, updateDegenerateLost},
      {"creation-empties-structure", K::CaseMutation,
       "creating an acceleration structure over a built one (scene.build.storage reused) leaves "
       "the built one empty: the top level holds no instance",
       nullptr, creationEmptiesStructure},
      {"copy-update-ignored", K::CaseMutation,
       "an update of a cloned, compacted or deserialized structure changes nothing", nullptr,
       copyUpdateIgnored},
      {"vertex-format-ignored", K::CaseMutation,
       "vertices in half or normalized formats are traced where the case wrote them, not where "
       "the format puts them",
       nullptr, vertexFormatIgnored},
      {"vertex-format-confused", K::CaseMutation,
       "each vertex format is read as another (unorm as snorm and back, float2 as half4 and "
       "back, half2 as unorm16x2, float4 as float3, half3 as half2, snorm16x3 as snorm16x2, "
       "unorm10x3 with R and B "
       "swapped): the model's side of the layout fault vertex-format-misread",
       nullptr, vertexFormatConfused},
      {"position-fetch-world-space", K::CaseMutation,
       "gl_HitTriangleVertexPositionsEXT gives the vertices through the instance transform "
       "(world space), not in object space",
       nullptr, positionFetchWorldSpace},
      {"build-counts-16-bit", K::CaseMutation,
       "a build keeps each geometry's primitive count and its instance count in 16 bits: "
       "2^16 primitives or instances become none, 2^16 + k the first k",
       nullptr, buildCounts16Bit},
      {"mesh-triangle-dropped", K::CaseMutation,
       "a build loses the middle triangle of a mesh (the first of 4 to 65,536 triangles, or a "
       "mesh split into as many geometries or instances): nothing is found where it lay",
       nullptr, meshTriangleDropped},
      {"mesh-triangle-duplicated", K::CaseMutation,
       "a build keeps the middle triangle of a mesh (as above) twice, the copy a primitive of its "
       "own: a ray through it finds two",
       nullptr, meshTriangleDuplicated},
      {"shared-scratch-keeps-previous", K::CaseMutation,
       "builds one after another in the same scratch memory (scene.build.one_by_one) build "
       "what the one before left there: every BLAS after the first traces as the one before it",
       nullptr, sharedScratchKeepsPrevious},
  };
}

// Hit objects (VK_NV_ray_tracing_invocation_reorder), broken on the model.
std::vector<FaultImpl> hitObjectMutations() {
  using K = FaultKind;
  return {
      {"hit-object-trace-shades", K::CaseMutation,
       "hitObjectTraceRayNV runs closest-hit or miss at once, as traceRayEXT does (and "
       "executing the hit object runs it again)",
       nullptr, hitObjectTraceShades},
      {"hit-object-state-wrong", K::CaseMutation,
       "hitObjectIsMissNV and hitObjectIsEmptyNV each answer the other", nullptr,
       hitObjectStateWrong},
      {"hit-object-ids-swapped", K::CaseMutation,
       "the hit object's instance id and custom index each read the other, so do its primitive "
       "and geometry index, and its hit kind is the other face's",
       nullptr, hitObjectIdsSwapped},
      {"hit-object-t-initial", K::CaseMutation,
       "hitObjectGetRayTMaxNV of a hit reads the tmax its trace started with", nullptr,
       hitObjectTInitial},
      {"hit-object-object-ray-world", K::CaseMutation,
       "the hit object's object-space ray reads the world-space ray", nullptr,
       hitObjectObjectRayWorld},
      {"hit-object-matrices-swapped", K::CaseMutation,
       "the hit object's object-to-world and world-to-object matrices each read the other", nullptr,
       hitObjectMatricesSwapped},
      {"hit-object-attributes-lost", K::CaseMutation,
       "hitObjectGetAttributesNV writes zero attributes", nullptr, hitObjectAttributesLost},
      {"hit-object-sbt-index-of-instance", K::CaseMutation,
       "hitObjectGetShaderBindingTableRecordIndexNV reads the hit instance's SBT offset alone "
       "(no geometry index times the stride, no trace offset), a miss's 0",
       nullptr, hitObjectSbtIndexOfInstance},
      {"hit-object-record-sbt-no-instance-offset", K::CaseMutation,
       "hitObjectRecordHitNV's record leaves out the instance's SBT offset (only the given "
       "offset plus geometry index times stride)",
       nullptr, hitObjectRecordSbtNoInstanceOffset},
      {"hit-object-record-index-plus-instance-offset", K::CaseMutation,
       "hitObjectRecordHitWithIndexNV adds the instance's SBT offset to the record index given",
       nullptr, hitObjectRecordIndexPlusInstanceOffset},
      {"hit-object-record-custom-index-is-id", K::CaseMutation,
       "a hit recorded by hand reports its instance id as its custom index "
       "(hitObjectGetInstanceCustomIndexNV)",
       nullptr, hitObjectRecordCustomIndexIsId},
      {"hit-object-record-handle-own", K::CaseMutation,
       "hitObjectGetShaderRecordBufferHandleNV addresses the calling stage's own shader record, "
       "not the hit object's",
       nullptr, hitObjectRecordHandleOwn},
  };
}

// Faults of values live across calls and of the sized members of the
// pipeline interface.
std::vector<FaultImpl> liveStateMutations() {
  using K = FaultKind;
  return {
      {"locals-lost-across-calls", K::CaseMutation,
       "a shader's local variables read zero after its traceRayEXT, executeCallableEXT or "
       "reportIntersectionEXT (live values spilled and restored wrongly)",
       nullptr, localsLostAcrossCalls},
      {"sized-locals-halved-across-calls", K::CaseMutation,
       "a local (a struct member too) of a sized scalar or vector type (int8 .. f64vec4, "
       "uvec2 .. uvec4) comes back from its "
       "traceRayEXT, executeCallableEXT or reportIntersectionEXT through a slot half its "
       "width (narrow and wide registers spilled wrongly): the lower half of its bits zero",
       nullptr, sizedLocalsHalved},
      {"sized-vectors-rotated-across-calls", K::CaseMutation,
       "a local of a sized vector type (i8vec2 .. f64vec4) comes back from its traceRayEXT, "
       "executeCallableEXT or reportIntersectionEXT with its components rotated (x takes "
       "y's, the last takes x's: a vector's lanes spilled to the wrong slots)",
       nullptr, sizedVectorsRotated},
      {"sized-null-initialiser-lost", K::CaseMutation,
       "an array of a sized type, declared with a null initialiser (= {}, an "
       "OpConstantNull), starts with every element one (1 or 1.0 in each lane) instead of "
       "zero",
       nullptr, sizedNullNotZero},
      {"struct-member-lost-across-calls", K::CaseMutation,
       "a struct local comes back from its traceRayEXT, executeCallableEXT or "
       "reportIntersectionEXT short by its last member, which reads zero (a struct spilled "
       "and restored one member short)",
       nullptr, structMemberLost},
      {"sized-payload-halved-across-trace", K::CaseMutation,
       "a payload's sized members (pipeline.payloads[].sized: int8 .. f64vec4) come back "
       "from traceRayEXT through slots half their width (narrow and wide interface members "
       "laid out or spilled wrongly): the lower half of each one's bits zero",
       nullptr, sizedPayloadHalved},
      {"sized-call-data-halved-across-call", K::CaseMutation,
       "callable data's sized members (pipeline.callable_data[].sized) come back from "
       "executeCallableEXT with the lower half of each one's bits zero",
       nullptr, sizedCallDataHalved},
      {"sized-attribute-halved-to-candidate", K::CaseMutation,
       "the sized members of the hit attribute (pipeline.hit_attribute.sized) reach any-hit "
       "and closest-hit from reportIntersectionEXT with the lower half of each one's bits zero",
       nullptr, sizedAttributeHalved},
  };
}

// Faults of shader code, launches and geometry numbering.
std::vector<FaultImpl> codeAndLaunchMutations() {
  using K = FaultKind;
  return {
      {"loop-trip-off-by-one", K::CaseMutation, "every repeat runs one trip more than its count",
       nullptr, loopTripOffByOne},
      {"bitwise-xor-as-or", K::CaseMutation, "bit_xor (^) is computed as bit_or (|)", nullptr,
       bitwiseXorAsOr},
      {"word-index-off-by-one", K::CaseMutation,
       "a payload or callable data word indexed by a value is read and written one word too "
       "far ((i + 1) % N)",
       nullptr, wordIndexOffByOne},
      {"cross-operands-swapped", K::CaseMutation, "cross(a, b) is computed as cross(b, a)", nullptr,
       crossOperandsSwapped},
      {"matrix-transposed", K::CaseMutation, "a matrix times a vector uses the transpose", nullptr,
       matrixTransposed},
      {"float-bits-converted", K::CaseMutation,
       "floatBitsToUint and uintBitsToFloat convert the value instead of keeping its bits", nullptr,
       floatBitsConverted},
      {"transform-builtins-swapped", K::CaseMutation,
       "gl_ObjectToWorldEXT and gl_WorldToObjectEXT (and their 3x4 forms) each read the other "
       "matrix",
       nullptr, transformBuiltinsSwapped},
      {"wide-launch-truncated", K::CaseMutation,
       "a launch wider than 65536 ids in x runs raygen only for x below 65536", nullptr,
       wideLaunchTruncated},
      {"address-writes-lost", K::CaseMutation,
       "with an empty pipeline layout, what the stages other than raygen write through device "
       "addresses is lost",
       nullptr, addressWritesLost},
      {"launch-id-x-wrapped", K::CaseMutation,
       "gl_LaunchIDEXT.x reads modulo 65536 in every stage (a launch wider than that repeats "
       "the first ids)",
       nullptr, launchIdXWrapped},
      {"launch-id-yz-wrapped", K::CaseMutation,
       "gl_LaunchIDEXT.y and .z read modulo 4096 in every stage (a launch deeper than that "
       "repeats the first rows and layers)",
       nullptr, launchIdYzWrapped},
      {"specialization-ignored", K::CaseMutation,
       "every shader runs with the specialization constants' defaults, whatever its "
       "VkSpecializationInfo sets",
       nullptr, specializationIgnored},
      {"function-ignore-lost", K::CaseMutation,
       "ignoreIntersectionEXT and terminateRayEXT inside a function only return from it", nullptr,
       functionIgnoreLost},
      {"empty-geometry-renumbered", K::CaseMutation,
       "geometries without primitives and instances of empty BLASes do not count for the "
       "geometry index, instance id and SBT index of the others",
       nullptr, emptyGeometryRenumbered},
  };
}

// Faults of the device's child process.
// The ray_query statement's rules broken (model/model_faults.h's rq_*).
std::vector<FaultImpl> rayQueryMutations() {
  using K = FaultKind;
  return {
      {"query-init-keeps-committed", K::CaseMutation,
       "rayQueryInitializeEXT keeps the committed intersection of the launch ray's last query",
       nullptr, queryInitKeepsCommitted},
      {"query-offers-opaque", K::CaseMutation,
       "a ray query returns opaque triangles as candidates (committed only when confirmed)",
       nullptr, queryOffersOpaque},
      {"query-confirm-ignored", K::CaseMutation, "rayQueryConfirmIntersectionEXT commits nothing",
       nullptr, queryConfirmIgnored},
      {"query-generate-ignored", K::CaseMutation, "rayQueryGenerateIntersectionEXT commits nothing",
       nullptr, queryGenerateIgnored},
      {"query-candidate-shrinks-interval", K::CaseMutation,
       "a ray query's interval shrinks to each candidate it returns, committed or not", nullptr,
       queryCandidateShrinksInterval},
      {"query-break-loses-commit", K::CaseMutation,
       "a ray query whose loop a break leaves before rayQueryProceedEXT returns false has "
       "nothing committed",
       nullptr, queryBreakLosesCommit},
      {"query-function-gets-copy", K::CaseMutation,
       "a function's rayQueryEXT parameter is a copy: its confirm, generate and terminate do not "
       "reach the caller's query",
       nullptr, queryFunctionGetsCopy},
      {"query-restart-keeps-committed", K::CaseMutation,
       "rayQueryInitializeEXT of a query in traversal (restart_query) keeps what is committed",
       nullptr, queryRestartKeepsCommitted},
      {"query-step-wrong-query", K::CaseMutation,
       "stepping an array of ray queries (ray_queries) proceeds the next element: each query's "
       "blocks decide the next query's candidates",
       nullptr, queryStepWrongQuery},
      {"query-terminate-ignored", K::CaseMutation,
       "neither rayQueryTerminateEXT nor a commit under TerminateOnFirstHit ends a ray query's "
       "traversal",
       nullptr, queryTerminateIgnored},
      {"query-committed-reads-candidate", K::CaseMutation,
       "the committed getters of a ray query read the current candidate while there is one",
       nullptr, queryCommittedReadsCandidate},
      {"query-custom-index-is-instance-id", K::CaseMutation,
       "a ray query's instance custom index getters read the instance id", nullptr,
       queryCustomIndexIsInstanceId},
      {"query-commit-beyond-committed-t", K::CaseMutation,
       "a ray query's commits leave its interval at tmax: a triangle beyond the committed t is "
       "still offered and confirming it, like a generate beyond the committed t, replaces the "
       "closer commit",
       nullptr, queryCommitKeepsInterval},
      {"query-confirm-only-first", K::CaseMutation,
       "rayQueryConfirmIntersectionEXT commits nothing once something is committed: the second "
       "of two confirmed candidates (offered far to near) is dropped",
       nullptr, queryConfirmOnlyFirst},
      {"query-candidate-type-swapped", K::CaseMutation,
       "a ray query's candidate type reads AABB for a triangle and triangle for an AABB (each "
       "runs the other block)",
       nullptr, queryCandidateTypeSwapped},
      {"query-front-face-inverted", K::CaseMutation,
       "a ray query's front face getters read a triangle's other face (culling unchanged)", nullptr,
       queryFrontFaceInverted},
      {"query-object-ray-world", K::CaseMutation,
       "a ray query candidate's object-space ray getters read the world-space ray (the "
       "crossing of a box, sphere_*, computed from it)",
       nullptr, queryObjectRayWorld},
  };
}

std::vector<FaultImpl> processFaults() {
  using K = FaultKind;
  return {
      // Process faults, raised in the device's child process.
      {"crash", K::Process, "the device process dies (SIGSEGV) after the run"},
      {"crash-once", K::Process,
       "the device process dies (SIGSEGV) the first time each case runs, not in its re-run"},
      {"crash-if-reused", K::Process,
       "the device process dies (SIGSEGV) after a case when it ran one of this fault's cases "
       "before (state an earlier case left behind)"},
      {"hang", K::Process, "the device process never returns"},
  };
}

// Faults made on a live device (run/fault_seam.cpp arms them by name): a
// Vulkan call that fails (vulkan/device_errors.cpp) or builds that misread
// their inputs (vulkan/vk_fault_hook.h, LayoutFault).
std::vector<FaultImpl> vulkanFaults() {
  using K = FaultKind;
  return {
      {"device-lost", K::Vulkan,
       "vkWaitForFences returns VK_ERROR_DEVICE_LOST: the case is a Crash and the next case gets "
       "a new device"},
      {"out-of-device-memory", K::Vulkan,
       "vkAllocateMemory returns VK_ERROR_OUT_OF_DEVICE_MEMORY: the case is NotSupported, never "
       "a pass"},
      {"pipeline-refused", K::Vulkan,
       "vkCreateRayTracingPipelinesKHR returns VK_ERROR_INITIALIZATION_FAILED for a pipeline the "
       "validation layer accepts: the case Fails (Refused)"},
      {"stride-ignored", K::Vulkan,
       "the builds read vertices and AABBs tightly packed, whatever their stride "
       "(scene.build.vertex_stride, aabb_stride)"},
      {"offsets-ignored", K::Vulkan,
       "the builds read primitiveOffset, firstVertex and transformOffset as 0"},
      {"pointers-reversed", K::Vulkan,
       "a top level built from an array of instance pointers reads them in reverse order"},
      {"vertex-format-misread", K::Vulkan,
       "the builds read each vertex format as another (unorm as snorm and back, float2 as half4 "
       "and back, float4 as float3, half3 as half2, snorm16x3 as snorm16x2, half2 as unorm16x2, "
       "unorm10x3 with R and B swapped)"},
      {"build-writes-past-size", K::Vulkan,
       "a build writes past the accelerationStructureSize it reported: 4 bytes of the guard "
       "after the first structure overwritten"},
      {"creation-clears-memory", K::Vulkan,
       "creating an acceleration structure over memory a built one holds zeroes that memory"},
      {"deferred-handle-early", K::Vulkan,
       "a pipeline created through a deferred operation is taken as its output slot held it "
       "before the operation wrote it (VK_NULL_HANDLE), as a harness reading the handle before "
       "the operation completes sees it on a driver that writes it at completion"},
      {"sparse-page-lost", K::Vulkan,
       "the second page of each sparse geometry and instance buffer (scene.build.sparse) loses "
       "its binding once filled: the builds read zeros there"},
  };
}

}  // namespace

const std::vector<FaultImpl>& faultImpls() {
  static const std::vector<FaultImpl> table = [] {
    std::vector<FaultImpl> all;
    for (auto part :
         {recordEdits, sceneAndFlagMutations, programMutations, sbtAndOrderMutations,
          pipelineMutations, structureMutations, liveStateMutations, codeAndLaunchMutations,
          rayQueryMutations, hitObjectMutations, processFaults, vulkanFaults, queryFaults})
      for (FaultImpl& f : part()) all.push_back(std::move(f));
    return all;
  }();
  return table;
}

const std::vector<FaultInfo>& faultTable() {
  static const std::vector<FaultInfo> table = [] {
    std::vector<FaultInfo> t;
    for (const FaultImpl& f : faultImpls()) t.push_back({f.name, f.kind, f.breaks});
    return t;
  }();
  return table;
}

const FaultInfo* findFault(const std::string& name) {
  for (const FaultInfo& f : faultTable())
    if (f.name == name) return &f;
  return nullptr;
}

const std::vector<std::string>& faultNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const FaultInfo& f : faultTable()) n.push_back(f.name);
    return n;
  }();
  return names;
}

bool isFaultName(const std::string& name) {
  return findFault(name) != nullptr;
}

const char* faultKindText(FaultKind kind) {
  switch (kind) {
    case FaultKind::RecordEdit:
      return "the model's results, one record edited";
    case FaultKind::CaseMutation:
      return "the model run on the case as the faulty device sees it";
    case FaultKind::Process:
      return "the device's process (a live device)";
    case FaultKind::Vulkan:
      return "a live device's Vulkan calls";
  }
  return "";
}

bool isProcessFault(const std::string& name) {
  const FaultInfo* f = findFault(name);
  return f && f->kind == FaultKind::Process;
}

}  // namespace rayspec
