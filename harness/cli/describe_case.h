// A human-readable summary of a parsed case, for `rayspec show`.
#pragma once

#include <string>
#include <vector>

#include "case/aim_rays.h"
#include "case/case.h"

namespace rayspec {

std::string describeCase(const Case& c);
// Each aimed ray's target (parse/parse_aim.h aimTargetsOf): its feature, the
// instance, geometry and triangles that have it, the point; "" for none.
std::string describeAimTargets(const std::vector<AimTarget>& aimed);

}  // namespace rayspec
