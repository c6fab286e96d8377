// A file's whole text ("" when it cannot be read), for tests that check what
// a command or a writer left on disk.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

namespace rayspec {

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace rayspec
