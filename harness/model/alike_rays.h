// Launch rays alike, traced once (a Machine's memo of the launch ray it
// traced last). Where no program reads the launch id (launchIdRead,
// model/uniform_launch.h), what a launch id does depends on its ray alone:
// the ray (origin, direction, tmin, tmax, flags, cull mask, SBT offset and
// stride, miss index) is all a stage reads of it, the rest (launch size,
// scene, SBT, programs) is the launch's; and a ray's outcome does not depend
// on what its Machine traced before (which Machine traces which chunk of
// rays already changes from run to run). So a launch ray bit for bit the same
// as the one its Machine traced last leaves what that one left: its record,
// its counter and floor moves, its ambiguous and bounded entries (named by
// its own index). A ray whose behaviour is undefined is not kept: its
// diagnosis names its launch index in its text (UndefinedRay::what), and
// such rays are few. cts-amber/basic2 launches 20,736 rays alike, each
// an ambiguous tie of four boxes that the exact tier replays.
//
// A traced ray is kept only where the launch ray after it is alike: rays
// alike lie side by side (a grid with no step, rays.same), and a launch of
// rays all different pays one comparison a ray. The last ray kept stays
// until another is (what it left stays valid); a ray alike an earlier one
// that was not kept is traced again.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "case/case.h"
#include "model/launch_state.h"

namespace rayspec {

class AlikeRays {
 public:
  // `on`: the launch's programs read no launch id (otherwise nothing is kept).
  explicit AlikeRays(bool on) : on_(on) {}
  // Launch ray i, whose ray is `ray`, is the last traced one again: what that
  // one left is added to `st` for i. False otherwise (trace it, between
  // starting and traced).
  bool repeat(LaunchState& st, const Ray& ray, uint32_t i) const;
  // Before launch ray i, whose ray is `ray`, is traced; `next`: the launch
  // ray after it (null: none). Kept only where `next` is alike.
  void starting(const LaunchState& st, const Ray& ray, const Ray* next);
  // After launch ray i is traced (its replays too): what it left, kept
  // unless the ray is undefined.
  void traced(const LaunchState& st, uint32_t i);

 private:
  struct Span {
    size_t begin = 0, end = 0;
  };
  bool on_ = false;
  bool keeping_ = false;  // the ray being traced is to be kept
  bool kept_ = false;     // ray_ and what it left are known
  Ray ray_;
  uint32_t index_ = 0;
  std::vector<uint64_t> counter_moves_, floor_moves_;  // before it, then its moves
  Span ambiguous_, t_bounds_, object_origin_bounds_, position_bounds_;
  size_t undefined_before_ = 0;
};

}  // namespace rayspec
