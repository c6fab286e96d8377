#include "run/judge_case.h"

#include <cstdio>

#include "bundle/image_files.h"
#include "compare/compare_results.h"
#include "run/failing_rays.h"

namespace rayspec {

CaseOutcome judgeCase(const Case& c, const Plan& plan, const Results& device, const Results& model,
                      const std::string& dir) {
  CaseOutcome out;
  out.name = c.name;
  out.rules = c.rules;
  out.device_seconds = device.seconds;
  out.model_seconds = model.seconds;
  out.verdict = compareResults(c, plan, device, model);
  for (const Image& di : device.images)
    for (const Image& mi : model.images)
      if (!dir.empty() && di.name == mi.name && di.texels != mi.texels)
        // A picture for people: the verdict stands without it, so its
        // failure is said and not the case's.
        if (const Result<void> diff = writeDiffImage(di, mi, dir + "/diff"); !diff)
          std::fprintf(stderr, "%s: difference image: %s\n", c.name.c_str(),
                       diff.error().format().c_str());
  out.failing_rays = failingRays(out.verdict, plan, device, model);
  for (const ImageOutput& im : plan.images) out.images.push_back(im.name);
  out.deriveFromVerdict();
  return out;
}

}  // namespace rayspec
