// R-WATERTIGHT: the frames triangles share edges in (case/share_frame.h).
#include "case/share_frame.h"

#include <bit>

namespace rayspec {

namespace {
// The frame index of every instance whose transform is the identity.
constexpr uint32_t kWorldFrame = ~0u;

bool bitIdentity(const Transform& m) {
  for (size_t k = 0; k < m.size(); ++k)
    if (std::bit_cast<uint32_t>(m[k]) != std::bit_cast<uint32_t>(kIdentity[k])) return false;
  return true;
}
}  // namespace

ShareFrame shareFrame(const Instance& instance, uint32_t index,
                      const std::optional<Transform>& geometry_transform) {
  ShareFrame f{};
  f[0] = bitIdentity(instance.transform) ? kWorldFrame : index;
  const Transform& g = geometry_transform.value_or(kIdentity);
  for (size_t k = 0; k < g.size(); ++k) f[1 + k] = std::bit_cast<uint32_t>(g[k]);
  return f;
}

}  // namespace rayspec
