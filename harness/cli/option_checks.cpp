#include "cli/option_checks.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "base/plain_tree.h"

namespace rayspec {
namespace fs = std::filesystem;

std::string outputFolderProblem(const std::string& dir) {
  if (dir.empty()) return "the output folder is empty (give a folder)";
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(fs::absolute(dir), ec);
  if (!ec && canonical == canonical.root_path())
    return "the output folder " + dir + " is the filesystem root";
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    return "the output folder " + dir + " is a file";
  fs::create_directories(dir, ec);
  if (ec) return "the output folder " + dir + " cannot be created: " + ec.message();
  // Nothing is ever written or deleted through a link in it: such entries go
  // themselves, and the user is told.
  for (const std::string& odd : removeOddEntries(dir))
    std::fprintf(stderr, "rayspec: removed from the output folder: %s (never followed)\n",
                 odd.c_str());
  const fs::path probe = fs::path(dir) / ".rayspec-write-probe";
  const bool writable = static_cast<bool>(std::ofstream(probe) << "");
  fs::remove(probe, ec);
  return writable ? std::string() : "the output folder " + dir + " is not writable";
}

CLI::Validator outputFolder() {
  return CLI::Validator(outputFolderProblem, "FOLDER");
}

namespace {

fs::path resolved(const std::string& dir) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(dir), ec);
  return ec ? fs::absolute(dir).lexically_normal() : p;
}

// `inner` is `outer` or lies inside it, component by component.
bool within(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i) {
    if (o->empty()) continue;  // a trailing separator
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

}  // namespace

std::string outputOverlapsInputs(const std::string& out, const std::vector<std::string>& inputs) {
  const fs::path o = resolved(out);
  for (const std::string& in : inputs) {
    const fs::path i = resolved(in);
    if (within(o, i) && within(i, o)) return "the output folder " + out + " is the input " + in;
    if (within(i, o)) return "the output folder " + out + " holds the input " + in;
    if (within(o, i)) return "the output folder " + out + " lies inside the input " + in;
  }
  return "";
}

CLI::Validator positiveSeconds() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0' || !std::isfinite(v) || v <= 0)
          return "'" + text + "' is no number of seconds above 0";
        return {};
      },
      "SECONDS>0");
}

CLI::Validator memoryLimit() {
  return CLI::Validator(
      [](const std::string& bytes) -> std::string {
        const unsigned long long v = std::strtoull(bytes.c_str(), nullptr, 10);
        if (v == 0 || v >= kMinMemoryLimit) return {};
        return std::to_string(v >> 20) + " MiB is below " + std::to_string(kMinMemoryLimit >> 20) +
               " MiB: a case side needs about that much to create its Vulkan device (validation "
               "layer on) or the model's Embree device (0: no limit)";
      },
      "BYTES");
}

CLI::Validator decimalSeed() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        const bool digits =
            !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        errno = 0;
        if (digits) (void)std::strtoull(text.c_str(), nullptr, 10);
        if (!digits || errno == ERANGE)
          return "'" + text + "' is no seed (a decimal integer from 0 to 2^64-1)";
        return {};
      },
      "SEED");
}

}  // namespace rayspec
