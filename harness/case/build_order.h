// Where a scene's copy (scene.build.copy) and structure queries
// (scene.build.queries) come in the order of each level's build and updates
// (scene.build.order): after how many of its updates. The Vulkan builds
// (vulkan/scene_builder.cpp) and the C export's player (export/
// scene_section.cpp: RS_COPY_AT, RS_QUERY_AT) both take them from here.
#pragma once

#include <algorithm>
#include <cstddef>

#include "case/case.h"

namespace rayspec {

// The copy: after Scene::updatesBeforeCopy() updates; without one,
// updates() + 1 (never).
inline size_t copyAt(const Scene& scene) {
  return scene.build.copy == AsCopy::None ? scene.updates() + 1 : scene.updatesBeforeCopy();
}

// The queries: just before the copy, or (without one) once the last update
// ran; updates() + 1 (never) where none is asked.
inline size_t queryAt(const Scene& scene) {
  if (scene.build.queries.queries.empty()) return scene.updates() + 1;
  return std::min(copyAt(scene), scene.updates());
}

}  // namespace rayspec
