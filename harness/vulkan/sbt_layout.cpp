#include "vulkan/sbt_layout.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "base/align.h"

namespace rayspec {

SbtLimits sbtLimits(const DeviceInfo& d) {
  SbtLimits l;
  l.handle_size = d.shader_group_handle_size;
  l.handle_alignment = d.shader_group_handle_alignment;
  l.base_alignment = d.shader_group_base_alignment;
  l.max_stride = d.max_shader_group_stride;
  return l;
}
namespace {

std::vector<SbtRecord> orDefault(const std::vector<SbtRecord>& given, size_t groups) {
  if (!given.empty()) return given;
  std::vector<SbtRecord> out(groups);
  for (size_t i = 0; i < groups; ++i) out[i].group = static_cast<uint32_t>(i);
  return out;
}

// One record (group handle, then data words) into `out` at byte `at`.
Result<void> writeRecord(const SbtLimits& limits, uint32_t record_data, uint64_t at,
                         std::optional<uint32_t> group, uint32_t group_base, uint32_t group_limit,
                         const std::vector<uint32_t>& data, const std::vector<uint8_t>& handles,
                         std::vector<uint8_t>& out, const std::string& what) {
  if (!group) return {};  // all-zero record (R-SBT-ZERO): handle and data stay zero
  if (*group >= group_limit)
    return errorMessage(what + ": group " + std::to_string(*group) + " out of range (" +
                        std::to_string(group_limit) + " groups)");
  const uint32_t room = std::min(record_data, kSbtRecordDataBytes);
  if (data.size() * 4 > room)
    return errorMessage(what + ": " + std::to_string(data.size()) + " data words (at most " +
                        std::to_string(room / 4) + ")");
  const uint64_t src = static_cast<uint64_t>(group_base + *group) * limits.handle_size;
  if (src + limits.handle_size > handles.size())
    return errorMessage(what + ": handle array too short");
  std::memcpy(out.data() + at, handles.data() + src, limits.handle_size);
  if (!data.empty())
    std::memcpy(out.data() + at + limits.handle_size, data.data(), data.size() * 4);
  return {};
}

// The records of one region, each from its group among group_limit groups
// that start at group_base.
Result<void> writeRegion(const SbtLimits& limits, uint32_t record_data, const SbtRegion& region,
                         const std::vector<SbtRecord>& records, uint32_t group_base,
                         uint32_t group_limit, const std::vector<uint8_t>& handles,
                         std::vector<uint8_t>& out, const char* name) {
  for (size_t i = 0; i < records.size(); ++i) {
    const std::string what = std::string("sbt ") + name + " record " + std::to_string(i);
    if (Result<void> r =
            writeRecord(limits, record_data, region.offset + i * region.stride, records[i].group,
                        group_base, group_limit, records[i].data, handles, out, what);
        !r)
      return r;
  }
  return {};
}

// The rule of vkCmdTraceRaysKHR a non-empty region breaks ("" none).
std::string regionProblem(const SbtRegion& r, const SbtLimits& limits, uint64_t total_size) {
  if (r.offset % limits.base_alignment)
    return "offset " + std::to_string(r.offset) + " not a multiple of shaderGroupBaseAlignment";
  if (r.stride % limits.handle_alignment)
    return "stride " + std::to_string(r.stride) + " not a multiple of shaderGroupHandleAlignment";
  if (r.stride > limits.max_stride)
    return "stride " + std::to_string(r.stride) + " > maxShaderGroupStride " +
           std::to_string(limits.max_stride);
  if (r.stride < limits.handle_size) return "stride smaller than the handle";
  if (r.offset + r.size > total_size) return "past the end of the table";
  return {};
}

}  // namespace

uint32_t sbtGroupCount(const Pipeline& p) {
  return static_cast<uint32_t>(p.raygenGroupCount() + p.miss.size() + p.hit_groups.size() +
                               p.callables.size());
}
uint32_t sbtMissGroup(const Pipeline& p, uint32_t i) {
  return p.raygenGroupCount() + i;
}
uint32_t sbtHitGroup(const Pipeline& p, uint32_t i) {
  return static_cast<uint32_t>(p.raygenGroupCount() + p.miss.size() + i);
}
uint32_t sbtCallableGroup(const Pipeline& p, uint32_t i) {
  return static_cast<uint32_t>(p.raygenGroupCount() + p.miss.size() + p.hit_groups.size() + i);
}

std::vector<SbtRecord> sbtMissRecords(const Pipeline& p) {
  return orDefault(p.sbt_miss, p.miss.size());
}
std::vector<SbtRecord> sbtHitRecords(const Pipeline& p) {
  return orDefault(p.sbt_hit, p.hit_groups.size());
}
std::vector<SbtRecord> sbtCallableRecords(const Pipeline& p) {
  return orDefault(p.sbt_callable, p.callables.size());
}

uint64_t sbtStride(const SbtLimits& limits, uint32_t record_data, uint32_t padding) {
  return alignUp(uint64_t{limits.handle_size} + record_data + padding, limits.handle_alignment);
}

SbtLayout computeSbtLayout(const SbtLimits& limits, const Pipeline& p) {
  const uint32_t k = p.sbt_record_data;
  const uint64_t raygen = sbtStride(limits, k, 0);
  SbtLayout layout;
  layout.raygen = {0, raygen, raygen, 1};
  uint64_t end = raygen;
  auto place = [&](SbtRegion& region, size_t count, uint32_t padding) {
    if (count == 0) return;  // empty region: all zero
    const uint64_t stride = sbtStride(limits, k, padding);
    region.count = static_cast<uint32_t>(count);
    region.offset = alignUp(end, limits.base_alignment);
    region.stride = stride;
    region.size = stride * count;
    end = region.offset + region.size;
  };
  place(layout.miss, sbtMissRecords(p).size(), p.sbt_padding.miss);
  place(layout.hit, sbtHitRecords(p).size(), p.sbt_padding.hit);
  place(layout.callable, sbtCallableRecords(p).size(), p.sbt_padding.callable);
  layout.total_size = end;
  return layout;
}

Result<void> checkSbtLayout(const SbtLayout& layout, const SbtLimits& limits) {
  const std::pair<const char*, const SbtRegion*> regions[] = {{"raygen", &layout.raygen},
                                                              {"miss", &layout.miss},
                                                              {"hit", &layout.hit},
                                                              {"callable", &layout.callable}};
  for (const auto& [name, region] : regions)
    if (region->size != 0)
      if (const std::string problem = regionProblem(*region, limits, layout.total_size);
          !problem.empty())
        return errorMessage(std::string("sbt ") + name + " region: " + problem);
  if (layout.raygen.size != layout.raygen.stride)
    return errorMessage("sbt raygen region: size != stride");
  return {};
}

Result<std::vector<uint8_t>> writeSbt(const SbtLayout& layout, const SbtLimits& limits,
                                      const Pipeline& p, const std::vector<uint8_t>& handles) {
  std::vector<uint8_t> out(layout.total_size, 0);
  const uint64_t need = static_cast<uint64_t>(sbtGroupCount(p)) * limits.handle_size;
  if (handles.size() < need)
    return errorMessage("sbt: " + std::to_string(handles.size()) + " handle bytes, need " +
                        std::to_string(need));
  SbtRecord raygen;
  raygen.group = p.raygen_group;
  raygen.data = p.raygen_data;
  const uint32_t k = p.sbt_record_data;
  Result<void> r = writeRegion(limits, k, layout.raygen, {raygen}, 0, p.raygenGroupCount(), handles,
                               out, "raygen");
  if (r)
    r = writeRegion(limits, k, layout.miss, sbtMissRecords(p), sbtMissGroup(p, 0),
                    static_cast<uint32_t>(p.miss.size()), handles, out, "miss");
  if (r)
    r = writeRegion(limits, k, layout.hit, sbtHitRecords(p), sbtHitGroup(p, 0),
                    static_cast<uint32_t>(p.hit_groups.size()), handles, out, "hit");
  if (r)
    r = writeRegion(limits, k, layout.callable, sbtCallableRecords(p), sbtCallableGroup(p, 0),
                    static_cast<uint32_t>(p.callables.size()), handles, out, "callable");
  if (!r) return r.error();
  return out;
}

}  // namespace rayspec
