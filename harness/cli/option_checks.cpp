#include "cli/option_checks.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "fuzz/generator_features.h"
#include "metamorphic/feature_path.h"

namespace rayspec {
namespace fs = std::filesystem;

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

namespace {

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

// The count of decimal digits at the start of text.
size_t leadingDigits(const std::string& text) {
  size_t n = 0;
  while (n < text.size() && isDigit(text[n])) ++n;
  return n;
}

}  // namespace

CLI::Validator positiveSeconds() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        const size_t whole = leadingDigits(text);
        const bool point = whole < text.size() && text[whole] == '.';
        const size_t fraction = point ? leadingDigits(text.substr(whole + 1)) : 0;
        const bool plain = whole + fraction > 0 && whole + point + fraction == text.size();
        const double v = plain ? std::strtod(text.c_str(), nullptr) : 0;
        if (!plain || !std::isfinite(v) || v <= 0)
          return "'" + text + "' is no number of seconds above 0 (digits, a decimal point)";
        return {};
      },
      "SECONDS>0");
}

CLI::Validator wholeCount() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        if (text.empty() || leadingDigits(text) != text.size() || text.size() > 9)
          return "'" + text + "' is no count (decimal digits only, at most 9)";
        return {};
      },
      "COUNT");
}

namespace {

// Empty when text is digits and an optional unit; else the problem.
std::string memorySizeTextProblem(const std::string& text) {
  const size_t digits = leadingDigits(text);
  std::string unit = text.substr(digits);
  for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  static const std::set<std::string> kUnits = {"",    "B", "K",  "KB",  "KIB", "M",  "MB",
                                               "MIB", "G", "GB", "GIB", "T",   "TB", "TIB"};
  if (digits > 0 && digits <= 20 && kUnits.count(unit) == 1) return "";
  return "'" + text +
         "' is no memory size (decimal digits, then K, M, G or T; e.g. 8G, 512M; 0: none)";
}

// Empty when bytes (decimal, as CLI::AsSizeValue wrote it) is a usable limit.
std::string memoryLimitProblem(const std::string& bytes) {
  errno = 0;
  const unsigned long long v = std::strtoull(bytes.c_str(), nullptr, 10);
  if (errno == ERANGE || bytes.empty() || leadingDigits(bytes) != bytes.size())
    return "'" + bytes + "' bytes is more than a limit can be (below 2^64)";
  if (v == 0 || v >= kMinMemoryLimit) return "";
  return std::to_string(v >> 20) + " MiB is below " + std::to_string(kMinMemoryLimit >> 20) +
         " MiB: a case side needs about that much to create its Vulkan device (validation "
         "layer on) or the model's Embree device (0: no limit)";
}

}  // namespace

CLI::Validator memoryLimit() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (std::string problem = memorySizeTextProblem(text); !problem.empty()) return problem;
        const std::string written = text;
        try {
          if (std::string problem = CLI::AsSizeValue(false)(text); !problem.empty()) return problem;
        } catch (const CLI::Error& e) {  // a size past 64 bits, say
          return "'" + written + "' is no memory size: " + e.what();
        }
        return memoryLimitProblem(text);
      },
      "SIZE");
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

CLI::Validator featurePath() {
  return CLI::Validator(
      [](const std::string& name) {
        return featurePathFromName(name)
                   ? std::string()
                   : "unknown feature path '" + name + "' (" + featurePathNames() + ")";
      },
      "PATH");
}

CLI::Validator leavableFeature() {
  return CLI::Validator(
      [](const std::string& name) {
        GeneratorFeatures scratch;
        const Result<void> known = leaveOut(scratch, name);
        return known ? std::string() : known.error().format();
      },
      "FEATURE");
}

}  // namespace rayspec
