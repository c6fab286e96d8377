// A check newer validators make and SPIRV-Tools 2023.1 (Debian 12) does not:
// an entry point may not list two Input variables decorated with the same
// BuiltIn (VUID-StandaloneSpirv-OpEntryPoint-09658, spirv-val 2024 and later).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rayspec {

// Empty when every entry point's Input built-ins are distinct; else one line
// per duplicate naming the entry point and the BuiltIn number.
std::string duplicateBuiltinInputs(const std::vector<uint32_t>& words);

}  // namespace rayspec
