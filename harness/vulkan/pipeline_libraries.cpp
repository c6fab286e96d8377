// The case's ray tracing pipeline, monolithic or linked from the case's
// pipeline libraries (pipeline.libraries, VK_KHR_pipeline_library).
#include <algorithm>
#include <set>

#include "vulkan/pipeline.h"
#include "vulkan/sbt_layout.h"

namespace rayspec {
namespace {

// Case group ids (sbt_layout.h's group order) of one library's own groups.
std::vector<uint32_t> ownGroups(const Pipeline& p, const PipelineLibrary& lib) {
  std::set<uint32_t> ids;
  for (uint32_t i : lib.miss) ids.insert(sbtMissGroup(p, i));
  for (uint32_t i : lib.hit_groups) ids.insert(sbtHitGroup(p, i));
  for (uint32_t i : lib.callables) ids.insert(sbtCallableGroup(p, i));
  return {ids.begin(), ids.end()};
}

void collectPlaced(const Pipeline& p, const std::vector<PipelineLibrary>& libs,
                   std::set<uint32_t>& placed) {
  for (const PipelineLibrary& lib : libs) {
    for (uint32_t id : ownGroups(p, lib)) placed.insert(id);
    collectPlaced(p, lib.libraries, placed);
  }
}

struct Linker {
  const VulkanContext& ctx;
  const CompiledPipeline& compiled;
  const Pipeline& p;
  VkPipelineLayout layout;
  Cleanup& cleanup;
  std::vector<GroupSite>& sites;  // by case group id

  void place(const PipelinePart& part, VkPipeline object) const {
    for (uint32_t i = 0; i < part.groups.size(); ++i) sites.at(part.groups[i]) = {object, i};
  }

  PipelinePart part(std::vector<uint32_t> groups, VkPipelineCreateFlags extra) const {
    PipelinePart out;
    out.groups = std::move(groups);
    out.flags = p.flags | extra;
    out.max_recursion = p.max_recursion;
    out.max_payload_bytes = interfacePayloadBytes(p);
    out.layout = layout;
    out.deferred_threads = p.deferred_threads;
    return out;
  }

  // Creates the libraries of `libs` (children first) into `part`; appends
  // their groups, in the linked pipeline's order, to `order`.
  Result<void> link(const std::vector<PipelineLibrary>& libs, PipelinePart& into,
                    std::vector<uint32_t>& order) {
    into.linked = !libs.empty();
    for (const PipelineLibrary& lib : libs) {
      PipelinePart own = part(ownGroups(p, lib), VK_PIPELINE_CREATE_LIBRARY_BIT_KHR);
      std::vector<uint32_t> lib_order = own.groups;
      RAYSPEC_TRY_VOID(link(lib.libraries, own, lib_order));
      own.linked = true;  // a library always declares the interface
      RAYSPEC_TRY(into.libraries.emplace_back(), createPipelineObject(ctx, compiled, own, cleanup));
      place(own, into.libraries.back());
      order.insert(order.end(), lib_order.begin(), lib_order.end());
    }
    return {};
  }
};

}  // namespace

uint32_t interfacePayloadBytes(const Pipeline& p) {
  uint32_t payload = 0;
  for (size_t location = 0; location < p.payload_words.size(); ++location)
    payload = std::max(payload, p.payloadBytes(location));
  return std::max(payload, p.callDataBytes(p.maxCallDataWords(), p.allCallDataSized()));
}

Result<RayTracingPipeline> createRayTracingPipeline(const VulkanContext& ctx,
                                                    const CompiledPipeline& compiled,
                                                    const Pipeline& p, VkPipelineLayout layout,
                                                    Cleanup& cleanup) {
  const uint32_t count = sbtGroupCount(p);
  std::set<uint32_t> placed;
  collectPlaced(p, p.libraries, placed);
  RayTracingPipeline out;
  out.group_site.assign(count, {});
  Linker linker{ctx, compiled, p, layout, cleanup, out.group_site};
  std::vector<uint32_t> own;
  for (uint32_t id = 0; id < count; ++id)
    if (!placed.count(id)) own.push_back(id);
  PipelinePart top = linker.part(own, 0);
  top.dynamic_stack_size = p.callable_depth.has_value();
  std::vector<uint32_t> order = own;
  RAYSPEC_TRY_VOID(linker.link(p.libraries, top, order));

  RAYSPEC_TRY(out.pipeline, createPipelineObject(ctx, compiled, top, cleanup));
  linker.place(top, out.pipeline);
  out.group_index.assign(count, 0);
  for (uint32_t linked = 0; linked < order.size(); ++linked)
    out.group_index[order[linked]] = linked;
  return out;
}

}  // namespace rayspec
