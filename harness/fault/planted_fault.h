// Planted faults (test only): the results a device that breaks one rule would
// give, put in place of a device's results after it ran and before the
// comparison, so tests can show that the comparison catches each rule break.
// `rayspec run --plant-fault NAME`; `faultTable()` lists every fault with the
// break it stands for (fault_table.cpp); `rayspec faults` prints it with the
// rules each breaks. Four kinds:
//   record edits    one field or run count of the device's own records
//                   changed (e.g. drop-miss: a clear ray's miss did not run)
//   case mutations  the model's exact tier run on the case as a device that
//                   breaks the rule sees it (e.g. instance-mask-ignored: every
//                   instance mask 0xFF); its results replace the device's
//   process faults  raised in the device's child process: crash, crash-once,
//                   crash-if-reused, hang
//   Vulkan faults   made on a live device (run/fault_seam.h arms them): a
//                   Vulkan call fails (vulkan/device_errors.h) or the builds
//                   misread their inputs (vulkan/vk_fault_hook.h's layout faults)
// rule_faults.h maps each rule of the catalog to the faults that break it.
#pragma once

#include <string>
#include <vector>

#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"

namespace rayspec {

enum class FaultKind { RecordEdit, CaseMutation, Process, Vulkan };

struct FaultInfo {
  std::string name;
  FaultKind kind = FaultKind::RecordEdit;
  std::string breaks;  // what the device does wrong, one line
};

const std::vector<FaultInfo>& faultTable();
const FaultInfo* findFault(const std::string& name);
const std::vector<std::string>& faultNames();
bool isFaultName(const std::string& name);
bool isProcessFault(const std::string& name);  // crash, crash-once, crash-if-reused, hang
const char* faultKindText(FaultKind kind);     // where the fault is made, a few words

struct FaultResult {
  bool applied = false;
  std::string what;  // what was corrupted ("ray 17: miss_runs 1 -> 0"), or why nothing was
};

// Corrupts `device` by the results fault `name`; `model` (the exact tier's
// results) chooses the rays (clear or ambiguous). A case mutation replaces
// the device's counters, records and images by the model's run of the mutated
// case. Process faults, Vulkan faults and unknown names change nothing.
FaultResult plantFault(const std::string& name, const Case& c, const Plan& plan, Results& device,
                       const Results& model);

// The model's exact-tier results as a device that answers every ambiguous ray
// one legal way: where a ray through a shared edge or vertex ran any-hit for
// each of the k triangles sharing it (the model's enumeration), the device
// ran it for one (R-WATERTIGHT). Otherwise the model's results unchanged.
Results perfectDevice(const Case& c, const Results& model);

// The model's exact tier as a device that answers every ambiguous ray by its
// legal answer of index `answer` (modulo their number; 0: the model's own),
// the ray's shaders run as that answer makes them run (legalAnswerDevice);
// or that passes between the triangles of every shared edge or vertex it
// crosses where that changes the answer (passBetweenEdgesDevice: R-WATERTIGHT,
// a "should", not met). Each as perfectDevice gives it; `threads` for the model.
Results legalAnswerDevice(const Case& c, const Plan& plan, uint32_t answer, unsigned threads);
Results passBetweenEdgesDevice(const Case& c, const Plan& plan, unsigned threads);
// The model's exact tier as a device whose AABB test takes in each box's
// neighbours (R-AABB-CONS: conservative, legal): intersection programs run
// for every box grown by its own extent on each side.
Results aabbNeighboursDevice(const Case& c, const Plan& plan, unsigned threads);
// The model's exact tier as a device that offers every box a ray passes
// within its error bound of (R-AABB-CONS, R-PREC: model/box_bound.h), the
// boxes the model's own ray misses among them (a far origin's rounding).
Results aabbNearDevice(const Case& c, const Plan& plan, unsigned threads);

// The model's exact tier as devices that decide one candidate after every
// other, the rest near to far (R-ORDER-UNSPEC: a device may meet last the
// candidate whose any-hit or query block terminates, and run every other's
// first): one per key (instance, geometry, primitive) of a scene of at most
// kMaxLastCandidates keys, none for a larger one nor for a scene of one key
// (its one order is the model's). Each as perfectDevice gives it, named
// "last-<instance>.<geometry>.<primitive>".
constexpr size_t kMaxLastCandidates = 8;
struct NamedDevice {
  std::string name;
  Results device;
};
std::vector<NamedDevice> lastCandidateDevices(const Case& c, const Plan& plan, unsigned threads);
// Whether the scene holds one candidate key (instance, geometry, primitive)
// at most: every trace then meets its candidates in the one order there is,
// and a device deciding them in another order answers as the model does.
bool oneCandidateAtMost(const Scene& scene);

// crash: raises SIGSEGV; crash-once: the same, but only the first time the
// case runs into the run folder run_dir (a flaky driver: the re-run passes);
// crash-if-reused: the same, but only in a process that raised it for a case
// before (a long-lived worker; a process of its own per case never crashes);
// hang: sleeps forever; otherwise returns.
void raiseProcessFault(const std::string& name, const std::string& case_name,
                       const std::string& run_dir);

}  // namespace rayspec
