#include "vulkan/case_buffers.h"

#include <cstring>
#include <string>

#include "glsl/bindings.h"
#include "results/record_layout.h"
#include "vulkan/vk_check.h"

namespace rayspec {
namespace {

// With their device address: pipeline.layout: empty reaches them so
// (vulkan/address_table.h).
constexpr VkBufferUsageFlags kStorage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;

bool isFloatField(const std::string& field) {
  const RecordField* f = findRecordField(field);
  return f && f->type == FieldType::Float;
}

}  // namespace

Result<ImageExtent> imageExtent(uint32_t launch_width, uint32_t launch_height,
                                uint32_t max_dimension) {
  if (launch_width <= max_dimension && launch_height <= max_dimension)
    return ImageExtent{launch_width, launch_height};
  const uint64_t rays = uint64_t(launch_width) * launch_height;
  const uint64_t rows = (rays + max_dimension - 1) / max_dimension;
  if (rows > max_dimension)
    return notSupported("an image of " + std::to_string(rays) + " texels does not fit " +
                        std::to_string(max_dimension) + "x" + std::to_string(max_dimension) +
                        " (maxImageDimension2D)");
  return ImageExtent{max_dimension, static_cast<uint32_t>(rows)};
}

Result<std::set<uint32_t>> caseBindings(const Plan& plan, const std::set<uint32_t>& declared) {
  std::set<uint32_t> b = {kBindingTlas, kBindingRays};
  if (plan.records) b.insert(kBindingRecords);
  if (!plan.counters.empty()) b.insert(kBindingCounters);
  if (plan.scene_data) b.insert(kBindingScene);
  if (plan.sbt_tables) b.insert(kBindingSbtTables);
  for (size_t i = 0; i < plan.images.size(); ++i)
    b.insert(kBindingFirstImage + static_cast<uint32_t>(i));
  for (uint32_t d : declared) {
    if (d >= kBindingFirstImage + plan.images.size())
      return deviceError("shaders declare binding " + std::to_string(d) +
                         " that no plan output backs: VK_ERROR_UNKNOWN");
    b.insert(d);
  }
  return b;
}

Result<CaseBuffers> createCaseBuffers(const VulkanContext& ctx, const Case& c, const Plan& plan,
                                      const std::set<uint32_t>& bindings, Cleanup& cleanup) {
  CaseBuffers out;
  out.bindings = bindings;
  std::vector<uint32_t> packed = packRays(c.rays);
  if (packed.size() * 4 > ctx.info.max_storage_buffer_range)
    return notSupported(std::to_string(c.rays.rays.size()) + " rays take " +
                        std::to_string(packed.size() * 4) + " bytes > maxStorageBufferRange " +
                        std::to_string(ctx.info.max_storage_buffer_range));
  RAYSPEC_TRY(out.rays,
              createUploadBuffer(ctx, packed.data(), packed.size() * 4, kStorage, cleanup));
  const uint64_t rays = static_cast<uint64_t>(c.rays.width) * c.rays.height;
  if (bindings.count(kBindingRecords)) {
    uint64_t bytes = rays * recordWords() * 4;
    // Reached by device address (shaders/common.glsl): no maxStorageBufferRange limit.
    RAYSPEC_TRY(out.records, createBuffer(ctx, bytes, kStorage, MemoryUse::Host, cleanup));
    std::memset(out.records.mapped, 0, bytes);
    const uint64_t address = out.records.address;
    RAYSPEC_TRY(out.records_ref,
                createUploadBuffer(ctx, &address, sizeof(address), kStorage, cleanup));
  }
  if (bindings.count(kBindingCounters)) {
    uint64_t bytes = (plan.counters.empty() ? 1 : plan.counters.size()) * 4;
    RAYSPEC_TRY(out.counters, createBuffer(ctx, bytes, kStorage, MemoryUse::Host, cleanup));
    std::memset(out.counters.mapped, 0, bytes);
  }
  if (bindings.count(kBindingScene)) {
    std::vector<uint32_t> scene = packSceneData(c.scene);
    RAYSPEC_TRY(out.scene,
                createUploadBuffer(ctx, scene.data(), scene.size() * 4, kStorage, cleanup));
  }
  if (bindings.count(kBindingSbtTables)) {
    const SbtTables tables = packSbtTables(c.pipeline);
    RAYSPEC_TRY(out.sbt_tables, createUploadBuffer(ctx, tables.words.data(),
                                                   tables.words.size() * 4, kStorage, cleanup));
  }
  if (!plan.images.empty()) {
    RAYSPEC_TRY(out.image_extent,
                imageExtent(c.rays.width, c.rays.height, ctx.info.max_image_dimension_2d));
  }
  const uint64_t texels = uint64_t(out.image_extent.width) * out.image_extent.height;
  for (const ImageOutput& img : plan.images) {
    bool is_float = isFloatField(img.field);
    out.image_float.push_back(is_float);
    RAYSPEC_TRY(
        out.images.emplace_back(),
        createStorageImage(ctx, out.image_extent.width, out.image_extent.height,
                           is_float ? VK_FORMAT_R32G32B32A32_SFLOAT : VK_FORMAT_R32_UINT, cleanup));
    RAYSPEC_TRY(out.image_readback.emplace_back(),
                createBuffer(ctx, texels * (is_float ? 16 : 4), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                             MemoryUse::Host, cleanup));
  }
  return out;
}

std::vector<DescriptorItem> descriptorItems(const CaseBuffers& b,
                                            const std::vector<VkAccelerationStructureKHR>& tlases) {
  std::vector<DescriptorItem> items;
  for (uint32_t binding : b.bindings) {
    DescriptorItem it;
    it.binding = binding;
    if (binding == kBindingTlas) {
      it.type = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
      it.tlases = tlases;
    } else if (binding >= kBindingFirstImage) {
      it.type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
      it.view = b.images.at(binding - kBindingFirstImage).view;
    } else {
      it.buffer = binding == kBindingRays       ? b.rays.buffer
                  : binding == kBindingRecords  ? b.records_ref.buffer
                  : binding == kBindingCounters ? b.counters.buffer
                  : binding == kBindingScene    ? b.scene.buffer
                                                : b.sbt_tables.buffer;
    }
    items.push_back(it);
  }
  return items;
}

void readResults(const CaseBuffers& b, const Plan& plan, uint32_t width, uint32_t height,
                 Results& r) {
  const uint64_t rays = static_cast<uint64_t>(width) * height;
  if (b.records.mapped) {
    const uint32_t* words = static_cast<const uint32_t*>(b.records.mapped);
    r.records.assign(words, words + rays * recordWords());
  }
  if (b.counters.mapped) {
    const uint32_t* words = static_cast<const uint32_t*>(b.counters.mapped);
    for (size_t i = 0; i < plan.counters.size(); ++i) r.counters[plan.counters[i]] = words[i];
  }
  for (size_t i = 0; i < b.images.size(); ++i) {
    Image img;
    img.name = plan.images[i].name;
    img.field = plan.images[i].field;
    img.width = width;
    img.height = height;
    img.is_float = b.image_float[i];
    img.channels = img.is_float ? 4 : 1;
    const uint32_t* texels = static_cast<const uint32_t*>(b.image_readback[i].mapped);
    img.texels.assign(texels, texels + rays * img.channels);
    r.images.push_back(std::move(img));
  }
}

}  // namespace rayspec
