// Where a value came from in a case file, for error messages.
#pragma once

#include <string>

namespace rayspec {

struct SourceLoc {
  std::string file;
  int line = 0;       // 1-based; 0 when unknown
  int column = 0;     // 1-based; 0 when unknown
  std::string field;  // dotted path of the field, e.g. "pipeline.miss[0][1].count"
};

}  // namespace rayspec
