// A cheap, conservative rejection ahead of watertightIntersect (exact and
// robust tiers, model_scene.cpp): a triangle the ray certainly misses, by a
// margin larger than the error bound of every edge function, is dropped
// without the full test (its bound per edge, t, barycentrics and t's error).
//
// It answers true only where watertightIntersectPrepared(ray, v0, v1, v2, vertex_err)
// returns either valid == false or hit == false with ambiguity == None: the
// two answers the model drops a triangle on. The proof is in
// watertight_rejection.cpp; tests/model_rejection_test.cpp checks it on
// random and adversarial (edge- and vertex-hitting) rays.
#pragma once

#include "model/watertight.h"

namespace rayspec {

bool watertightCertainMiss(const WatertightRay& ray, const DVec3& v0, const DVec3& v1,
                           const DVec3& v2, const DVec3& vertex_err);

}  // namespace rayspec
