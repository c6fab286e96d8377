// Folders rayspec writes into or exports from hold nothing but regular files
// and folders: a symbolic link inside one would send a write, a delete or a
// copy to wherever it points, and a FIFO or device would block or leak.
#pragma once

#include <string>
#include <vector>

namespace rayspec {

// Empty when each folder on the way from `base` to `base/relative` (a
// relative path of folders, as a case name is) and everything below it (not
// following links) is a regular file or a folder; else the problem, naming
// the first entry that is not. A missing path is fine.
std::string plainPathProblem(const std::string& base, const std::string& relative);

}  // namespace rayspec
