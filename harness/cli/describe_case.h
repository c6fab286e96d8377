// A human-readable summary of a parsed case, for `rayspec show`.
#pragma once

#include <string>

#include "case/case.h"

namespace rayspec {

std::string describeCase(const Case& c);

}  // namespace rayspec
