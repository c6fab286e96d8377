#include "export/export_support.h"

#include <algorithm>

#include "compare/counter_modes.h"

namespace rayspec {
namespace {

// The pipeline's shape: one pipeline of every stage (its traces by ray
// query too, or raygen as a compute shader), without flags, specialization
// or a dynamic stack size.
std::string pipelineFeature(const Case& c, const Plan& plan) {
  const Pipeline& p = c.pipeline;
  if (!c.expected_rejections.empty()) return "expected compiler rejections (expect_rejected)";
  if (plan.dynamic_tlas_index) return "top levels indexed dynamically (tlas: expr)";
  if (!p.libraries.empty()) return "pipeline libraries";
  if (p.deferred_threads) return "deferred pipeline creation (pipeline.deferred)";
  if (p.callable_depth) return "a dynamic stack size (pipeline.callable_depth)";
  if (p.flags) return "pipeline create flags (pipeline.flags)";
  if (!p.constants.empty() || !p.specialize.empty()) return "specialization constants";
  if (p.empty_layout) return "an empty pipeline layout (pipeline.layout)";
  if (plan.position_fetch) return "position fetch (vertex_position)";
  if (plan.hit_objects) return "hit objects (VK_NV_ray_tracing_invocation_reorder)";
  if (plan.cull_mask_builtin) return "the cull_mask built-in (VK_KHR_ray_tracing_maintenance1)";
  return "";
}

// Whether every update (scene.update) keeps the scene's shape: its BLASes'
// geometry counts and its instance count (the player's tables hold one
// shape for every state, as the updates of rayspec's builds need).
bool updatesKeepShape(const Scene& s) {
  for (const auto& e : s.earlier) {
    if (e->blases.size() != s.blases.size() || e->instances.size() != s.instances.size())
      return false;
    for (size_t b = 0; b < s.blases.size(); ++b)
      if (e->blases[b].geometries.size() != s.blases[b].geometries.size()) return false;
  }
  return true;
}

// The scene: bottom levels of triangles or boxes, top levels over instances
// read directly; built with device commands, updated (scene.update) and
// copied (scene.build.copy) as rayspec's builds do.
std::string sceneFeature(const Case& c) {
  const Scene& s = c.scene;
  if (!updatesKeepShape(s)) return "updates that change the scene's shape (scene.update)";
  if (!s.build.queries.queries.empty() && s.build.queries.command == QueryCommand::Host)
    return "structure queries on the host (scene.build.query_command host)";
  if (s.build.command != BuildCommand::Device) return "indirect builds (scene.build.command)";
  if (s.build.instances_as_pointers) return "instances as pointers (scene.build)";
  for (const Instance& i : s.instances)
    if (i.flags & kInstanceOpacityMicromapFlags)
      return "opacity micromap instance flags (VK_EXT_opacity_micromap)";
  if (s.blases.empty() || s.instances.empty()) return "an empty scene";
  if (std::all_of(s.blases.begin(), s.blases.end(),
                  [](const Blas& b) { return b.geometries.empty(); }))
    return "an empty bottom level";
  if (c.rays.command != TraceCommand::Direct) return "an indirect trace (rays.command)";
  if (const uint64_t rays = uint64_t(c.rays.width) * c.rays.height; rays > kMaxExportedRays)
    return "a launch of " + std::to_string(rays) + " rays (at most " +
           std::to_string(kMaxExportedRays) + " are embedded)";
  return "";
}

// Whether any-hit repetition may change a record or a counter not
// informational (compare/any_hit_repeat_verdict.cpp).
bool repeatChangesJudged(const Case& c, const Results& model) {
  const std::map<std::string, CounterMode> modes = counterModes(c);
  return !model.repeat_dependent.empty() ||
         std::any_of(model.repeat_counters.begin(), model.repeat_counters.end(),
                     [&](const std::string& name) {
                       const auto it = modes.find(name);
                       return it != modes.end() && it->second != CounterMode::Informational;
                     });
}

// What the model expects, as the player compares it: clear rays, ambiguous
// rays with their legal answers replayed (on a shared edge or vertex, with
// the double hits and leaks the judge accepts with a warning, replayed too).
std::string expectationFeature(const Case& c, const Results& model) {
  // R-AHIT-DUP: what any-hit repetition may change is left out where the
  // case claims the rule; else rayspec judges the case not portable.
  if (repeatChangesJudged(c, model) &&
      std::find(c.rules.begin(), c.rules.end(), "R-AHIT-DUP") == c.rules.end())
    return "rays any-hit repetition may change, R-AHIT-DUP not claimed (not portable)";
  if (!model.order_dependent.empty() || !model.endless_restarts.empty())
    return "order-dependent candidate programs";
  for (const RayAmbiguity& a : model.ambiguous) {
    if (a.replays.empty() || a.replays[0].record.size() != recordWords())
      return "an ambiguous ray without replayed legal answers";
    // The judge reads a hit behind a shared edge as a pass between its
    // triangles (R-WATERTIGHT, a QualityWarning) by the hit alone where the
    // model replayed none of them; the player holds records to replays.
    if (!a.leak_answers.empty() && a.leak_replays.empty())
      return "a ray on a shared edge or vertex whose leaks the model does not replay "
             "(R-WATERTIGHT)";
  }
  return "";
}

// The images: the model draws each, and those the case declares equal
// (equal_to) are equal in the model (else rayspec's verdict is a CaseError).
std::string imageFeature(const Plan& plan, const Results& model) {
  for (const ImageOutput& out : plan.images) {
    const Image* im = imageNamed(model, out.name);
    if (!im) return "an image the model does not draw (" + out.name + ")";
    if (out.equal_to.empty()) continue;
    const Image* other = imageNamed(model, out.equal_to);
    if (!other || other->texels != im->texels)
      return "images declared equal (equal_to) that the model draws differently (a CaseError)";
  }
  return "";
}

}  // namespace

const Image* imageNamed(const Results& r, const std::string& name) {
  for (const Image& im : r.images)
    if (im.name == name) return &im;
  return nullptr;
}

std::string unexportedFeature(const Case& c, const Plan& plan, const Results& model) {
  if (!model.ok()) return "a case the model does not run (" + model.statusText() + ")";
  if (std::string f = pipelineFeature(c, plan); !f.empty()) return f;
  if (std::string f = sceneFeature(c); !f.empty()) return f;
  if (std::string f = imageFeature(plan, model); !f.empty()) return f;
  return expectationFeature(c, model);
}

}  // namespace rayspec
