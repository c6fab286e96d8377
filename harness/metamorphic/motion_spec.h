// The text of a rigid motion on the command line (`rayspec run --move SPEC`):
// three signed axis names, the source axis of each new axis, then optionally
// three translation terms, all separated by commas:
//   -y,x,z              a turn by 90 degrees about z (new x = -old y, new y = old x)
//   z,x,y,1024,-2048,0  the axes cycled, then translated
//   x,y,-z              a mirror in the plane z = 0
#pragma once

#include <optional>
#include <string>

#include "metamorphic/transform_case.h"

namespace rayspec {

// The motion, or the error saying what is wrong with the text.
Result<RigidMotion> parseMotionSpec(const std::string& spec);

// The motion written back in the same form (translation terms only where one
// is not 0), e.g. "-y,x,z" or "z,x,y,1024,-2048,0".
std::string motionSpecText(const RigidMotion& m);

}  // namespace rayspec
