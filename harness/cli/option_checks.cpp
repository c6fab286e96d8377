#include "cli/option_checks.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace rayspec {
namespace fs = std::filesystem;

namespace {

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
  const fs::path probe = fs::path(dir) / ".rayspec-write-probe";
  const bool writable = static_cast<bool>(std::ofstream(probe) << "");
  fs::remove(probe, ec);
  return writable ? std::string() : "the output folder " + dir + " is not writable";
}

}  // namespace

CLI::Validator outputFolder() {
  return CLI::Validator(outputFolderProblem, "FOLDER");
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
