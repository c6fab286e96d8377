#include "base/plain_tree.h"

#include <filesystem>

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

}  // namespace

std::string plainTreeProblem(const std::string& root, bool root_may_link) {
  std::error_code ec;
  if (!root_may_link)
    if (std::string odd = oddEntry(root); !odd.empty()) return odd;
  if (!fs::is_directory(root, ec)) return "";
  for (fs::recursive_directory_iterator it(root, fs::directory_options::none, ec), end;
       !ec && it != end; it.increment(ec))
    if (std::string odd = oddEntry(it->path()); !odd.empty()) return odd;
  return ec ? "cannot read " + root + ": " + ec.message() : "";
}

std::string plainPathProblem(const std::string& base, const std::string& relative) {
  fs::path at = base;
  for (const fs::path& part : fs::path(relative)) {
    if (part.empty() || part == ".") continue;
    at /= part;
    if (std::string odd = oddEntry(at); !odd.empty()) return odd;
  }
  return plainTreeProblem(at.string());
}

std::vector<std::string> removeOddEntries(const std::string& root) {
  std::vector<std::string> odd_entries;
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return odd_entries;
  std::vector<fs::path> odd;
  for (fs::recursive_directory_iterator it(root, fs::directory_options::none, ec), end;
       !ec && it != end; it.increment(ec))
    if (std::string what = oddEntry(it->path()); !what.empty()) {
      odd.push_back(it->path());
      odd_entries.push_back(what);
    }
  for (const fs::path& p : odd) fs::remove(p, ec);  // the entry itself: a link is not followed
  return odd_entries;
}

}  // namespace rayspec
