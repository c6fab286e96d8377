#include "results/file_name.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace rayspec {
namespace {

bool fileNameByte(char ch) {
  return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
         ch == '-' || ch == '_' || ch == '.';
}

std::string filePartFor(const std::string& part) {
  if (part.empty()) return "_";
  const bool dots = part == "." || part == "..";
  std::string out;
  for (const char ch : part) {
    if (fileNameByte(ch) && !dots) {
      out += ch;
      continue;
    }
    char hex[8];
    std::snprintf(hex, sizeof hex, "_x%02X", static_cast<unsigned char>(ch));
    out += hex;
  }
  if (out.size() > kMaxFileName) out.resize(kMaxFileName);
  return out;
}

}  // namespace

std::string fileNameProblem(const std::string& name) {
  if (name.empty()) return "is empty";
  if (name.size() > kMaxFileName)
    return "is " + std::to_string(name.size()) + " bytes long (at most " +
           std::to_string(kMaxFileName) + ")";
  if (name == "." || name == "..") return "may not be '" + name + "'";
  const auto bad =
      std::find_if(name.begin(), name.end(), [](char ch) { return !fileNameByte(ch); });
  if (bad == name.end()) return {};
  const unsigned char ch = static_cast<unsigned char>(*bad);
  const std::string shown =
      ch >= 0x21 && ch < 0x7F ? std::string("'") + *bad + "'" : "byte " + std::to_string(ch);
  return "holds " + shown + " (only letters, digits, '-', '_' and '.')";
}

void removeCaseOutputs(const std::string& case_dir) {
  std::error_code ec;
  for (const char* part : kCaseOutputs)
    std::filesystem::remove_all(std::filesystem::path(case_dir) / part, ec);
}

std::string caseNameProblem(const std::string& name) {
  if (name.empty()) return "is empty";
  size_t start = 0;
  for (int part = 1;; ++part) {
    const size_t slash = name.find('/', start);
    const std::string p =
        name.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
    if (const std::string problem = fileNameProblem(p); !problem.empty())
      return "part " + std::to_string(part) + " ('" + p.substr(0, 40) + "') " + problem;
    if (slash == std::string::npos) return {};
    start = slash + 1;
  }
}

std::string caseNameFor(const std::string& name) {
  if (caseNameProblem(name).empty()) return name;
  std::string out;
  for (size_t start = 0;;) {
    const size_t slash = name.find('/', start);
    out += filePartFor(name.substr(start, slash == std::string::npos ? slash : slash - start));
    if (slash == std::string::npos) return out;
    out += '/';
    start = slash + 1;
  }
}

}  // namespace rayspec
