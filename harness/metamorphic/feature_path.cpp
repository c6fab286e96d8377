#include "metamorphic/feature_path.h"

#include <memory>

#include "case/flag_names.h"
#include "case/ray_query_inlining.h"

namespace rayspec {
namespace {

// The launch by an indirect command, where the case launches directly.
Result<void> launchIndirect(Case& c, TraceCommand command) {
  if (c.rays.command != TraceCommand::Direct) {
    return errorMessage("the case chooses its own launch command");
  }
  c.rays.command = command;
  return {};
}

// One library holding every miss, hit and callable group; the linked
// pipeline keeps raygen.
Result<void> intoLibrary(Case& c) {
  Pipeline& p = c.pipeline;
  if (!p.libraries.empty()) {
    return errorMessage("the case builds its own pipeline libraries");
  }
  if (p.empty_layout) return errorMessage("its pipeline layout is empty (pipeline.layout)");
  PipelineLibrary lib;
  for (uint32_t i = 0; i < p.miss.size(); ++i) lib.miss.push_back(i);
  for (uint32_t i = 0; i < p.hit_groups.size(); ++i) lib.hit_groups.push_back(i);
  for (uint32_t i = 0; i < p.callables.size(); ++i) lib.callables.push_back(i);
  if (lib.miss.empty() && lib.hit_groups.empty() && lib.callables.empty()) {
    return errorMessage("the case has no group but raygen to put in a library");
  }
  p.libraries.push_back(std::move(lib));
  return {};
}

Result<void> copied(Case& c, AsCopy copy) {
  if (c.scene.build.copy != AsCopy::None) {
    return errorMessage("the case copies its structures its own way");
  }
  c.scene.build.copy = copy;
  return {};
}

// Built with ALLOW_UPDATE, then updated in place to the very same geometry
// and instances (scene.update with nothing moved).
Result<void> updatedInPlace(Case& c) {
  if (c.scene.updates()) {
    return errorMessage("the case updates its structures itself");
  }
  c.scene.build.flags |= kBuildAllowUpdate;
  c.scene.earlier.push_back(std::make_shared<const Scene>(c.scene));
  return {};
}

// Every trace a ray query loop, where nothing is in the way.
Result<void> tracedByRayQuery(Case& c) {
  if (std::string obstacle = rayQueryObstacle(c); !obstacle.empty())
    return errorMessage(std::move(obstacle));
  c.pipeline.ray_query = true;
  return {};
}

// Raygen, its traces ray query loops, run as a compute shader.
Result<void> tracedFromCompute(Case& c) {
  if (std::string obstacle = computeRayQueryObstacle(c); !obstacle.empty())
    return errorMessage(std::move(obstacle));
  c.pipeline.ray_query = true;
  c.pipeline.from_compute = true;
  return {};
}

// The traces of closest-hit and miss stages ray query loops there, where
// there are some and nothing is in the way.
Result<void> tracedByRayQueryInHit(Case& c) {
  if (std::string obstacle = rayQueryInHitObstacle(c); !obstacle.empty())
    return errorMessage(std::move(obstacle));
  c.pipeline.ray_query_in_hit = true;
  return {};
}

// Every build input laid out another way: instances behind pointers, every
// input at offsets behind junk, vertices 20 bytes apart (fits every vertex
// format: at least 12 bytes, a multiple of 4) and boxes 40. Not
// first_vertex: lavapipe 25.0.7 applies it twice, which would fail every
// triangle case; accel/layouts-first-vertex checks it alone.
Result<void> laidOut(Case& c) {
  if (c.scene.build.customLayout()) {
    return errorMessage("the case lays its build inputs out itself");
  }
  c.scene.build.instances_as_pointers = true;
  c.scene.build.data_offsets = true;
  c.scene.build.vertex_stride = kLayoutsVertexStride;
  c.scene.build.aabb_stride = kLayoutsAabbStride;
  return {};
}

// Every build and update recorded in a command of its own, in sequence, in
// the same scratch memory behind barriers.
Result<void> builtOneByOne(Case& c) {
  if (c.scene.build.one_by_one) return errorMessage("the case builds one by one itself");
  c.scene.build.one_by_one = true;
  return {};
}

// Every update written into a second structure, source and destination
// differing: a case's own updates, or else one to the same scene.
Result<void> updatedIntoOther(Case& c) {
  if (c.scene.build.copy != AsCopy::None)
    return errorMessage("the case copies its structures (an update into another is not combined)");
  if (!c.scene.updates()) RAYSPEC_TRY_VOID(updatedInPlace(c));
  c.scene.build.update_into_other = true;
  return {};
}

// Every structure, copies and update targets too, created with the GENERIC
// type and built with its real one.
Result<void> createdGeneric(Case& c) {
  if (c.scene.build.generic != GenericLevels::None)
    return errorMessage("the case chooses its own GENERIC levels");
  c.scene.build.generic = GenericLevels::Both;
  return {};
}

// Every buffer of the builds in sparse-bound memory: structures, scratch,
// instances and geometry.
Result<void> sparselyBound(Case& c) {
  if (c.scene.build.sparse.any()) return errorMessage("the case binds its memory sparsely itself");
  if (c.scene.build.storage != StructureStorage::Own)
    return errorMessage("the case places its structures in shared buffers");
  c.scene.build.sparse = SparseBuffers::every();
  return {};
}

// Every structure in shared buffers, over the memory of a decoy scene built
// and destroyed first, with another structure created over each.
Result<void> reusedStorage(Case& c) {
  if (c.scene.build.storage != StructureStorage::Own)
    return errorMessage("the case chooses its own structure storage");
  if (c.scene.build.sparse.structures)
    return errorMessage("the case binds its structures sparsely");
  c.scene.build.storage = StructureStorage::Reused;
  return {};
}

// Every pipeline object created through a deferred operation joined by
// kDeferredPathThreads threads.
Result<void> createdDeferred(Case& c) {
  if (c.pipeline.deferred_threads)
    return errorMessage("the case creates its pipelines through a deferred operation itself");
  if (c.pipeline.from_compute)
    return errorMessage("the case makes no ray tracing pipeline (raygen runs as compute)");
  c.pipeline.deferred_threads = kDeferredPathThreads;
  return {};
}

}  // namespace

const char* featurePathName(FeaturePath p) {
  return nameOf(p);
}

std::optional<FeaturePath> featurePathFromName(const std::string& name) {
  return valueNamed<FeaturePath>(name);
}

const std::string& featurePathNames() {
  static const std::string names = namesJoined(enumNames<FeaturePath>());
  return names;
}

Result<Case> throughPath(const Case& c, FeaturePath path) {
  Case out = c;
  switch (path) {
    case FeaturePath::Indirect:
      RAYSPEC_TRY_VOID(launchIndirect(out, TraceCommand::Indirect));
      break;
    case FeaturePath::Indirect2:
      RAYSPEC_TRY_VOID(launchIndirect(out, TraceCommand::Indirect2));
      break;
    case FeaturePath::Libraries:
      RAYSPEC_TRY_VOID(intoLibrary(out));
      break;
    case FeaturePath::Clone:
      RAYSPEC_TRY_VOID(copied(out, AsCopy::Clone));
      break;
    case FeaturePath::Compact:
      RAYSPEC_TRY_VOID(copied(out, AsCopy::Compact));
      break;
    case FeaturePath::Serialize:
      RAYSPEC_TRY_VOID(copied(out, AsCopy::Serialize));
      break;
    case FeaturePath::Update:
      RAYSPEC_TRY_VOID(updatedInPlace(out));
      break;
    case FeaturePath::RayQuery:
      RAYSPEC_TRY_VOID(tracedByRayQuery(out));
      break;
    case FeaturePath::RayQueryCompute:
      RAYSPEC_TRY_VOID(tracedFromCompute(out));
      break;
    case FeaturePath::RayQueryInHit:
      RAYSPEC_TRY_VOID(tracedByRayQueryInHit(out));
      break;
    case FeaturePath::Layouts:
      RAYSPEC_TRY_VOID(laidOut(out));
      break;
    case FeaturePath::OneByOne:
      RAYSPEC_TRY_VOID(builtOneByOne(out));
      break;
    case FeaturePath::UpdateIntoOther:
      RAYSPEC_TRY_VOID(updatedIntoOther(out));
      break;
    case FeaturePath::Generic:
      RAYSPEC_TRY_VOID(createdGeneric(out));
      break;
    case FeaturePath::Sparse:
      RAYSPEC_TRY_VOID(sparselyBound(out));
      break;
    case FeaturePath::ReusedStorage:
      RAYSPEC_TRY_VOID(reusedStorage(out));
      break;
    case FeaturePath::Deferred:
      RAYSPEC_TRY_VOID(createdDeferred(out));
      break;
  }
  return out;
}

}  // namespace rayspec
