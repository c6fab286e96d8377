#include "fuzz/generate_case.h"

#include "fuzz/case_generator.h"
#include "fuzz/content_features.h"

namespace rayspec {

const std::vector<std::string>& generatorFeatures() {
  static const std::vector<std::string> kFeatures = {
      // the scene
      "several-blas", "several-geometries", "triangles", "aabbs", "indexed", "non-indexed",
      "nan-vertex", "nan-box", "non-opaque-geometry", "inactive-instance", "rotation", "mirror",
      "non-uniform-scale", "instance-mask", "sbt-offset", "instance-flags", "custom-index-24",
      "mesh-shape", "geometry-transform", "vertex-format",
      // layouts, copies and updates
      "build-flags", "copy-clone", "copy-compact", "copy-serialize", "copy-before-update",
      "copy-after-updates", "instances-as-pointers", "data-offsets", "first-vertex",
      "vertex-stride", "aabb-stride", "one-by-one", "update-into-other", "tlas-rebuild",
      "update-vertices", "update-boxes", "update-instances", "several-updates",
      // the rays
      "ray-list", "ray-grid", "ray-interval", "ray-flags", "cull-mask", "sbt-stride-0",
      "aimed-centre", "aimed-edge", "aimed-vertex", "aimed-box-centre", "aimed-box-boundary",
      "grazing-ray", "huge-ray", "aim-form", "launch-3d", "indirect-launch",
      // the programs
      "callables", "any-hit-ignore", "any-hit-terminate", "any-hit-payload", "conditional-report",
      "two-reports", "nested-trace", "nested-trace-from-miss", "hit-builtin-after-trace",
      "call-in-hit", "call-in-miss", "call-in-callable", "if-else", "repeat", "switch", "function",
      "local-across-call", "float-color", "float-builtin", "any-hit-accumulate",
      "any-hit-on-payload", "any-hit-function", "ray-query", "ray-query-generate",
      "ray-query-terminate", "traces-ray-query", "traces-compute", "code-after-end", "vector-math",
      "float-bits", "call-words", "miss-world-ray-beside-empty-group",
      // typed live state
      "sized-values", "sized-vector", "struct-local", "sized-array", "sized-across-report"};
  return kFeatures;
}

std::string fuzzCaseName(uint64_t seed) {
  return "fuzz/seed-" + std::to_string(seed);
}

GeneratedCase generateCase(uint64_t seed, const GeneratorFeatures& allowed) {
  CaseGenerator g(seed, allowed);
  // What was left out, so that the description says how to make it again.
  const std::string without = leftOutText(allowed);
  g.text() = "# rayspec fuzz, seed " + std::to_string(seed) +
             ": a generated case (harness/fuzz/generate_case.h)\n"
             // R-AHIT-DUP: an any-hit that writes may run twice on geometry
             // without no_duplicate_any_hit; the case is judged on the rest.
             "rules: [R-BUILTIN, R-AHIT-DUP]\n"
             "description: generated from seed " +
             std::to_string(seed) + (without.empty() ? "" : " " + without) + "\n";
  g.scene();
  g.rays();
  g.pipeline();
  g.outputs();
  // What the text shows is read from it (one definition: the known classes
  // key on it, and a saved case is classified by it the same).
  g.features().merge(contentFeatures(g.text()));
  return {seed, fuzzCaseName(seed), g.text(), g.features()};
}

}  // namespace rayspec
