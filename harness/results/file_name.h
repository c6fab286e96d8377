// Names that become file names (a case name's parts, an image's name): letters,
// digits, '-', '_' and '.', at most kMaxFileName bytes, not "." or "..".
#pragma once

#include <array>
#include <cstddef>
#include <string>

namespace rayspec {

constexpr size_t kMaxFileName = 100;

// What is wrong with name as a file name; empty when it is fine.
std::string fileNameProblem(const std::string& name);

// What is wrong with name as a case name ('/'-separated parts, each a file
// name: never absolute, never "..", never empty); empty when it is fine. Every
// name read from input (case files, sweeps, saved bundles, summaries,
// baselines) that becomes a path below an output or input folder passes here.
std::string caseNameProblem(const std::string& name);

// What a case's run writes in its folder: its device and model bundles, diff
// images, re-run and cost.json.
inline constexpr std::array<const char*, 5> kCaseOutputs = {"device", "model", "diff", "rerun",
                                                            "cost.json"};

// A case name standing for `name` (`name` itself when it is one): in each
// part, every byte a file name may not hold as "_xNN" (a space "_x20"), "."
// and ".." as "_x2E" and "_x2E_x2E", an empty part as "_", a part still
// too long cut to kMaxFileName bytes. A case file badly named (a space, bytes
// that are not UTF-8) is reported as a CaseError under it, a name that every
// reader of a run's files (summary.json, the journal, baselines) accepts.
std::string caseNameFor(const std::string& name);

// Removes what a case's run writes in its folder (its device and model
// bundles, diff images, re-run and cost.json) and nothing else: a folder the
// user keeps beside them in --out survives.
void removeCaseOutputs(const std::string& case_dir);

}  // namespace rayspec
