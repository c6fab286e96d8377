// `rayspec export CASE --format c`: one failing case as one standalone C
// file that a driver developer builds with `cc repro.c -lvulkan -o repro`
// and runs without rayspec (issue 57). Design:
//
//  - The file is a fixed, generic player (harness/export/player/, embedded in the binary
//    at build time) with the case's data spliced in. The player creates the
//    instance and device, builds bottom levels, the top level, the pipeline,
//    the SBT and the descriptor set, traces, reads back and compares; it
//    knows nothing of the case but what the data arrays say.
//  - The data is what the Vulkan engine (harness/vulkan/) itself computes
//    for the case, taken from the same functions, never retyped: the GLSL
//    (generateGlsl) and its SPIR-V (compilePipeline, through the compile
//    cache), the build inputs as the builds lay them out (layTriangles:
//    vertex bytes, strides, ranges), the instances, the SBT records in the
//    engine's group order (sbt_layout.h), the rays (packRays), and the
//    bindings (caseBindings over the SPIR-V's declared ones). Only the
//    device's numbers (handle size, alignments) are read by the player at
//    run time, as the engine reads them.
//  - The expectations are the model's exact tier, as the judge compares
//    them (compare/compare_records.cpp): each clear ray's record in the
//    compared fields (comparedRecordFields: integers exact, floats within
//    the field's tolerance), each ambiguous ray against every legal answer
//    the model replayed through the launch ray (the record must be one of
//    them; or one of the double hits and leaks at a shared edge or vertex
//    the model replayed too, which the judge accepts with a QualityWarning,
//    AmbiguousRecordJudge saying which), undefined rays (R-UB) not judged,
//    and each counter exact, bounded (at_least, at_most) or not judged
//    (informational). Float tolerances are the judge's (fieldTolerance),
//    each ray's bounds as the judge widens them (ModelRayBounds).
//  - What the player does not play yet is refused (export_support.h):
//    "export: case uses X, not yet exported".
// The player's exit status: 0 PASS (or QualityWarning: R-WATERTIGHT warned,
// a last line "QualityWarning: ..." for PASS's, as rayspec run exits 0 on
// it), 1 FAIL (rule, ray, field, expected, observed), 77 NotSupported (the
// feature named), 2 a Vulkan error.
#pragma once

#include <string>

#include "base/result.h"
#include "case/case.h"
#include "plan/plan.h"
#include "results/results.h"
#include "vulkan/vk_fault_hook.h"

namespace rayspec {

// The file an export writes, and how its header says to build and run it
// (`rayspec export` and `rayspec reduce` write it; report.md quotes these).
inline constexpr const char* kReproducerFile = "repro.c";
inline constexpr const char* kReproducerBuildLine = "cc repro.c -lvulkan -o repro";
inline constexpr const char* kReproducerRunLine = "./repro [DEVICE]";

// The C file of case c, its expectations from `model` (the model's exact
// tier run of c); the NotSupported error "export: case uses X, not yet
// exported" for a case the export does not handle, or the ShaderCompile
// error of a stage that does not compile. `layout`: LayoutFault::None, but
// where a reduction ran with a planted layout fault (test only; which ones
// a file carries: run/fault_seam.h's exportedLayoutFault) the build inputs
// are laid out as that fault misreads them, as the engine's builds lay them
// out under it, and the header says so.
Result<std::string> exportCaseAsC(const Case& c, const Plan& plan, const Results& model,
                                  LayoutFault layout = LayoutFault::None);

// The player's text (the files of harness/export/player/ joined), as embedded at build time.
const std::string& exportPlayerSource();

}  // namespace rayspec
