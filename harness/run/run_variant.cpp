// runVariant (run/run_options.h): what a run does to every case, as its run
// folder records it.
#include "metamorphic/motion_spec.h"
#include "run/run_options.h"

namespace rayspec {

std::string runVariant(const RunOptions& opt) {
  std::string v;
  auto add = [&](const std::string& part) {
    v += (v.empty() ? "" : "; ") + part;
  };
  if (opt.through) add(std::string("through ") + featurePathName(*opt.through));
  if (opt.permute) add("permute " + std::to_string(*opt.permute));
  if (opt.move) add("move " + motionSpecText(*opt.move));
  return v;
}

}  // namespace rayspec
