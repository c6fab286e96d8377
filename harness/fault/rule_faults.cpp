// The table: every rule of the catalog and the faults that break it.
#include "fault/rule_faults.h"

#include <algorithm>

namespace rayspec {

namespace {

// The rules of traversal and of what the stages of one trace do.
std::vector<RuleFaults> traversalRules() {
  const Status qw = Status::QualityWarning;
  return {
      {"R-CAND-TRI-OPEN", {"closed-triangle-interval"}, {}},
      {"R-CAND-AABB-CLOSED", {"open-aabb-interval"}, {}},
      {"R-TIE", {"tie-answered-neither"}, {}},
      {"R-ORDER-UNSPEC",
       {"build-order-first-hit"},
       {"reverse-order", "permuted-order-1", "permuted-order-2", "permuted-order-3"}},
      {"R-INST-XFORM", {"instance-transform-inverted"}, {}},
      {"R-PREC", {"shift-t"}, {}},
      {"R-WATERTIGHT", {"leak-edge", "double-hit-edge", "pass-between-edges"}, {}, qw},
      {"R-AABB-CONS", {"box-entered-from-inside-missed", "zero-length-ray-box-missed"}, {}},
      {"R-ISECT-MULTI", {}, {"intersection-runs-twice"}},
      {"R-ISECT-CLOSEST", {"closest-box-skipped"}, {}},
      {"R-SKIP-TRI", {"skip-triangles-ignored"}, {}},
      {"R-SKIP-AABB", {"skip-aabbs-ignored"}, {}},
      {"R-MASK", {"instance-mask-ignored", "inactive-hides-last-active"}, {}},
      {"R-FACE-DET", {"facing-inverted", "world-space-facing"}, {}},
      {"R-FACE-CULL", {"facing-cull-ignored", "cull-disable-ignored"}, {}},
      {"R-HITKIND-TRI", {"hit-kind-flipped"}, {}},
      {"R-OPACITY", {"instance-opacity-ignored", "ray-opacity-ignored"}, {}},
      {"R-CULL-OPQ", {"opacity-cull-ignored"}, {}},
      {"R-AHIT-OPAQUE-SKIP", {"any-hit-on-opaque"}, {}},
      {"R-AHIT-UNUSED", {"unused-any-hit-ignores"}, {}},
      {"R-AHIT-DUP", {"duplicate-any-hit"}, {"any-hit-runs-twice"}},
      {"R-AHIT-CLOSEST", {"closest-any-hit-skipped"}, {}},
      {"R-IGNORE",
       {"ignore-accepts", "code-after-ignore-runs", "function-ignore-lost",
        "ignore-discards-writes"},
       {}},
      {"R-TERMINATE",
       {"terminate-continues", "code-after-terminate-runs", "function-ignore-lost"},
       {}},
      {"R-ISECT-REPORT", {"report-return-inverted", "report-kind-dropped"}, {}},
      {"R-TMAX-VIEW", {"tmax-view-initial"}, {}},
      {"R-TOFH", {"first-hit-flag-ignored"}, {"reverse-order"}},
      {"R-MISS-XOR-CHIT",
       {"drop-miss", "chit-after-ignore", "miss-after-closest-hit", "skip-closest-hit-ignored"},
       {}},
  };
}

// The rules of acceleration structures: copies, sizes, builds, memory,
// updates and vertex formats.
std::vector<RuleFaults> structureRules() {
  const Status fail = Status::Fail;
  return {
      {"R-AS-COPY", {"copy-drops-instance"}, {}},
      {"R-AS-SIZE",
       {"build-counts-16-bit", "mesh-triangle-dropped", "mesh-triangle-duplicated"},
       {}},
      {"R-AS-BUILD",
       {"shared-scratch-keeps-previous"},
       {},
       fail,
       "",
       {"stride-ignored", "offsets-ignored", "pointers-reversed", "sparse-page-lost"}},
      {"R-AS-MEMORY", {"memory-guard-overwritten"}, {}, fail, "", {"build-writes-past-size"}},
      {"R-AS-CREATE", {"creation-empties-structure"}, {}, fail, "", {"creation-clears-memory"}},
      // scene.build.queries (vulkan/structure_queries.h, fault/record_faults_queries.cpp).
      {"R-AS-QUERY-COMPACTED",
       {"compacted-size-reported-large"},
       {},
       fail,
       "",
       {"compacted-size-too-large"}},
      {"R-AS-QUERY-SIZE",
       {"structure-size-reported-large"},
       {},
       fail,
       "",
       {"structure-size-too-large"}},
      {"R-AS-QUERY-AVAILABILITY", {"query-unavailable"}, {}, fail, "", {"query-availability-lost"}},
      {"R-AS-SERIAL-HEADER", {"serialized-header-wrong"}, {}, fail, "", {"serialized-uuid-wrong"}},
      {"R-AS-SERIAL-POINTERS", {"serialized-pointer-foreign"}, {}, fail, "", {"pointer-count-off"}},
      {"R-AS-UPDATE",
       {"update-ignored", "later-updates-ignored", "copy-update-ignored", "update-degenerate-lost"},
       {}},
      {"R-VERTEX-FORMAT",
       {"vertex-format-ignored", "vertex-format-confused"},
       {},
       fail,
       "",
       {"vertex-format-misread"}},
  };
}

// The rules of the pipeline around traversal: the SBT, data between stages,
// built-ins, structures, launches and shader code.
std::vector<RuleFaults> pipelineRules() {
  return {
      {"R-SBT-HIT",
       {"hit-record-shifted", "instance-sbt-offset-ignored", "custom-index-truncated",
        "empty-geometry-renumbered"},
       {}},
      {"R-SBT-MISS", {"miss-record-shifted"}, {}},
      {"R-SBT-CALL", {"callable-record-shifted", "callable-index-ignored"}, {}},
      {"R-SBT-ZERO", {"zero-record-runs-group-0"}, {}},
      {"R-SBT-RECORD", {"shader-record-data-zeroed", "record-layout-swapped"}, {}},
      {"R-STAGE-INTERFACE", {"stage-interface-accepted"}, {}},
      {"R-RECURSION", {"nested-trace-dropped"}, {}},
      {"R-CALLABLE",
       {"callable-data-not-returned", "call-data-words-lost", "sized-call-data-halved-across-call"},
       {}},
      {"R-PAYLOAD",
       {"payload-writes-lost", "payload-start-lost", "payload-words-lost", "hit-attributes-lost",
        "word-index-off-by-one", "sized-payload-halved-across-trace",
        "sized-attribute-halved-to-candidate"},
       {}},
      {"R-BUILTIN",
       {"builtin-wrong", "swap-primitive-id", "shift-t", "empty-geometry-renumbered",
        "transform-builtins-swapped", "launch-id-x-wrapped", "launch-id-yz-wrapped",
        "nested-trace-clobbers-hit", "incoming-flags-with-pipeline-skip"},
       {}},
      // Several top levels are built as copies of the instance list, the other
      // levels' instances inactive (Instance::tlas): which instances a trace
      // finds active is which level it names.
      {"R-INACTIVE",
       {"inactive-renumbered", "inactive-revived", "inactive-hides-last-active", "tlas-ignored"},
       {}},
      // A descriptor array of top levels (tlas: k, tlas: expr) and a top level
      // passed to a function.
      {"R-TLAS-ARRAY", {"tlas-ignored", "tlas-index-off-by-one"}, {}},
      {"R-DEGEN", {"degenerate-hit"}, {}},
      {"R-LIBRARY", {"library-groups-lost", "library-handle-differs"}, {}},
      {"R-RAYGEN-REGION", {"raygen-group-ignored"}, {}},
      {"R-CULLMASK-BUILTIN", {"cull-mask-builtin-default"}, {}},
      {"R-NULL-SHADERS", {"no-null-shaders-dropped"}, {}},
      {"R-INDIRECT", {"indirect-launch-short"}, {}},
      {"R-STACK", {"stack-size-ignored"}, {}},
      {"R-POSITION-FETCH", {"position-fetch-world-space"}, {}},
      {"R-LAUNCH-3D",
       {"launch-depth-lost", "zero-launch-runs", "wide-launch-truncated", "launch-row-repeated",
        "launch-row-lost"},
       {}},
      {"R-LIVE-STATE",
       {"locals-lost-across-calls", "sized-locals-halved-across-calls",
        "sized-vectors-rotated-across-calls", "sized-null-initialiser-lost",
        "struct-member-lost-across-calls"},
       {}},
      {"R-CONTROL-FLOW",
       {"loop-trip-off-by-one", "function-ignore-lost", "specialization-ignored",
        "bitwise-xor-as-or", "float-bits-converted", "cross-operands-swapped", "matrix-transposed"},
       {}},
  };
}

// The rules of ray queries: a ray query loop that decides candidates,
// commits or reads built-ins otherwise than the pipeline's stages would
// (pipeline.traces: ray_query), and the ray_query statement (cases/ray-query/).
std::vector<RuleFaults> rayQueryRules() {
  return {
      {"R-RQ-INIT",
       {"query-init-keeps-committed", "query-restart-keeps-committed", "query-step-wrong-query"},
       {}},
      {"R-RQ-CANDIDATES",
       {"query-offers-opaque", "query-commit-beyond-committed-t", "tlas-ignored",
        "query-candidate-shrinks-interval"},
       {}},
      {"R-RQ-COMMIT",
       {"query-confirm-ignored", "query-generate-ignored", "query-commit-beyond-committed-t",
        "query-confirm-only-first", "query-break-loses-commit", "query-function-gets-copy"},
       {}},
      {"R-RQ-TERMINATE", {"query-terminate-ignored"}, {}},
      {"R-RQ-VALUES",
       {"query-committed-reads-candidate", "query-custom-index-is-instance-id",
        "query-candidate-type-swapped", "query-front-face-inverted", "query-object-ray-world"},
       {}},
      {"R-RQ-EQUIV",
       {"ignore-accepts", "terminate-continues", "any-hit-on-opaque", "report-return-inverted",
        "hit-attributes-lost", "skip-closest-hit-ignored", "first-hit-flag-ignored",
        "tmax-view-initial", "transform-builtins-swapped", "builtin-wrong",
        "nested-trace-clobbers-hit"},
       {}},
      {"R-UB", {}, {}, Status::Fail, "never checked for a result (robustness probe only)"},
  };
}

// The rules of how a pipeline is created.
std::vector<RuleFaults> creationRules() {
  const Status fail = Status::Fail;
  return {
      {"R-DEFERRED", {"deferred-groups-lost"}, {}, fail, "", {"deferred-handle-early"}},
      // pipeline.layout: empty: the CTS's empty_pipeline_layout asks only that
      // the pipeline is made (pipeline-refused); rayspec also runs it.
      {"R-EMPTY-LAYOUT", {"address-writes-lost"}, {}, fail, "", {"pipeline-refused"}},
  };
}

// The rules of hit objects (VK_NV_ray_tracing_invocation_reorder), broken on
// the model: one getter family each, closest-hit run at the trace, and hits
// recorded by hand and the shader record handle.
std::vector<RuleFaults> hitObjectRules() {
  return {
      {"R-HIT-OBJECT",
       {"hit-object-state-wrong", "hit-object-ids-swapped", "hit-object-t-initial",
        "hit-object-object-ray-world", "hit-object-matrices-swapped", "hit-object-attributes-lost",
        "hit-object-sbt-index-of-instance"},
       {}},
      {"R-HIT-OBJECT-DEFERRED", {"hit-object-trace-shades"}, {}},
      {"R-HIT-OBJECT-RECORD",
       {"hit-object-record-sbt-no-instance-offset", "hit-object-record-index-plus-instance-offset",
        "hit-object-record-custom-index-is-id", "hit-object-record-handle-own"},
       {}},
  };
}

}  // namespace

const std::vector<RuleFaults>& ruleFaults() {
  static const std::vector<RuleFaults> table = [] {
    std::vector<RuleFaults> all = traversalRules();
    for (auto part : {pipelineRules, rayQueryRules, creationRules, structureRules, hitObjectRules})
      for (RuleFaults& r : part()) all.push_back(std::move(r));
    return all;
  }();
  return table;
}

const RuleFaults* findRuleFaults(const std::string& rule) {
  for (const RuleFaults& r : ruleFaults())
    if (r.rule == rule) return &r;
  return nullptr;
}

RulesOfFault rulesOfFault(const std::string& fault) {
  RulesOfFault out;
  const auto names = [&fault](const std::vector<std::string>& list) {
    return std::find(list.begin(), list.end(), fault) != list.end();
  };
  for (const RuleFaults& r : ruleFaults()) {
    if (names(r.breaks) || names(r.live)) out.breaks.push_back(r.rule);
    if (names(r.legal)) out.allows.push_back(r.rule);
  }
  return out;
}

}  // namespace rayspec
