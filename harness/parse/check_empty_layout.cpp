// checkEmptyLayout (parse_parts.h): what a pipeline of no descriptor set
// cannot reach (the ray query forms refuse it themselves:
// case/ray_query_inlining.h).
#include "parse/parse_parts.h"

namespace rayspec {

void checkEmptyLayout(YamlReader& r, const Case& c, const YAML::Node& pipeline) {
  const Pipeline& p = c.pipeline;
  if (!p.empty_layout) return;
  const YAML::Node at = YamlReader::get(pipeline, "layout");
  const auto refuse = [&](const std::string& what) {
    r.error(at, "pipeline.layout",
            "an empty layout binds no descriptor set, so " + what +
                " cannot be reached (its shaders reach buffers and the top level through "
                "their device addresses only)");
  };
  if (!c.outputs.images.empty()) refuse("outputs.images (storage images)");
  if (c.scene.tlasCount() > 1) refuse("several top levels (an array of them)");
  if (!p.libraries.empty()) refuse("pipeline.libraries (not made with it yet)");
  if (p.tlas_function) refuse("pipeline.tlas_function (not made with it yet)");
}

}  // namespace rayspec
