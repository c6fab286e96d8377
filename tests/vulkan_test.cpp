// The Vulkan backend: the pure SBT layout with the numbers of lavapipe and of
// an NVIDIA-like device, and a hand-built triangle case traced on the ray
// tracing device (lavapipe here) with the validation layer on.
#include <gtest/gtest.h>

#include "sbt_support.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <map>

#include "parse/parse_case.h"
#include "plan/plan.h"
#include "result_support.h"
#include "results/record_layout.h"
#include "suite_cases.h"
#include "vulkan/case_buffers.h"
#include "vulkan/sbt_layout.h"
#include "vulkan/vk_check.h"
#include "vulkan/vulkan_engine.h"
#include "vulkan_support.h"

namespace rayspec {
namespace {
using sbt_test::allBytes;
using sbt_test::fakeHandles;
using sbt_test::wordAt;

// ---------------------------------------------------------------- SBT layout

SbtLimits lavapipeLimits() {
  return {32, 16, 32, 16384};
}
SbtLimits nvidiaLimits() {
  return {32, 32, 64, 4096};
}

Pipeline groups(size_t miss, size_t hit, size_t callables) {
  Pipeline p;
  p.miss.resize(miss);
  p.hit_groups.resize(hit);
  p.callables.resize(callables);
  return p;
}

SbtRecord rec(std::optional<uint32_t> group, std::vector<uint32_t> data = {}) {
  SbtRecord r;
  r.group = group;
  r.data = std::move(data);
  return r;
}

TEST(SbtLayout, GroupOrderIsRaygenMissHitCallable) {
  Pipeline p = groups(2, 3, 2);
  EXPECT_EQ(sbtGroupCount(p), 8u);
  EXPECT_EQ(sbtMissGroup(p, 0), 1u);
  EXPECT_EQ(sbtMissGroup(p, 1), 2u);
  EXPECT_EQ(sbtHitGroup(p, 0), 3u);
  EXPECT_EQ(sbtHitGroup(p, 2), 5u);
  EXPECT_EQ(sbtCallableGroup(p, 0), 6u);
  EXPECT_EQ(sbtCallableGroup(p, 1), 7u);
}

TEST(SbtLayout, LavapipeNumbers) {
  Pipeline p = groups(2, 3, 1);
  SbtLayout l = computeSbtLayout(lavapipeLimits(), p);
  // Record = 32-byte handle + 32 bytes of data = 64, a multiple of 16.
  EXPECT_EQ(l.raygen.offset, 0u);
  EXPECT_EQ(l.raygen.stride, 64u);
  EXPECT_EQ(l.raygen.size, l.raygen.stride);
  EXPECT_EQ(l.miss.offset, 64u);
  EXPECT_EQ(l.miss.stride, 64u);
  EXPECT_EQ(l.miss.size, 128u);
  EXPECT_EQ(l.hit.offset, 192u);
  EXPECT_EQ(l.hit.size, 192u);
  EXPECT_EQ(l.callable.offset, 384u);
  EXPECT_EQ(l.callable.size, 64u);
  EXPECT_EQ(l.total_size, 448u);
  std::string error;
  EXPECT_TRUE(orError(checkSbtLayout(l, lavapipeLimits()), &error)) << error;
}

TEST(SbtLayout, NvidiaLikeNumbersAlignRegionsTo64) {
  // 64-byte records already fall on 64-byte boundaries; a base alignment of
  // 128 (wider than the record) must push every region to the next multiple.
  Pipeline p = groups(1, 1, 1);
  SbtLayout l = computeSbtLayout(nvidiaLimits(), p);
  EXPECT_EQ(l.raygen.stride, 64u);
  EXPECT_EQ(l.raygen.size, 64u);
  EXPECT_EQ(l.miss.offset, 64u);
  EXPECT_EQ(l.hit.offset, 128u);
  EXPECT_EQ(l.callable.offset, 192u);
  EXPECT_EQ(l.total_size, 256u);
  std::string error;
  EXPECT_TRUE(orError(checkSbtLayout(l, nvidiaLimits()), &error)) << error;

  SbtLimits wide = nvidiaLimits();
  wide.base_alignment = 128;
  SbtLayout w = computeSbtLayout(wide, p);
  EXPECT_EQ(w.miss.offset, 128u);
  EXPECT_EQ(w.hit.offset, 256u);
  EXPECT_EQ(w.callable.offset, 384u);
  EXPECT_TRUE(orError(checkSbtLayout(w, wide), &error)) << error;
}

TEST(SbtLayout, StrideRoundsUpToHandleAlignment) {
  SbtLimits odd{40, 16, 64, 4096};  // hypothetical 40-byte handles
  SbtLayout l = computeSbtLayout(odd, groups(1, 2, 0));
  EXPECT_EQ(l.raygen.stride, 80u);  // 40 + 32 = 72 -> 80
  EXPECT_EQ(l.hit.stride, 80u);
  EXPECT_EQ(l.miss.offset, 128u);
  EXPECT_EQ(l.hit.offset, 256u);
  EXPECT_EQ(l.callable.size, 0u);
  std::string error;
  EXPECT_TRUE(orError(checkSbtLayout(l, odd), &error)) << error;
}

TEST(SbtLayout, EmptyRegionsAreAllZero) {
  SbtLayout l = computeSbtLayout(lavapipeLimits(), groups(0, 1, 0));
  EXPECT_EQ(l.miss.size, 0u);
  EXPECT_EQ(l.miss.stride, 0u);
  EXPECT_EQ(l.miss.offset, 0u);
  EXPECT_EQ(l.callable.size, 0u);
  EXPECT_EQ(l.hit.offset, 64u);
  EXPECT_EQ(l.hit.count, 1u);
}

TEST(SbtLayout, StrideAboveMaxShaderGroupStrideIsRejected) {
  SbtLimits tight = lavapipeLimits();
  tight.max_stride = 32;
  SbtLayout l = computeSbtLayout(tight, groups(1, 1, 0));
  std::string error;
  EXPECT_FALSE(orError(checkSbtLayout(l, tight), &error));
  EXPECT_NE(error.find("maxShaderGroupStride"), std::string::npos) << error;
  for (const SbtLimits& real : {lavapipeLimits(), nvidiaLimits()}) {
    SbtLayout ok = computeSbtLayout(real, groups(3, 4, 2));
    for (const SbtRegion* r : {&ok.raygen, &ok.miss, &ok.hit, &ok.callable})
      EXPECT_LE(r->stride, real.max_stride);
    EXPECT_TRUE(orError(checkSbtLayout(ok, real), &error)) << error;
  }
}

TEST(SbtLayout, MisalignedRegionIsRejected) {
  SbtLayout l = computeSbtLayout(lavapipeLimits(), groups(1, 1, 0));
  l.hit.offset += 16;
  l.total_size += 16;
  std::string error;
  EXPECT_FALSE(orError(checkSbtLayout(l, lavapipeLimits()), &error));
  EXPECT_NE(error.find("shaderGroupBaseAlignment"), std::string::npos) << error;
}

TEST(SbtLayout, DefaultRecordsAreOnePerGroupInOrder) {
  Pipeline p = groups(2, 2, 1);
  SbtLimits lim = lavapipeLimits();
  SbtLayout l = computeSbtLayout(lim, p);
  std::vector<uint8_t> bytes;
  std::string error;
  error.clear();
  bytes = orError(writeSbt(l, lim, p, fakeHandles(p, lim)), &error);
  ASSERT_EQ(error, "");
  ASSERT_EQ(bytes.size(), l.total_size);
  EXPECT_TRUE(allBytes(bytes, 0, 32, 0x10));                   // raygen group 0
  EXPECT_TRUE(allBytes(bytes, 32, 32, 0));                     // its data
  EXPECT_TRUE(allBytes(bytes, l.miss.offset, 32, 0x11));       // miss 0 -> group 1
  EXPECT_TRUE(allBytes(bytes, l.miss.offset + 64, 32, 0x12));  // miss 1 -> group 2
  EXPECT_TRUE(allBytes(bytes, l.hit.offset, 32, 0x13));        // hit 0 -> group 3
  EXPECT_TRUE(allBytes(bytes, l.hit.offset + 64, 32, 0x14));   // hit 1 -> group 4
  EXPECT_TRUE(allBytes(bytes, l.callable.offset, 32, 0x15));   // callable 0 -> group 5
}

TEST(SbtLayout, ZeroRecordsAndRecordData) {
  Pipeline p = groups(1, 2, 1);
  p.raygen_data = {0xAAAA0001u, 0xAAAA0002u};
  p.sbt_miss = {rec(0), rec(std::nullopt)};
  p.sbt_hit = {rec(1, {7, 8, 9}), rec(std::nullopt), rec(0, {1, 2, 3, 4, 5, 6, 7, 0xFFFFFFFFu})};
  p.sbt_callable = {rec(std::nullopt), rec(0, {42})};
  for (const SbtLimits& lim : {lavapipeLimits(), nvidiaLimits()}) {
    SbtLayout l = computeSbtLayout(lim, p);
    EXPECT_EQ(l.miss.count, 2u);
    EXPECT_EQ(l.hit.count, 3u);
    EXPECT_EQ(l.callable.count, 2u);
    std::vector<uint8_t> bytes;
    std::string error;
    error.clear();
    bytes = orError(writeSbt(l, lim, p, fakeHandles(p, lim)), &error);
    ASSERT_EQ(error, "");
    const uint64_t s = l.hit.stride;
    // raygen data right after the handle
    EXPECT_EQ(wordAt(bytes, lim.handle_size), 0xAAAA0001u);
    EXPECT_EQ(wordAt(bytes, lim.handle_size + 4), 0xAAAA0002u);
    // miss: record 1 all zero (handle and data)
    EXPECT_TRUE(allBytes(bytes, l.miss.offset, lim.handle_size, 0x11));
    EXPECT_TRUE(allBytes(bytes, l.miss.offset + s, s, 0));
    // hit 0: group 1 -> pipeline group 3, data 7 8 9 then zeros
    EXPECT_TRUE(allBytes(bytes, l.hit.offset, lim.handle_size, 0x13));
    EXPECT_EQ(wordAt(bytes, l.hit.offset + lim.handle_size), 7u);
    EXPECT_EQ(wordAt(bytes, l.hit.offset + lim.handle_size + 4), 8u);
    EXPECT_EQ(wordAt(bytes, l.hit.offset + lim.handle_size + 8), 9u);
    EXPECT_TRUE(allBytes(bytes, l.hit.offset + lim.handle_size + 12, s - lim.handle_size - 12, 0));
    // hit 1: all zero
    EXPECT_TRUE(allBytes(bytes, l.hit.offset + s, s, 0));
    // hit 2: group 0 -> pipeline group 2, all 8 data words
    EXPECT_TRUE(allBytes(bytes, l.hit.offset + 2 * s, lim.handle_size, 0x12));
    EXPECT_EQ(wordAt(bytes, l.hit.offset + 2 * s + lim.handle_size + 28), 0xFFFFFFFFu);
    // callables: zero, then group 0 -> pipeline group 4 with 42
    EXPECT_TRUE(allBytes(bytes, l.callable.offset, s, 0));
    EXPECT_TRUE(allBytes(bytes, l.callable.offset + s, lim.handle_size, 0x14));
    EXPECT_EQ(wordAt(bytes, l.callable.offset + s + lim.handle_size), 42u);
    // gaps between regions stay zero
    EXPECT_TRUE(allBytes(bytes, l.miss.offset + l.miss.size,
                         l.hit.offset - l.miss.offset - l.miss.size, 0));
  }
}

TEST(SbtLayout, BadRecordsAreErrors) {
  SbtLimits lim = lavapipeLimits();
  Pipeline p = groups(1, 1, 0);
  p.sbt_hit = {rec(1)};  // only hit group 0 exists
  std::vector<uint8_t> bytes;
  std::string error;
  error.clear();
  bytes = orError(writeSbt(computeSbtLayout(lim, p), lim, p, fakeHandles(p, lim)), &error);
  EXPECT_NE(error, "");
  EXPECT_NE(error.find("out of range"), std::string::npos) << error;

  p.sbt_hit = {rec(0, std::vector<uint32_t>(9, 1))};  // 9 data words
  error.clear();
  bytes = orError(writeSbt(computeSbtLayout(lim, p), lim, p, fakeHandles(p, lim)), &error);
  EXPECT_NE(error, "");
  EXPECT_NE(error.find("data words"), std::string::npos) << error;

  p.sbt_hit = {rec(0)};
  std::vector<uint8_t> short_handles(lim.handle_size);  // one handle for three groups
  error.clear();
  bytes = orError(writeSbt(computeSbtLayout(lim, p), lim, p, short_handles), &error);
  EXPECT_NE(error, "");
}

// ------------------------------------------------------------- on the device

Expr builtin(const std::string& name, ValueType t) {
  Expr e = builtinExpr(name);
  e.type = t;
  return e;
}
Expr uintLit(uint32_t v) {
  Expr e;
  e.kind = Expr::Kind::Literal;
  e.type = ValueType::Uint;
  e.literal = {double(v)};
  return e;
}
Stmt countStmt(const std::string& n) {
  Stmt s;
  s.kind = Stmt::Kind::Count;
  s.counter = n;
  return s;
}
Stmt recordStmt(std::vector<std::pair<std::string, Expr>> a) {
  Stmt s;
  s.kind = Stmt::Kind::Record;
  s.assigns = std::move(a);
  return s;
}

Ray downRay(float x, float y) {
  Ray r;
  r.origin = {x, y, 1};
  r.direction = {0, 0, -1};
  r.tmin = 0.001f;
  r.tmax = 10.0f;
  return r;
}

// Two triangles side by side (primitives 0 and 1); rays 0 and 1 aim at them,
// rays 2 and 3 pass beside them.
Case triangleCase() {
  Case c;
  c.name = "vulkan_test/two-triangles";
  c.family = "vulkan_test";
  Geometry g;
  g.vertices = {{-1, -1, 0}, {0, -1, 0}, {-0.5f, 1, 0}, {0, -1, 0}, {1, -1, 0}, {0.5f, 1, 0}};
  g.flags = kGeometryOpaque;
  Blas blas;
  blas.name = "tris";
  blas.geometries = {g};
  c.scene.blases = {blas};
  Instance inst;
  inst.blas = 0;
  c.scene.instances = {inst};
  c.rays.width = 4;
  c.rays.height = 1;
  c.rays.rays = {downRay(-0.5f, -0.5f), downRay(0.5f, -0.5f), downRay(3, 3), downRay(-3, 0)};
  c.rays.defaults = downRay(0, 0);

  Stmt trace;
  trace.kind = Stmt::Kind::Trace;
  c.pipeline.raygen = {trace};
  c.pipeline.miss = {{countStmt("miss"), recordStmt({{"hit", uintLit(0)}})}};
  HitGroup hg;
  hg.closest_hit =
      Program{countStmt("closesthit"),
              recordStmt({{"hit", uintLit(1)},
                          {"primitive_id", builtin("primitive_id", ValueType::Uint)}})};
  c.pipeline.hit_groups = {hg};
  c.outputs.counters = {"miss", "closesthit"};
  c.outputs.per_ray = {"hit", "primitive_id"};
  c.outputs.images = {{"primitive", "primitive_id", {}}};
  return c;
}

std::unique_ptr<VulkanEngine> makeBackend() {
  std::string error;
  auto backend = orError(VulkanEngine::create(VulkanOptions{}), &error);
  if (!backend) ADD_FAILURE() << "backend: " << error;
  return backend;
}

#define SKIP_WITHOUT_RT_DEVICE()                                           \
  if (!rayTracingDeviceExists())                                           \
  GTEST_SKIP() << "no Vulkan device with VK_KHR_ray_tracing_pipeline and " \
                  "VK_KHR_acceleration_structure on this machine (install Mesa >= 25 lavapipe)"

uint32_t field(const Results& r, uint32_t ray, const char* name) {
  const RecordField* f = findRecordField(name);
  return r.records.at(ray * recordWords() + f->offset);
}

TEST(VulkanDevice, ListsARayTracingDevice) {
  SKIP_WITHOUT_RT_DEVICE();
  std::string error;
  auto devices = orError(listDevices(), &error);
  ASSERT_FALSE(devices.empty()) << error;
  bool found = false;
  for (const DeviceInfo& d : devices) {
    if (!d.ray_tracing_pipeline) continue;
    found = true;
    EXPECT_GE(d.max_ray_recursion_depth, 1u) << d.name;
    EXPECT_GE(d.shader_group_handle_size, 16u) << d.name;
    EXPECT_FALSE(d.api_version.empty());
  }
  EXPECT_TRUE(found);
}

TEST(VulkanDevice, TrianglesHitAndMissWithoutValidationMessages) {
  SKIP_WITHOUT_RT_DEVICE();
  auto backend = makeBackend();
  ASSERT_TRUE(backend);
  EXPECT_TRUE(backend->validationEnabled()) << "VK_LAYER_KHRONOS_validation is installed here";
  Case c = triangleCase();
  Plan plan = derivePlan(c);
  for (int round = 0; round < 2; ++round) {  // the device is reused across cases
    Results r = backend->run(c, plan);
    ASSERT_EQ(r.statusText(), "ok");
    EXPECT_EQ(r.backend, "vulkan");
    EXPECT_EQ(r.device, backend->device().name);
    EXPECT_TRUE(r.validation_messages.empty()) << r.validation_messages.front();
    ASSERT_EQ(r.records.size(), 4u * recordWords());
    EXPECT_EQ(field(r, 0, "hit"), 1u);
    EXPECT_EQ(field(r, 0, "primitive_id"), 0u);
    EXPECT_EQ(field(r, 1, "hit"), 1u);
    EXPECT_EQ(field(r, 1, "primitive_id"), 1u);
    EXPECT_EQ(field(r, 2, "hit"), 0u);
    EXPECT_EQ(field(r, 3, "hit"), 0u);
    // The written-mask word says which fields were recorded.
    for (uint32_t ray = 0; ray < 4; ++ray)
      EXPECT_TRUE(written(&r.records[ray * recordWords()], recordFieldIndex("hit"))) << ray;
    EXPECT_EQ(r.counters["miss"], 2u);
    EXPECT_EQ(r.counters["closesthit"], 2u);
    ASSERT_EQ(r.images.size(), 1u);
    EXPECT_EQ(r.images[0].channels, 1u);
    EXPECT_FALSE(r.images[0].is_float);
    ASSERT_EQ(r.images[0].texels.size(), 4u);
    EXPECT_EQ(r.images[0].texels[1], 1u);  // primitive 1
    EXPECT_GT(r.seconds, 0.0);
  }
  std::vector<std::string> teardown = backend->close();
  EXPECT_TRUE(teardown.empty()) << teardown.front();
}

TEST(VulkanDevice, NullInstanceAndMaskedRaysMiss) {
  SKIP_WITHOUT_RT_DEVICE();
  auto backend = makeBackend();
  ASSERT_TRUE(backend);
  Case c = triangleCase();
  c.scene.instances.push_back(c.scene.instances[0]);
  c.scene.instances[0].blas.reset();  // inactive instance (reference 0)
  c.scene.instances[1].mask = 0x02;
  c.rays.rays[1].cull_mask = 0x01;  // hides instance 1 from ray 1
  c.outputs.images.clear();
  Plan plan = derivePlan(c);
  Results r = backend->run(c, plan);
  ASSERT_EQ(r.statusText(), "ok");
  EXPECT_TRUE(r.validation_messages.empty()) << r.validation_messages.front();
  EXPECT_EQ(field(r, 0, "hit"), 1u);
  EXPECT_EQ(field(r, 1, "hit"), 0u);
  EXPECT_EQ(r.counters["miss"], 3u);
  EXPECT_TRUE(r.images.empty());
  EXPECT_TRUE(backend->close().empty());
}

TEST(VulkanDevice, IndexedGeometryWithTransformAndSkipTrianglesFlag) {
  SKIP_WITHOUT_RT_DEVICE();
  auto backend = makeBackend();
  ASSERT_TRUE(backend);
  Case c = triangleCase();
  Geometry& g = c.scene.blases[0].geometries[0];
  g.vertices = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  g.indices = {0, 1, 2, 0, 2, 3};
  g.transform = Transform{1, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, 0};  // moves the quad to x = 10
  c.rays.rays = {downRay(10.5f, -0.5f), downRay(9.5f, 0.5f), downRay(0, 0), downRay(12, 0)};
  c.outputs.images.clear();
  Plan plan = derivePlan(c);
  Results r = backend->run(c, plan);
  ASSERT_EQ(r.statusText(), "ok");
  EXPECT_TRUE(r.validation_messages.empty()) << r.validation_messages.front();
  EXPECT_EQ(field(r, 0, "hit"), 1u);
  EXPECT_EQ(field(r, 0, "primitive_id"), 0u);
  EXPECT_EQ(field(r, 1, "hit"), 1u);
  EXPECT_EQ(field(r, 1, "primitive_id"), 1u);
  EXPECT_EQ(field(r, 2, "hit"), 0u);  // where the quad would be without the transform
  EXPECT_EQ(field(r, 3, "hit"), 0u);

  c.pipeline.flags = 0x1000;  // VK_PIPELINE_CREATE_RAY_TRACING_SKIP_TRIANGLES_BIT_KHR
  r = backend->run(c, derivePlan(c));
  ASSERT_EQ(r.statusText(), "ok");
  EXPECT_TRUE(r.validation_messages.empty()) << r.validation_messages.front();
  EXPECT_EQ(r.counters["miss"], 4u);
  EXPECT_EQ(r.counters["closesthit"], 0u);
  EXPECT_TRUE(backend->close().empty());
}

TEST(VulkanDevice, RecursionBeyondTheDeviceIsNotSupported) {
  SKIP_WITHOUT_RT_DEVICE();
  auto backend = makeBackend();
  ASSERT_TRUE(backend);
  Case c = triangleCase();
  c.pipeline.max_recursion = backend->device().max_ray_recursion_depth + 1;
  Results r = backend->run(c, derivePlan(c));
  EXPECT_EQ(r.status, SideStatus::NotSupported) << r.statusText();
  EXPECT_TRUE(r.records.empty());
  EXPECT_TRUE(backend->close().empty());
}

// A 1024 x 1024 launch needs 160 MiB of records, more than lavapipe's
// maxStorageBufferRange (128 MiB): the records are reached by device address,
// so the launch runs without a validation error and the last ray is recorded.
TEST(VulkanDevice, RecordsBeyondMaxStorageBufferRange) {
  SKIP_WITHOUT_RT_DEVICE();
  auto backend = makeBackend();
  ASSERT_TRUE(backend);
  Case c = triangleCase();
  c.rays.width = 1024;
  c.rays.height = 1024;
  c.rays.rays.assign(1024u * 1024u, downRay(0.5f, -0.5f));
  c.rays.rays.back() = downRay(-3, 0);  // the last ray misses
  c.outputs.images.clear();
  const uint64_t bytes = uint64_t(1024) * 1024 * recordWords() * 4;
  EXPECT_GT(bytes, uint64_t(128) << 20);
  Results r = backend->run(c, derivePlan(c));
  ASSERT_EQ(r.statusText(), "ok");
  EXPECT_TRUE(r.validation_messages.empty()) << r.validation_messages.front();
  ASSERT_EQ(r.records.size(), 1024u * 1024u * recordWords());
  EXPECT_EQ(field(r, 0, "hit"), 1u);
  EXPECT_EQ(field(r, 0, "primitive_id"), 1u);
  EXPECT_EQ(field(r, 1024u * 1024u - 2u, "hit"), 1u);
  EXPECT_EQ(field(r, 1024u * 1024u - 2u, "primitive_id"), 1u);
  EXPECT_EQ(field(r, 1024u * 1024u - 1u, "hit"), 0u);
  EXPECT_EQ(r.counters["miss"], 1u);
  EXPECT_EQ(r.counters["closesthit"], 1024u * 1024u - 1u);
  EXPECT_TRUE(backend->close().empty());
}

// Images live at the launch's extent unless the device's largest image is
// smaller; then the launch's texels fold into rows, in order.
TEST(ImageExtent, FoldsOnlyWhatTheDeviceCannotHold) {
  EXPECT_EQ(imageExtent(64, 32, 16384)->width, 64u);
  EXPECT_EQ(imageExtent(64, 32, 16384)->height, 32u);
  EXPECT_EQ(imageExtent(16384, 1, 16384)->width, 16384u);
  const ImageExtent list = *imageExtent(40000, 1, 16384);
  EXPECT_EQ(list.width, 16384u);
  EXPECT_EQ(list.height, 3u);  // 40,000 texels in rows of 16,384
  EXPECT_EQ(imageExtent(5000, 1, 4096)->height, 2u);
  const Result<ImageExtent> too_big = imageExtent(4096 * 4096 + 1, 1, 4096);
  ASSERT_FALSE(too_big);
  EXPECT_EQ(too_big.error().kind, ErrorKind::NotSupported);
}

// A ray list of 40,000 rays (beyond lavapipe's maxImageDimension2D, 16,384)
// with an image: launch i traces ray i, texel i of the image is ray i's, and
// the validation layer has nothing to say.
TEST(VulkanDevice, RayListBeyondMaxImageDimension2D) {
  SKIP_WITHOUT_RT_DEVICE();
  auto backend = makeBackend();
  ASSERT_TRUE(backend);
  Case c = triangleCase();
  const uint32_t n = 40000;
  c.rays.width = n;
  c.rays.height = 1;
  c.rays.rays.clear();
  for (uint32_t i = 0; i < n; ++i)
    c.rays.rays.push_back(i % 3 == 0   ? downRay(-0.5f, -0.5f)
                          : i % 3 == 1 ? downRay(0.5f, -0.5f)
                                       : downRay(3, 3));
  Results r = backend->run(c, derivePlan(c));
  ASSERT_EQ(r.statusText(), "ok");
  EXPECT_TRUE(r.validation_messages.empty()) << r.validation_messages.front();
  ASSERT_EQ(r.images.size(), 1u);
  EXPECT_EQ(r.images[0].width, n);
  EXPECT_EQ(r.images[0].height, 1u);
  ASSERT_EQ(r.images[0].texels.size(), n);
  uint32_t wrong = 0;
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t hit = i % 3 != 2, primitive = i % 3 == 1;
    wrong += field(r, i, "hit") != hit || (hit && field(r, i, "primitive_id") != primitive) ||
             r.images[0].texels[i] != (hit ? primitive : 0u);
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(r.counters["miss"], n / 3);
  EXPECT_TRUE(backend->close().empty());
}

// Every case of cases/ runs on one reused device: no crash, no validation
// error, records and counters of the planned sizes.
TEST(VulkanDevice, EveryCaseFileRunsCleanly) {
  SKIP_WITHOUT_RT_DEVICE();
  namespace fs = std::filesystem;
  // One case per file (a sweep's first variant): the sweeps' ctest runs run them all.
  const std::vector<CaseFile> files = suiteCases(true);
  ASSERT_FALSE(files.empty()) << "no case files in " << kSuiteCases;
  auto backend = makeBackend();
  ASSERT_TRUE(backend);
  for (const CaseFile& f : files) {
    ParseResult parsed = loadSuiteCase(f);
    if (!parsed.value) {
      ADD_FAILURE() << f.name << ": " << (parsed.errors.empty() ? "?" : parsed.errors[0].format());
      continue;
    }
    const Case& c = *parsed.value;
    Plan plan = derivePlan(c);
    Results r = backend->run(c, plan);
    EXPECT_TRUE(r.ok() || r.status == SideStatus::NotSupported) << c.name << ": " << r.statusText();
    EXPECT_TRUE(r.validation_messages.empty()) << c.name << ": " << r.validation_messages.front();
    if (!r.ok()) continue;
    if (plan.records) {
      EXPECT_EQ(r.records.size(), size_t(c.rays.width) * c.rays.height * recordWords()) << c.name;
    }
    EXPECT_EQ(r.counters.size(), plan.counters.size()) << c.name;
    EXPECT_EQ(r.images.size(), plan.images.size()) << c.name;
  }
  std::vector<std::string> teardown = backend->close();
  EXPECT_TRUE(teardown.empty()) << teardown.front();
}

TEST(VulkanDevice, UnknownDeviceFilterFails) {
  SKIP_WITHOUT_RT_DEVICE();
  VulkanOptions o;
  o.device_filter = "no-such-device-xyz";
  std::string error;
  EXPECT_FALSE(orError(VulkanEngine::create(o), &error));
  EXPECT_NE(error.find("no-such-device-xyz"), std::string::npos) << error;
}

}  // namespace
}  // namespace rayspec
