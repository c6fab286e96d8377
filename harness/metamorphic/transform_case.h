// A rigid motion of a whole case (the metamorphic checks of the stability
// families): every instance transform is composed with the motion and every
// launch ray moved by it. With a signed permutation of the axes (an exact
// rotation: axis swaps, turns by 90 degrees, mirrors) and a translation
// whose every sum is exact in float, each float of the moved case is the
// exact image of the original's: the geometry a device sees is the same, so
// verdicts and the leak and double-hit counts must not move.
//
// Two scopes. SameGeometry (the stability families' count checks) moves only
// cases whose stages trace nothing but the raygen's one launch ray
// (`raygen: [trace: {}]`) and never branch: a nested trace's own origin would
// not move, and a condition on a world-space built-in could change its mind.
// Verdict (`rayspec run --move`) moves every instance and launch ray of a
// case whose traces give no origin or direction of their own (a constant
// there would not move): nested traces of the incoming ray and conditions on
// world-space built-ins are evaluated on the moved case by the device and
// the model alike, so a correct device's verdict does not change.
// World-space built-ins a stage records (world ray origin, hit position)
// move with the case; compare counts, ids and hits, not those.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "base/result.h"
#include "case/case.h"

namespace rayspec {

struct RigidMotion {
  std::array<int, 3> axis{0, 1, 2};  // new x[k] = sign[k] * old x[axis[k]] + translate[k]
  std::array<int, 3> sign{1, 1, 1};  // +1 or -1
  std::array<double, 3> translate{0, 0, 0};
};

// The moved case, or the error: the motion is not a signed permutation, a
// sum is not exact in float, or the case traces other rays.
// Its source_hash mixes in the motion (motion_spec.h's text).
enum class MoveScope { SameGeometry, Verdict };
Result<Case> moveCase(const Case& c, const RigidMotion& m,
                      MoveScope scope = MoveScope::SameGeometry);

}  // namespace rayspec
