// The shader binding table's record shape (pipeline.sbt.record_data and
// padding): the strides computeSbtLayout derives from it with the numbers of
// lavapipe, of an NVIDIA-like device and of a device with 64-byte handles,
// the bytes writeSbt lays out, and on the device: the largest stride the
// device allows runs cleanly, one step more is NotSupported (never a crash or
// a validation error).
#include <gtest/gtest.h>

#include "sbt_support.h"

#include <cstring>

#include "parse/parse_case.h"
#include "plan/plan.h"
#include "result_support.h"
#include "results/record_layout.h"
#include "vulkan/sbt_layout.h"
#include "vulkan/vulkan_engine.h"
#include "vulkan_support.h"

namespace rayspec {
namespace {
using sbt_test::allBytes;
using sbt_test::fakeHandles;
using sbt_test::wordAt;

// handle size, handle alignment, base alignment, maxShaderGroupStride
SbtLimits lavapipe() {
  return {32, 16, 32, 16384};
}
SbtLimits nvidiaLike() {
  return {32, 32, 64, 4096};
}
SbtLimits wideHandles() {
  return {64, 64, 64, 4096};
}

Pipeline shaped(uint32_t record_data, SbtPadding padding, size_t miss = 2, size_t hit = 3,
                size_t callables = 2) {
  Pipeline p;
  p.miss.resize(miss);
  p.hit_groups.resize(hit);
  p.callables.resize(callables);
  p.sbt_record_data = record_data;
  p.sbt_padding = padding;
  return p;
}

SbtPadding all(uint32_t p) {
  return {p, p, p};
}

// Handle bytes of group g: every byte 0x10 + g.
TEST(SbtStride, DefaultShapeKeepsTheOldStride) {
  Pipeline p;
  EXPECT_EQ(p.sbt_record_data, 32u);
  EXPECT_EQ(p.sbt_padding.miss + p.sbt_padding.hit + p.sbt_padding.callable, 0u);
  EXPECT_EQ(computeSbtLayout(lavapipe(), shaped(32, all(0))).hit.stride, 64u);
}

// The strides of sbt/record-stride (record_data x padding) on three devices.
TEST(SbtStride, RecordDataAndPaddingSetTheStride) {
  struct Row {
    uint32_t k, pad;
    uint64_t lavapipe, nvidia, wide;
  };
  const Row rows[] = {
      {0, 0, 32, 32, 64},   // exactly the handle size
      {4, 0, 48, 64, 128},  // 36 -> the handle alignment
      {16, 0, 48, 64, 128},         {32, 0, 64, 64, 128},        {0, 32, 64, 64, 128},
      {4, 32, 80, 96, 128},         {16, 32, 80, 96, 128},       {32, 32, 96, 96, 128},
      {0, 4000, 4032, 4032, 4096},  {4, 4000, 4048, 4064, 4096}, {16, 4000, 4048, 4064, 4096},
      {32, 4000, 4064, 4064, 4096},  // 64-byte handles: exactly 4096, still allowed
  };
  for (const Row& r : rows) {
    const Pipeline p = shaped(r.k, all(r.pad));
    for (auto [limits, want] :
         {std::pair{lavapipe(), r.lavapipe}, std::pair{nvidiaLike(), r.nvidia},
          std::pair{wideHandles(), r.wide}}) {
      SCOPED_TRACE("record_data " + std::to_string(r.k) + " padding " + std::to_string(r.pad) +
                   " handle " + std::to_string(limits.handle_size) + "/" +
                   std::to_string(limits.handle_alignment));
      const SbtLayout l = computeSbtLayout(limits, p);
      EXPECT_EQ(sbtStride(limits, r.k, r.pad), want);
      EXPECT_EQ(l.miss.stride, want);
      EXPECT_EQ(l.hit.stride, want);
      EXPECT_EQ(l.callable.stride, want);
      EXPECT_EQ(l.hit.size, 3 * want);
      // The raygen region is one record without padding: its stride is its size.
      EXPECT_EQ(l.raygen.stride, sbtStride(limits, r.k, 0));
      EXPECT_EQ(l.raygen.size, l.raygen.stride);
      for (const SbtRegion* region : {&l.miss, &l.hit, &l.callable})
        EXPECT_EQ(region->offset % limits.base_alignment, 0u);
      EXPECT_EQ(l.total_size, l.callable.offset + l.callable.size);
      std::string error;
      EXPECT_TRUE(orError(checkSbtLayout(l, limits), &error)) << error;
    }
  }
}

TEST(SbtStride, EachRegionHasItsOwnPadding) {
  const SbtLimits lim = lavapipe();
  const SbtLayout l = computeSbtLayout(lim, shaped(8, {4000, 0, 32}));
  EXPECT_EQ(l.raygen.stride, 48u);
  EXPECT_EQ(l.miss.stride, 4048u);
  EXPECT_EQ(l.hit.stride, 48u);
  EXPECT_EQ(l.callable.stride, 80u);
  EXPECT_EQ(l.miss.offset, 64u);             // after the 48-byte raygen record, base-aligned
  EXPECT_EQ(l.hit.offset, 64u + 2 * 4048u);  // 8160: a multiple of 32
  EXPECT_EQ(l.callable.offset, 8320u);       // 8160 + 3 * 48 = 8304, base-aligned
  std::string error;
  EXPECT_TRUE(orError(checkSbtLayout(l, lim), &error)) << error;
}

TEST(SbtStride, AStrideAboveMaxShaderGroupStrideIsRefusedNamingTheRegion) {
  std::string error;
  // 32 + 32 + 4033 = 4097 -> 4128 on an NVIDIA-like device: the hit region alone.
  SbtLayout l = computeSbtLayout(nvidiaLike(), shaped(32, {0, 4033, 0}));
  EXPECT_FALSE(orError(checkSbtLayout(l, nvidiaLike()), &error));
  EXPECT_NE(error.find("sbt hit region: stride 4128 > maxShaderGroupStride 4096"),
            std::string::npos)
      << error;
  // The same case fits lavapipe's 16384.
  EXPECT_TRUE(orError(
      checkSbtLayout(computeSbtLayout(lavapipe(), shaped(32, {0, 4033, 0})), lavapipe()), &error))
      << error;
  // Exactly maxShaderGroupStride is allowed; one alignment step more is not.
  l = computeSbtLayout(lavapipe(), shaped(0, {16384 - 32, 0, 0}));
  EXPECT_EQ(l.miss.stride, 16384u);
  EXPECT_TRUE(orError(checkSbtLayout(l, lavapipe()), &error)) << error;
  l = computeSbtLayout(lavapipe(), shaped(0, {16384 - 31, 0, 0}));
  EXPECT_EQ(l.miss.stride, 16400u);
  EXPECT_FALSE(orError(checkSbtLayout(l, lavapipe()), &error));
  EXPECT_NE(error.find("sbt miss region"), std::string::npos) << error;
  // An empty region's padding does not matter (its stride is 0).
  l = computeSbtLayout(nvidiaLike(), shaped(32, {0, 0, 60000}, 1, 1, 0));
  EXPECT_EQ(l.callable.stride, 0u);
  EXPECT_TRUE(orError(checkSbtLayout(l, nvidiaLike()), &error)) << error;
}

TEST(SbtStride, RecordsLieAtTheirStrideWithZeroPadding) {
  const SbtLimits lim = lavapipe();
  Pipeline p = shaped(8, {32, 4000, 0}, 2, 2, 1);
  p.raygen_data = {0xAAAA0001u, 0xAAAA0002u};
  p.sbt_miss = {{1, {11, 12}}, {0, {21}}};
  p.sbt_hit = {{1, {31, 32}}, {std::nullopt, {}}, {0, {51, 52}}};
  p.sbt_callable = {{0, {61, 62}}};
  const SbtLayout l = computeSbtLayout(lim, p);
  ASSERT_EQ(l.miss.stride, 80u);
  ASSERT_EQ(l.hit.stride, 4048u);
  std::vector<uint8_t> bytes;
  std::string error;
  error.clear();
  bytes = orError(writeSbt(l, lim, p, fakeHandles(p, lim)), &error);
  ASSERT_EQ(error, "");
  // raygen: handle 0x10, its two words right after it
  EXPECT_EQ(bytes[0], 0x10);
  EXPECT_EQ(wordAt(bytes, 32), 0xAAAA0001u);
  EXPECT_EQ(wordAt(bytes, 36), 0xAAAA0002u);
  // miss record 1 at offset + 80: miss 0 -> group 1
  EXPECT_EQ(bytes[l.miss.offset], 0x12);
  EXPECT_EQ(wordAt(bytes, l.miss.offset + 32), 11u);
  EXPECT_EQ(bytes[l.miss.offset + 80], 0x11);
  EXPECT_EQ(wordAt(bytes, l.miss.offset + 80 + 32), 21u);
  EXPECT_EQ(wordAt(bytes, l.miss.offset + 80 + 36), 0u);
  // hit record 2 at offset + 2 * 4048, the padding between all zero
  EXPECT_EQ(bytes[l.hit.offset], 0x14);
  EXPECT_EQ(bytes[l.hit.offset + 2 * 4048], 0x13);
  EXPECT_EQ(wordAt(bytes, l.hit.offset + 2 * 4048 + 36), 52u);
  for (uint64_t at = l.hit.offset + 40; at < l.hit.offset + 2 * 4048; ++at)
    ASSERT_EQ(bytes[at], 0) << at;
  EXPECT_EQ(bytes[l.callable.offset], 0x15);
  EXPECT_EQ(wordAt(bytes, l.callable.offset + 36), 62u);
}

TEST(SbtStride, DataPastTheRecordDataBytesIsAnError) {
  const SbtLimits lim = lavapipe();
  Pipeline p = shaped(4, all(0), 1, 1, 0);
  p.sbt_hit = {{0, {1, 2}}};  // 8 bytes of data, 4 bytes per record
  std::vector<uint8_t> bytes;
  std::string error;
  error.clear();
  bytes = orError(writeSbt(computeSbtLayout(lim, p), lim, p, fakeHandles(p, lim)), &error);
  EXPECT_NE(error, "");
  EXPECT_NE(error.find("sbt hit record 0: 2 data words (at most 1)"), std::string::npos) << error;
  p.sbt_hit = {{0, {1}}};
  p.raygen_data = {1, 2};
  error.clear();
  bytes = orError(writeSbt(computeSbtLayout(lim, p), lim, p, fakeHandles(p, lim)), &error);
  EXPECT_NE(error, "");
  EXPECT_NE(error.find("sbt raygen record 0"), std::string::npos) << error;
}

// ------------------------------------------------------------- on the device

// One triangle (hit record 1 through instance SBT offset 1) and one ray
// beside it; closest-hit and miss record their record's first word.
std::string strideCase(uint32_t padding) {
  return R"(rules: [R-SBT-HIT]
scene:
  blas:
    tri: [{triangles: {vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]}, flags: [opaque]}]
  instances: [{blas: tri, sbt_offset: 1}]
rays:
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
    - {origin: [5, 0, 1], direction: [0, 0, -1], miss: 1}
pipeline:
  miss: [[record: {value: {add: [500, {shader_record_uint: 0}]}}]]
  hit_groups: [{closest_hit: [record: {value: {add: [100, {shader_record_uint: 0}]}}]}]
  sbt:
    record_data: 4
    padding: )" +
         std::to_string(padding) + R"(
    miss: [{group: 0, data: {uints: [1]}}, {group: 0, data: {uints: [2]}}]
    hit: [{group: 0, data: {uints: [3]}}, {group: 0, data: {uints: [4]}}]
outputs:
  per_ray: [value]
)";
}

