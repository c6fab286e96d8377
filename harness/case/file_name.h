// Names that become file names (a case's name, an image's name): letters,
// digits, '-', '_' and '.', at most kMaxFileName bytes, not "." or "..".
#pragma once

#include <cstddef>
#include <string>

namespace rayspec {

constexpr size_t kMaxFileName = 100;

// What is wrong with name as a file name; empty when it is fine.
std::string fileNameProblem(const std::string& name);

}  // namespace rayspec
