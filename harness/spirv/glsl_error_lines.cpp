#include "spirv/glsl_error_lines.h"

#include <cstdlib>
#include <sstream>

namespace rayspec {

std::string glslLine(const std::string& glsl, int line) {
  if (line < 1) return {};
  size_t start = 0;
  for (int i = 1; i < line; ++i) {
    start = glsl.find('\n', start);
    if (start == std::string::npos) return {};
    ++start;
  }
  size_t end = glsl.find('\n', start);
  return glsl.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

namespace {

// Line number of a glslang message "ERROR: 0:57: ...", or 0.
int messageLine(const std::string& msg) {
  for (const char* tag : {"ERROR: ", "WARNING: "}) {
    if (msg.rfind(tag, 0) != 0) continue;
    size_t colon = msg.find(':', std::string(tag).size());
    if (colon == std::string::npos) return 0;
    return std::atoi(msg.c_str() + colon + 1);
  }
  return 0;
}

}  // namespace

std::string quoteGlslLines(const std::string& log, const std::string& glsl) {
  std::istringstream in(log);
  std::ostringstream out;
  std::string msg;
  while (std::getline(in, msg)) {
    out << msg << "\n";
    if (int line = messageLine(msg); line > 0)
      out << "  " << line << " | " << glslLine(glsl, line) << "\n";
  }
  return out.str();
}

}  // namespace rayspec