TEST(SbtStrideDevice, TheLargestStrideRunsAndOneStepMoreIsNotSupported) {
  if (!rayTracingDeviceExists()) GTEST_SKIP() << "no ray tracing device";
  std::string error;
  auto backend = orError(VulkanEngine::create(VulkanOptions{}), &error);
  ASSERT_TRUE(backend) << error;
  const DeviceInfo& d = backend->device();
  const uint32_t largest =
      d.max_shader_group_stride - d.shader_group_handle_size - 4;  // stride == max
  const uint32_t beyond = largest + d.shader_group_handle_alignment;
  if (beyond > kMaxSbtPaddingBytes)
    GTEST_SKIP() << "maxShaderGroupStride beyond what a case can ask";
  for (uint32_t padding : {0u, largest, beyond}) {
    SCOPED_TRACE("padding " + std::to_string(padding));
    ParseResult parsed = parseCaseText(strideCase(padding), "stride.yaml", "sbt/stride");
    ASSERT_TRUE(parsed.value) << (parsed.errors.empty() ? "?" : parsed.errors[0].format());
    const Case& c = *parsed.value;
    Results r = backend->run(c, derivePlan(c));
    EXPECT_TRUE(r.validation_messages.empty()) << r.validation_messages.front();
    if (padding == beyond) {
      EXPECT_EQ(r.status, SideStatus::NotSupported) << r.statusText();
      EXPECT_NE(r.status_detail.find("maxShaderGroupStride"), std::string::npos) << r.status_detail;
      const std::string shape =
          "record_data 4 + pipeline.sbt.padding: miss " + std::to_string(beyond);
      EXPECT_NE(r.status_detail.find(shape), std::string::npos) << r.status_detail;
      continue;
    }
    ASSERT_EQ(r.statusText(), "ok");
    const RecordField* value = findRecordField("value");
    EXPECT_EQ(r.records.at(0 * recordWords() + value->offset), 104u);  // hit record 1
    EXPECT_EQ(r.records.at(1 * recordWords() + value->offset), 502u);  // miss record 1
  }
  EXPECT_TRUE(backend->close().empty());
}

}  // namespace
}  // namespace rayspec
