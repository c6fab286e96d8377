// A case that expects its compiler to reject shaders launches nothing; its
// verdict is whether each shader the model names (every one of
// expect_rejected) was refused on the device side for the interface its stage
// cannot declare (vulkan/expected_rejections.h).
#include <algorithm>

#include "compare/compare_parts.h"

namespace rayspec {
namespace {

bool listed(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

// "hit0.intersection uses payload.value (line 22), which needs rayPayloadInEXT"
std::string useText(const ExpectedRejection& e) {
  if (e.uses.empty()) return e.shader;
  const InterfaceUse& u = e.uses.front();
  return e.shader + " uses " + u.what + " (line " + std::to_string(u.loc.line) + "), which needs " +
         u.qualifier;
}

}  // namespace

void compareRejections(const Case& c, const Results& device, const Results& model, Verdict& v) {
  for (const ExpectedRejection& e : c.expected_rejections) {
    if (!listed(model.rejected, e.shader)) continue;  // the model expects it: always, when run
    Finding f;
    f.rule = "R-STAGE-INTERFACE";
    if (listed(device.rejected, e.shader)) {
      f.status = Status::Pass;
      f.message = useText(e) + ": the compiler rejected it, as it must";
    } else {
      f.message = useText(e) + ": not rejected for that (the compiler accepted it, or refused " +
                  "it for another reason; `rayspec show " + c.name +
                  "` prints the GLSL), but its stage cannot declare " +
                  (e.uses.empty() ? std::string("it") : e.uses.front().qualifier);
    }
    v.add(f);
  }
}

}  // namespace rayspec
