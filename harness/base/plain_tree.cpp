#include "base/plain_tree.h"

#include <filesystem>
#include <utility>

namespace rayspec {
namespace fs = std::filesystem;
namespace {

// Empty for a regular file or folder; else what the entry is.
std::string oddEntry(const fs::path& p) {
  std::error_code ec;
  const fs::file_status s = fs::symlink_status(p, ec);
  if (ec || s.type() == fs::file_type::not_found) return "";
  switch (s.type()) {
    case fs::file_type::regular:
    case fs::file_type::directory:
      return "";
    case fs::file_type::symlink:
      return p.string() + " is a symbolic link";
    default:
      return p.string() + " is neither a regular file nor a folder (a FIFO, socket or device)";
  }
}

// Every entry below `root` (not following links) that is not a regular file
// or a folder: its path and what it is. A folder that cannot be read is said
// in `*error`.
std::vector<std::pair<fs::path, std::string>> oddEntriesBelow(const fs::path& root,
                                                              std::string* error) {
  std::vector<std::pair<fs::path, std::string>> odd;
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return odd;
  for (fs::recursive_directory_iterator it(root, fs::directory_options::none, ec), end;
       !ec && it != end; it.increment(ec))
    if (std::string what = oddEntry(it->path()); !what.empty()) odd.emplace_back(it->path(), what);
  if (ec) *error = "cannot read " + root.string() + ": " + ec.message();
  return odd;
}

}  // namespace

std::string plainPathProblem(const std::string& base, const std::string& relative) {
  fs::path at = base;
  for (const fs::path& part : fs::path(relative)) {
    if (part.empty() || part == ".") continue;
    at /= part;
    if (std::string odd = oddEntry(at); !odd.empty()) return odd;
  }
  std::string error;
  const auto odd = oddEntriesBelow(at, &error);
  return odd.empty() ? error : odd.front().second;
}

}  // namespace rayspec
