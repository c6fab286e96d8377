// Feature paths (--through): a way of building and launching that must not
// change what shaders observe, applied to every case of a run so that the
// path meets every family (R-INDIRECT, R-LIBRARY, R-AS-COPY, R-AS-UPDATE,
// R-RQ-EQUIV, R-AS-BUILD, R-DEFERRED), or laying the build inputs out another way (layouts).
// The model's expectation stays the case's own; a case that already takes
// another way of the same kind (its own launch command, libraries, copy or
// update) is not sent through it, and says why.
#pragma once

#include <optional>
#include <string>

#include "base/enum_names.h"
#include "base/result.h"
#include "case/case.h"

namespace rayspec {

#define RAYSPEC_FEATURE_PATHS(X)                                                              \
  X(Indirect, "indirect")   /* rays.command indirect: vkCmdTraceRaysIndirectKHR */            \
  X(Indirect2, "indirect2") /* rays.command indirect2: vkCmdTraceRaysIndirect2KHR */          \
  X(Libraries, "libraries") /* every miss, hit and callable group in one pipeline library */  \
  X(Clone, "clone")         /* scene.build.copy clone */                                      \
  X(Compact, "compact")     /* scene.build.copy compact */                                    \
  X(Serialize, "serialize") /* scene.build.copy serialize */                                  \
  /* built with ALLOW_UPDATE, then updated in place to the same scene */                      \
  X(Update, "update")                                                                         \
  /* every trace a ray query loop in raygen (case/ray_query_inlining.h) */                    \
  X(RayQuery, "ray-query")                                                                    \
  /* the same loops in raygen run as a compute shader, one vkCmdDispatch */                   \
  X(RayQueryCompute, "ray-query-compute")                                                     \
  /* closest-hit's and miss's traces ray query loops there (case/ray_query_inlining.h) */     \
  X(RayQueryInHit, "ray-query-in-hit")                                                        \
  /* build inputs behind pointers, at offsets, at padded strides (scene.build layouts) */     \
  X(Layouts, "layouts")                                                                       \
  /* every build and update in a command of its own, one scratch (scene.build.one_by_one) */  \
  X(OneByOne, "one-by-one")                                                                   \
  /* updated into a second structure (scene.build.update_into other; no update: to itself) */ \
  X(UpdateIntoOther, "update-into-other")                                                     \
  /* every structure created GENERIC, built as bottom or top (scene.build.generic both) */    \
  X(Generic, "generic")                                                                       \
  /* every buffer of the builds in sparse-bound memory, page by page (scene.build.sparse) */  \
  X(Sparse, "sparse")                                                                         \
  /* structures in shared buffers over a destroyed decoy's memory (scene.build.storage) */    \
  X(ReusedStorage, "reused-storage")                                                          \
  /* made through a deferred operation joined by 4 threads (pipeline.deferred) */             \
  X(Deferred, "deferred")
enum class FeaturePath { RAYSPEC_FEATURE_PATHS(RAYSPEC_ENUMERATOR) };
RAYSPEC_ENUM_NAMES(FeaturePath, RAYSPEC_FEATURE_PATHS);

// The strides of the layouts path.
constexpr uint32_t kLayoutsVertexStride = 20;
constexpr uint32_t kLayoutsAabbStride = 40;
// The threads that join each deferred operation of the deferred path: more
// than one, so that a thread may find no work left (VK_THREAD_DONE_KHR).
constexpr uint32_t kDeferredPathThreads = 4;

const char* featurePathName(FeaturePath p);
std::optional<FeaturePath> featurePathFromName(const std::string& name);
const std::string& featurePathNames();  // "indirect, indirect2, ..." for help and errors

// The case sent through `path`, or the error saying why it cannot go.
Result<Case> throughPath(const Case& c, FeaturePath path);

}  // namespace rayspec
