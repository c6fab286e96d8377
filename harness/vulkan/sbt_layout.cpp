#include "vulkan/sbt_layout.h"

#include <algorithm>
#include <cstring>

#include "base/align.h"

namespace rayspec {
namespace {

std::vector<SbtRecord> orDefault(const std::vector<SbtRecord>& given, size_t groups) {
  if (!given.empty()) return given;
  std::vector<SbtRecord> out(groups);
  for (size_t i = 0; i < groups; ++i) out[i].group = static_cast<uint32_t>(i);
  return out;
}

bool writeRecord(const SbtLimits& limits, uint32_t record_data, uint64_t at,
                 std::optional<uint32_t> group, uint32_t group_base, uint32_t group_limit,
                 const std::vector<uint32_t>& data, const std::vector<uint8_t>& handles,
                 std::vector<uint8_t>* out, const std::string& what, std::string* error) {
  if (!group) return true;  // all-zero record (R-SBT-ZERO): handle and data stay zero
  if (*group >= group_limit) {
    *error = what + ": group " + std::to_string(*group) + " out of range (" +
             std::to_string(group_limit) + " groups)";
    return false;
  }
  if (data.size() * 4 > std::min(record_data, kSbtRecordDataBytes)) {
    *error = what + ": " + std::to_string(data.size()) + " data words (at most " +
             std::to_string(std::min(record_data, kSbtRecordDataBytes) / 4) + ")";
    return false;
  }
  uint64_t src = static_cast<uint64_t>(group_base + *group) * limits.handle_size;
  if (src + limits.handle_size > handles.size()) {
    *error = what + ": handle array too short";
    return false;
  }
  std::memcpy(out->data() + at, handles.data() + src, limits.handle_size);
  if (!data.empty())
    std::memcpy(out->data() + at + limits.handle_size, data.data(), data.size() * 4);
  return true;
}

bool writeRegion(const SbtLimits& limits, uint32_t record_data, const SbtRegion& region,
                 const std::vector<SbtRecord>& records, uint32_t group_base, uint32_t group_limit,
                 const std::vector<uint8_t>& handles, std::vector<uint8_t>* out, const char* name,
                 std::string* error) {
  for (size_t i = 0; i < records.size(); ++i) {
    std::string what = std::string("sbt ") + name + " record " + std::to_string(i);
    if (!writeRecord(limits, record_data, region.offset + i * region.stride, records[i].group,
                     group_base, group_limit, records[i].data, handles, out, what, error))
      return false;
  }
  return true;
}

}  // namespace

uint32_t sbtGroupCount(const Pipeline& p) {
  return static_cast<uint32_t>(1 + p.miss.size() + p.hit_groups.size() + p.callables.size());
}
uint32_t sbtMissGroup(const Pipeline&, uint32_t i) {
  return 1 + i;
}
uint32_t sbtHitGroup(const Pipeline& p, uint32_t i) {
  return static_cast<uint32_t>(1 + p.miss.size() + i);
}
uint32_t sbtCallableGroup(const Pipeline& p, uint32_t i) {
  return static_cast<uint32_t>(1 + p.miss.size() + p.hit_groups.size() + i);
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

bool checkSbtLayout(const SbtLayout& layout, const SbtLimits& limits, std::string* error) {
  struct Named {
    const char* name;
    const SbtRegion* region;
  };
  const Named regions[] = {{"raygen", &layout.raygen},
                           {"miss", &layout.miss},
                           {"hit", &layout.hit},
                           {"callable", &layout.callable}};
  for (const Named& n : regions) {
    const SbtRegion& r = *n.region;
    std::string name = std::string("sbt ") + n.name + " region";
    if (r.size == 0) continue;
    if (r.offset % limits.base_alignment) {
      *error = name + ": offset " + std::to_string(r.offset) +
               " not a multiple of shaderGroupBaseAlignment";
      return false;
    }
    if (r.stride % limits.handle_alignment) {
      *error = name + ": stride " + std::to_string(r.stride) +
               " not a multiple of shaderGroupHandleAlignment";
      return false;
    }
    if (r.stride > limits.max_stride) {
      *error = name + ": stride " + std::to_string(r.stride) + " > maxShaderGroupStride " +
               std::to_string(limits.max_stride);
      return false;
    }
    if (r.stride < limits.handle_size) {
      *error = name + ": stride smaller than the handle";
      return false;
    }
    if (r.offset + r.size > layout.total_size) {
      *error = name + ": past the end of the table";
      return false;
    }
  }
  if (layout.raygen.size != layout.raygen.stride) {
    *error = "sbt raygen region: size != stride";
    return false;
  }
  return true;
}

bool writeSbt(const SbtLayout& layout, const SbtLimits& limits, const Pipeline& p,
              const std::vector<uint8_t>& handles, std::vector<uint8_t>* out, std::string* error) {
  out->assign(layout.total_size, 0);
  std::string ignored;
  if (!error) error = &ignored;
  SbtRecord raygen;
  raygen.group = 0;
  raygen.data = p.raygen_data;
  const uint64_t need = static_cast<uint64_t>(sbtGroupCount(p)) * limits.handle_size;
  if (handles.size() < need) {
    *error =
        "sbt: " + std::to_string(handles.size()) + " handle bytes, need " + std::to_string(need);
    return false;
  }
  const uint32_t k = p.sbt_record_data;
  return writeRegion(limits, k, layout.raygen, {raygen}, 0, 1, handles, out, "raygen", error) &&
         writeRegion(limits, k, layout.miss, sbtMissRecords(p), sbtMissGroup(p, 0),
                     static_cast<uint32_t>(p.miss.size()), handles, out, "miss", error) &&
         writeRegion(limits, k, layout.hit, sbtHitRecords(p), sbtHitGroup(p, 0),
                     static_cast<uint32_t>(p.hit_groups.size()), handles, out, "hit", error) &&
         writeRegion(limits, k, layout.callable, sbtCallableRecords(p), sbtCallableGroup(p, 0),
                     static_cast<uint32_t>(p.callables.size()), handles, out, "callable", error);
}

}  // namespace rayspec
