// The implementations behind the fault table (internal to fault/): one
// function per fault, a record edit or a case mutation.
#pragma once

#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "base/vec3.h"
#include "fault/planted_fault.h"
#include "fault/record_edit.h"
#include "model/model_engine.h"

namespace rayspec {

struct RecordFaultArgs {
  const Case& c;
  RecordEdit& dev;        // the device's results, to corrupt
  const RecordView& mod;  // the model's results
  const Results& model;
  const std::set<uint32_t>& ambiguous;  // rays the model marks ambiguous
};
using RecordFaultFn = FaultResult (*)(RecordFaultArgs&);

// Changes the case (and the model's options) into what a device breaking the
// rule acts on; returns what it changed, empty when nothing (not applicable).
using CaseMutationFn = std::string (*)(Case&, ModelOptions&);

struct FaultImpl {
  const char* name;
  FaultKind kind;
  const char* breaks;
  RecordFaultFn record = nullptr;
  CaseMutationFn mutate = nullptr;
};
const std::vector<FaultImpl>& faultImpls();

FaultResult describeRay(uint32_t ray, const std::string& what);  // applied, "ray N: what"
FaultResult notApplicable(const std::string& why);

// A finding only the device shows (Results::device_findings), as the device
// side's own check would make it; the fault's description when it applies
// (record_faults_rules.cpp).
FaultResult plantDeviceFinding(RecordFaultArgs& a, DeviceFinding finding, std::string what);
// The faults of scene.build.queries: record edits and their live Vulkan
// faults (record_faults_queries.cpp).
std::vector<FaultImpl> queryFaults();

// Record edits (record_faults.cpp, record_faults_rules.cpp).
FaultResult dropMiss(RecordFaultArgs& a);
FaultResult swapPrimitiveId(RecordFaultArgs& a);
FaultResult chitAfterIgnore(RecordFaultArgs& a);
FaultResult shiftT(RecordFaultArgs& a);
FaultResult duplicateAnyHit(RecordFaultArgs& a);
FaultResult leakEdge(RecordFaultArgs& a);
FaultResult doubleHitEdge(RecordFaultArgs& a);
FaultResult missAfterClosestHit(RecordFaultArgs& a);
FaultResult hitKindFlipped(RecordFaultArgs& a);
FaultResult inactiveRenumbered(RecordFaultArgs& a);
FaultResult tmaxViewInitial(RecordFaultArgs& a);
FaultResult builtinWrong(RecordFaultArgs& a);
FaultResult indirectLaunchShort(RecordFaultArgs& a);
FaultResult launchDepthLost(RecordFaultArgs& a);
FaultResult zeroLaunchRuns(RecordFaultArgs& a);
FaultResult launchRowRepeated(RecordFaultArgs& a);
FaultResult launchRowLost(RecordFaultArgs& a);
FaultResult libraryHandleDiffers(RecordFaultArgs& a);
FaultResult memoryGuardOverwritten(RecordFaultArgs& a);
FaultResult tieAnsweredNeither(RecordFaultArgs& a);  // record_faults_ties.cpp

// Case mutations: scene (mutate_scene.cpp), boxes (mutate_boxes.cpp), ray
// flags and candidate order (mutate_flags.cpp), stage programs
// (mutate_programs.cpp), shader binding table (mutate_sbt.cpp).
std::string instanceMaskIgnored(Case& c, ModelOptions& o);
std::string facingInverted(Case& c, ModelOptions& o);
std::string worldSpaceFacing(Case& c, ModelOptions& o);
std::string cullDisableIgnored(Case& c, ModelOptions& o);
std::string instanceOpacityIgnored(Case& c, ModelOptions& o);
std::string anyHitOnOpaque(Case& c, ModelOptions& o);
std::string instanceTransformInverted(Case& c, ModelOptions& o);
std::string inactiveRevived(Case& c, ModelOptions& o);
std::string inactiveHidesLastActive(Case& c, ModelOptions& o);
std::string degenerateHit(Case& c, ModelOptions& o);
// Triangle p of g (through its indices): its vertices when they are finite
// and span no area (R-DEGEN: a segment or a point), else none.
std::optional<std::array<DVec3, 3>> degenerateTriangle(const Geometry& g, uint32_t p);
// Triangle p of g given the vertices t (an indexed one its own new vertices,
// as others may share its old ones).
void setTriangle(Geometry& g, uint32_t p, const std::array<Vec3, 3>& t);
std::string boxEnteredFromInsideMissed(Case& c, ModelOptions& o);
std::string zeroLengthRayBoxMissed(Case& c, ModelOptions& o);
std::string closestBoxSkipped(Case& c, ModelOptions& o);
std::string facingCullIgnored(Case& c, ModelOptions& o);
std::string rayOpacityIgnored(Case& c, ModelOptions& o);
std::string opacityCullIgnored(Case& c, ModelOptions& o);
std::string firstHitFlagIgnored(Case& c, ModelOptions& o);
std::string skipClosestHitIgnored(Case& c, ModelOptions& o);
std::string skipTrianglesIgnored(Case& c, ModelOptions& o);
std::string skipAabbsIgnored(Case& c, ModelOptions& o);
std::string incomingFlagsWithPipelineSkip(Case& c, ModelOptions& o);
std::string ignoreAccepts(Case& c, ModelOptions& o);
std::string codeAfterIgnoreRuns(Case& c, ModelOptions& o);
std::string terminateContinues(Case& c, ModelOptions& o);
std::string codeAfterTerminateRuns(Case& c, ModelOptions& o);
std::string reportReturnInverted(Case& c, ModelOptions& o);
std::string reportKindDropped(Case& c, ModelOptions& o);
std::string closestAnyHitSkipped(Case& c, ModelOptions& o);
std::string ignoreDiscardsWrites(Case& c, ModelOptions& o);
std::string unusedAnyHitIgnores(Case& c, ModelOptions& o);
std::string payloadWritesLost(Case& c, ModelOptions& o);
std::string payloadStartLost(Case& c, ModelOptions& o);
std::string payloadWordsLost(Case& c, ModelOptions& o);
std::string callDataWordsLost(Case& c, ModelOptions& o);
std::string cullMaskBuiltinDefault(Case& c, ModelOptions& o);
std::string noNullShadersDropped(Case& c, ModelOptions& o);
std::string tlasIgnored(Case& c, ModelOptions& o);
std::string raygenGroupIgnored(Case& c, ModelOptions& o);
std::string libraryGroupsLost(Case& c, ModelOptions& o);
std::string deferredGroupsLost(Case& c, ModelOptions& o);
std::string stackSizeIgnored(Case& c, ModelOptions& o);
std::string copyDropsInstance(Case& c, ModelOptions& o);
std::string updateIgnored(Case& c, ModelOptions& o);
std::string laterUpdatesIgnored(Case& c, ModelOptions& o);
std::string copyUpdateIgnored(Case& c, ModelOptions& o);
std::string updateDegenerateLost(Case& c, ModelOptions& o);
std::string creationEmptiesStructure(Case& c, ModelOptions& o);
std::string vertexFormatIgnored(Case& c, ModelOptions& o);
std::string vertexFormatConfused(Case& c, ModelOptions& o);
std::string positionFetchWorldSpace(Case& c, ModelOptions& o);
std::string localsLostAcrossCalls(Case& c, ModelOptions& o);
std::string sizedLocalsHalved(Case& c, ModelOptions& o);
std::string sizedVectorsRotated(Case& c, ModelOptions& o);
std::string sizedNullNotZero(Case& c, ModelOptions& o);
std::string structMemberLost(Case& c, ModelOptions& o);
std::string sizedPayloadHalved(Case& c, ModelOptions& o);
std::string sizedCallDataHalved(Case& c, ModelOptions& o);
std::string sizedAttributeHalved(Case& c, ModelOptions& o);
std::string loopTripOffByOne(Case& c, ModelOptions& o);
std::string bitwiseXorAsOr(Case& c, ModelOptions& o);
std::string crossOperandsSwapped(Case& c, ModelOptions& o);
std::string wordIndexOffByOne(Case& c, ModelOptions& o);
std::string tlasIndexOffByOne(Case& c, ModelOptions& o);
std::string matrixTransposed(Case& c, ModelOptions& o);
std::string floatBitsConverted(Case& c, ModelOptions& o);
std::string functionIgnoreLost(Case& c, ModelOptions& o);
std::string transformBuiltinsSwapped(Case& c, ModelOptions& o);
// Hit objects (mutate_hit_objects.cpp).
std::string hitObjectTraceShades(Case& c, ModelOptions& o);
std::string hitObjectStateWrong(Case& c, ModelOptions& o);
std::string hitObjectIdsSwapped(Case& c, ModelOptions& o);
std::string hitObjectTInitial(Case& c, ModelOptions& o);
std::string hitObjectObjectRayWorld(Case& c, ModelOptions& o);
std::string hitObjectMatricesSwapped(Case& c, ModelOptions& o);
std::string hitObjectAttributesLost(Case& c, ModelOptions& o);
std::string hitObjectSbtIndexOfInstance(Case& c, ModelOptions& o);
std::string hitObjectRecordSbtNoInstanceOffset(Case& c, ModelOptions& o);
std::string hitObjectRecordIndexPlusInstanceOffset(Case& c, ModelOptions& o);
std::string hitObjectRecordCustomIndexIsId(Case& c, ModelOptions& o);
std::string hitObjectRecordHandleOwn(Case& c, ModelOptions& o);
// Ray query statements (mutate_ray_query.cpp).
std::string queryInitKeepsCommitted(Case& c, ModelOptions& o);
std::string queryOffersOpaque(Case& c, ModelOptions& o);
std::string queryConfirmIgnored(Case& c, ModelOptions& o);
std::string queryGenerateIgnored(Case& c, ModelOptions& o);
std::string queryCandidateShrinksInterval(Case& c, ModelOptions& o);
std::string queryTerminateIgnored(Case& c, ModelOptions& o);
std::string queryBreakLosesCommit(Case& c, ModelOptions& o);
std::string queryFunctionGetsCopy(Case& c, ModelOptions& o);
std::string queryRestartKeepsCommitted(Case& c, ModelOptions& o);
std::string queryStepWrongQuery(Case& c, ModelOptions& o);
std::string queryCommittedReadsCandidate(Case& c, ModelOptions& o);
std::string queryCustomIndexIsInstanceId(Case& c, ModelOptions& o);
std::string queryCommitKeepsInterval(Case& c, ModelOptions& o);
std::string queryConfirmOnlyFirst(Case& c, ModelOptions& o);
std::string queryCandidateTypeSwapped(Case& c, ModelOptions& o);
std::string queryFrontFaceInverted(Case& c, ModelOptions& o);
std::string queryObjectRayWorld(Case& c, ModelOptions& o);
std::string wideLaunchTruncated(Case& c, ModelOptions& o);
std::string launchIdXWrapped(Case& c, ModelOptions& o);
std::string launchIdYzWrapped(Case& c, ModelOptions& o);
std::string addressWritesLost(Case& c, ModelOptions& o);
std::string specializationIgnored(Case& c, ModelOptions& o);
std::string emptyGeometryRenumbered(Case& c, ModelOptions& o);
std::string buildCounts16Bit(Case& c, ModelOptions& o);
std::string meshTriangleDropped(Case& c, ModelOptions& o);
std::string meshTriangleDuplicated(Case& c, ModelOptions& o);
std::string sharedScratchKeepsPrevious(Case& c, ModelOptions& o);
std::string hitAttributesLost(Case& c, ModelOptions& o);
std::string callableDataNotReturned(Case& c, ModelOptions& o);
std::string nestedTraceDropped(Case& c, ModelOptions& o);
std::string nestedTraceClobbersHit(Case& c, ModelOptions& o);
std::string intersectionRunsTwice(Case& c, ModelOptions& o);
std::string anyHitRunsTwice(Case& c, ModelOptions& o);
std::string hitRecordShifted(Case& c, ModelOptions& o);
std::string instanceSbtOffsetIgnored(Case& c, ModelOptions& o);
std::string missRecordShifted(Case& c, ModelOptions& o);
std::string callableRecordShifted(Case& c, ModelOptions& o);
std::string callableIndexIgnored(Case& c, ModelOptions& o);
std::string customIndexTruncated(Case& c, ModelOptions& o);
std::string zeroRecordRunsGroup0(Case& c, ModelOptions& o);
std::string shaderRecordDataZeroed(Case& c, ModelOptions& o);
std::string recordLayoutSwapped(Case& c, ModelOptions& o);
FaultResult stageInterfaceAccepted(RecordFaultArgs& a);
std::string reverseOrder(Case& c, ModelOptions& o);
template <uint32_t Seed>
std::string permutedOrder(Case& c, ModelOptions& o);  // Seed 1, 2, 3
std::string passBetweenEdges(Case& c, ModelOptions& o);
std::string buildOrderFirstHit(Case& c, ModelOptions& o);
// The interval ends (mutate_intervals.cpp).
std::string closedTriangleInterval(Case& c, ModelOptions& o);
std::string openAabbInterval(Case& c, ModelOptions& o);

}  // namespace rayspec
