#include "metamorphic/feature_path.h"

#include <memory>

#include "case/flag_names.h"
#include "case/ray_query_inlining.h"

namespace rayspec {
namespace {

// The launch by an indirect command, where the case launches directly.
bool launchIndirect(Case& c, TraceCommand command, std::string* why_not) {
  if (c.rays.command != TraceCommand::Direct) {
    *why_not = "the case chooses its own launch command";
    return false;
  }
  c.rays.command = command;
  return true;
}

// One library holding every miss, hit and callable group; the linked
// pipeline keeps raygen.
bool intoLibrary(Case& c, std::string* why_not) {
  Pipeline& p = c.pipeline;
  if (!p.libraries.empty()) {
    *why_not = "the case builds its own pipeline libraries";
    return false;
  }
  PipelineLibrary lib;
  for (uint32_t i = 0; i < p.miss.size(); ++i) lib.miss.push_back(i);
  for (uint32_t i = 0; i < p.hit_groups.size(); ++i) lib.hit_groups.push_back(i);
  for (uint32_t i = 0; i < p.callables.size(); ++i) lib.callables.push_back(i);
  if (lib.miss.empty() && lib.hit_groups.empty() && lib.callables.empty()) {
    *why_not = "the case has no group but raygen to put in a library";
    return false;
  }
  p.libraries.push_back(std::move(lib));
  return true;
}

bool copied(Case& c, AsCopy copy, std::string* why_not) {
  if (c.scene.build.copy != AsCopy::None) {
    *why_not = "the case copies its structures its own way";
    return false;
  }
  c.scene.build.copy = copy;
  return true;
}

// Built with ALLOW_UPDATE, then updated in place to the very same geometry
// and instances (scene.update with nothing moved).
bool updatedInPlace(Case& c, std::string* why_not) {
  if (c.scene.updates()) {
    *why_not = "the case updates its structures itself";
    return false;
  }
  c.scene.build.flags |= kBuildAllowUpdate;
  c.scene.earlier.push_back(std::make_shared<const Scene>(c.scene));
  return true;
}

// Every trace a ray query loop, where nothing is in the way.
bool tracedByRayQuery(Case& c, std::string* why_not) {
  *why_not = rayQueryObstacle(c);
  if (!why_not->empty()) return false;
  c.pipeline.ray_query = true;
  return true;
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

std::optional<Case> throughPath(const Case& c, FeaturePath path, std::string* why_not) {
  Case out = c;
  bool ok = false;
  switch (path) {
    case FeaturePath::Indirect:
      ok = launchIndirect(out, TraceCommand::Indirect, why_not);
      break;
    case FeaturePath::Indirect2:
      ok = launchIndirect(out, TraceCommand::Indirect2, why_not);
      break;
    case FeaturePath::Libraries:
      ok = intoLibrary(out, why_not);
      break;
    case FeaturePath::Clone:
      ok = copied(out, AsCopy::Clone, why_not);
      break;
    case FeaturePath::Compact:
      ok = copied(out, AsCopy::Compact, why_not);
      break;
    case FeaturePath::Serialize:
      ok = copied(out, AsCopy::Serialize, why_not);
      break;
    case FeaturePath::Update:
      ok = updatedInPlace(out, why_not);
      break;
    case FeaturePath::RayQuery:
      ok = tracedByRayQuery(out, why_not);
      break;
  }
  if (!ok) return std::nullopt;
  return out;
}

}  // namespace rayspec
