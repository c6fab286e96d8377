// Case mutations of ray and pipeline flags: a device that ignores a flag.
#include "case/flag_names.h"
#include "fault/fault_impl.h"
#include "fault/planted_fault.h"
#include "fault/program_edit.h"

namespace rayspec {
namespace {

std::string ignoreFlags(Case& c, uint32_t ray_bits, uint32_t pipeline_bits, const char* what) {
  bool changed = clearRayFlags(c, ray_bits);
  if (c.pipeline.flags & pipeline_bits) changed = true;
  c.pipeline.flags &= ~pipeline_bits;
  return changed ? std::string(what) + " cleared" : std::string();
}

}  // namespace

std::string facingCullIgnored(Case& c, ModelOptions&) {
  return ignoreFlags(c, kRayCullBackFacing | kRayCullFrontFacing, 0,
                     "CullBackFacing / CullFrontFacing");
}

std::string rayOpacityIgnored(Case& c, ModelOptions&) {
  return ignoreFlags(c, kRayOpaque | kRayNoOpaque, 0, "Opaque / NoOpaque ray flags");
}

std::string opacityCullIgnored(Case& c, ModelOptions&) {
  return ignoreFlags(c, kRayCullOpaque | kRayCullNoOpaque, 0, "CullOpaque / CullNoOpaque");
}

// Only a device that does not find the closest hit first can show it: one
// that traverses far to near (legal) and ignores the flag.
std::string firstHitFlagIgnored(Case& c, ModelOptions& o) {
  o.faults.order = CandidateOrder::ReverseDistance;
  return ignoreFlags(c, kRayTerminateOnFirstHit, 0,
                     "TerminateOnFirstHit (candidates found far to near)");
}

std::string skipClosestHitIgnored(Case& c, ModelOptions&) {
  return ignoreFlags(c, kRaySkipClosestHit, 0, "SkipClosestHit");
}

std::string skipTrianglesIgnored(Case& c, ModelOptions&) {
  return ignoreFlags(c, kRaySkipTriangles, kPipelineSkipTriangles, "SkipTriangles");
}

std::string skipAabbsIgnored(Case& c, ModelOptions&) {
  return ignoreFlags(c, kRaySkipAabbs, kPipelineSkipAabbs, "SkipAABBs");
}

// R-ORDER-UNSPEC, legal: the candidates decided far to near (nothing to
// change in a scene of one candidate at most).
std::string reverseOrder(Case& c, ModelOptions& o) {
  if (oneCandidateAtMost(c.scene)) return "";
  o.faults.order = CandidateOrder::ReverseDistance;
  return "candidates decided far to near";
}

// R-ORDER-UNSPEC, legal: the candidates decided in a fixed shuffle (seed
// 1, 2 or 3), whatever their t: boxes entered at one t, ties and
// order-dependent programs meet another order than near to far or far to near.
template <uint32_t Seed>
std::string permutedOrder(Case& c, ModelOptions& o) {
  if (oneCandidateAtMost(c.scene)) return "";
  o.faults.order = CandidateOrder::Permuted;
  o.faults.order_seed = Seed;
  return "candidates decided in shuffle " + std::to_string(Seed);
}
template std::string permutedOrder<1>(Case&, ModelOptions&);
template std::string permutedOrder<2>(Case&, ModelOptions&);
template std::string permutedOrder<3>(Case&, ModelOptions&);

// R-WATERTIGHT not met: rays through a shared edge or vertex pass between
// its triangles where that changes the answer (what lies behind, or a miss).
std::string passBetweenEdges(Case&, ModelOptions& o) {
  o.faults.pass_between_edges = true;
  return "rays through shared edges pass between their triangles";
}

// An order-dependent device: every trace ends at its first confirmed
// candidate in the order of the build (instance, geometry, primitive).
std::string buildOrderFirstHit(Case& c, ModelOptions& o) {
  o.faults.order = CandidateOrder::BuildOrder;
  setRayFlags(c, kRayTerminateOnFirstHit);
  return "first confirmed candidate in build order wins";
}

}  // namespace rayspec
