// Folders rayspec writes into or exports from hold nothing but regular files
// and folders: a symbolic link inside one would send a write, a delete or a
// copy to wherever it points, and a FIFO or device would block or leak.
#pragma once

#include <string>
#include <vector>

namespace rayspec {

// Empty when everything under `root` (not following links) is a regular file
// or a folder, and so is `root` itself unless `root_may_link`; else the
// problem, naming the first entry that is not. A missing root is fine.
std::string plainTreeProblem(const std::string& root, bool root_may_link = false);

// The same for each folder on the way from `base` to `base/relative` (a
// relative path of folders, as a case name is), and what lies below it.
std::string plainPathProblem(const std::string& base, const std::string& relative);

// Makes the tree under `root` plain: every entry that is neither a regular
// file nor a folder (a link, a FIFO, ...) is removed itself, never followed;
// `root` itself is left as it is. The paths removed, and what each was.
std::vector<std::string> removeOddEntries(const std::string& root);

}  // namespace rayspec
