// The model's per-run set-up and its worker threads (model_engine.cpp):
// chunks of launch rays (256 to 4096, the last one partial) cover every ray
// exactly once whatever the thread count, images are written per chunk, and
// the SBT reach that decides whether a fast run needs every candidate still
// reads the rays when their offsets could matter.
#include <gtest/gtest.h>

#include <bit>

#include "model_support.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

using namespace model_test;

// w x h rays over an 8x8 opaque grid, some beyond it (misses).
Case wideLaunch(uint32_t w, uint32_t h) {
  std::vector<Ray> rays;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      rays.push_back(downRay(-1.3f + 2.6f * (x + 0.5f) / w, -1.3f + 2.6f * (y + 0.5f) / h));
  return baseCase({grid(8, kGeometryOpaque)}, rays, w);
}

// Every ray runs raygen once and exactly one of closest-hit and miss; the
// records and counters equal the single-threaded run's, on the direct path
// (raygen `trace: {}`) and on the general one. 512 x 261 rays: one thread
// takes 4096-ray chunks (the cap) and a partial last one, seven take 596.
TEST(ModelThreads, ChunksCoverEveryRayOnce) {
  const uint32_t w = 512, h = 261, n = w * h;
  Case direct = wideLaunch(w, h);
  Case general = direct;
  general.pipeline.raygen = {traceStmt(), count("near_accepted")};
  for (Case* c : {&direct, &general}) {
    const Results one = run(*c, ModelTier::Fast, 1);
    ASSERT_EQ(one.statusText(), "ok");
    EXPECT_GT(one.counters.at("miss"), 0u);
    EXPECT_GT(one.counters.at("closesthit"), 0u);
    EXPECT_EQ(one.counters.at("miss") + one.counters.at("closesthit"), n);
    for (uint32_t i = 0; i < n; ++i) {
      ASSERT_EQ(word(one, i, "raygen_runs"), 1u) << i;
      ASSERT_EQ(word(one, i, "closest_hit_runs") + word(one, i, "miss_runs"), 1u) << i;
    }
    for (unsigned threads : {2u, 3u, 7u, 16u}) {
      const Results r = run(*c, ModelTier::Fast, threads);
      ASSERT_EQ(r.statusText(), "ok");
      EXPECT_EQ(r.counters, one.counters) << threads;
      EXPECT_TRUE(r.records == one.records) << threads;
    }
  }
}

// Images are written by the workers, chunk by chunk, from their rays'
// records: every texel of a uint image (primitive_id) and of an rgba32f one
// (hit_t in red, 0 in green and blue, 1 in alpha) follows the ray's record,
// and the images are the same for 1 and 7 threads.
TEST(ModelThreads, ImagesWrittenPerChunkFollowTheRecords) {
  const uint32_t w = 512, h = 261, n = w * h;
  Case c = wideLaunch(w, h);
  c.outputs.images = {{"prim", "primitive_id", {}}, {"t", "hit_t", {}}};
  const Results one = run(c, ModelTier::Fast, 1), seven = run(c, ModelTier::Fast, 7);
  ASSERT_EQ(one.statusText(), "ok");
  ASSERT_EQ(one.images.size(), 2u);
  ASSERT_EQ(one.images[0].texels.size(), size_t{n});
  ASSERT_EQ(one.images[1].texels.size(), size_t{n} * 4);
  const uint32_t one_bits = std::bit_cast<uint32_t>(1.0f);
  for (uint32_t i = 0; i < n; ++i) {
    ASSERT_EQ(one.images[0].texels[i], word(one, i, "primitive_id")) << i;
    ASSERT_EQ(one.images[1].texels[i * 4], word(one, i, "hit_t")) << i;
    ASSERT_EQ(one.images[1].texels[i * 4 + 1], 0u) << i;
    ASSERT_EQ(one.images[1].texels[i * 4 + 2], 0u) << i;
    ASSERT_EQ(one.images[1].texels[i * 4 + 3], one_bits) << i;
  }
  ASSERT_EQ(seven.images.size(), 2u);
  for (size_t k = 0; k < 2; ++k) EXPECT_TRUE(seven.images[k].texels == one.images[k].texels) << k;
}

// An opaque quad (geometry 0) in front of a non-opaque one (geometry 1), two
// hit records: a ray with SBT offset 1 needs record 2 for the non-opaque
// triangle behind, which a device may read (R-UB) although the closest hit
// is the opaque one. Only the last of 2000 rays sets that offset; one with
// offset 16 (low 4 bits 0, R-SBT-HIT) stays defined. Every tier finds it:
// the fast and robust ones must read the rays' offsets to know that they
// need every candidate.
TEST(ModelThreads, RayOffsetReachingPastTheRegionIsFoundAtTheLastRay) {
  Geometry front = quad(0, kGeometryOpaque), behind = quad(-1, 0);
  std::vector<Ray> rays(2000, downRay(0.25f, 0.3f));
  Case c = baseCase({front, behind}, rays, 100);
  c.pipeline.hit_groups.push_back(c.pipeline.hit_groups[0]);
  for (ModelTier tier : kTiers) {
    c.rays.rays.back().sbt_offset = 0;
    const Results none = run(c, tier, 3);
    ASSERT_EQ(none.statusText(), "ok");
    EXPECT_TRUE(none.undefined.empty()) << modelTierName(tier);
    EXPECT_EQ(none.counters.at("closesthit"), 2000u);
    c.rays.rays.back().sbt_offset = 16;
    EXPECT_TRUE(run(c, tier, 3).undefined.empty()) << modelTierName(tier);
    c.rays.rays.back().sbt_offset = 1;
    const Results last = run(c, tier, 3);
    ASSERT_EQ(last.undefined.size(), 1u) << modelTierName(tier);
    EXPECT_EQ(last.undefined[0].ray, 1999u);
    EXPECT_EQ(last.undefined[0].reason, UndefinedReason::HitRecordOutOfRange);
    EXPECT_EQ(word(last, 1998, "geometry_index"), 0u);  // the opaque quad in front
  }
}

}  // namespace
}  // namespace rayspec
