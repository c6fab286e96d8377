// case/huge_rays.h: the one definition of a huge ray at a sphere-testing box
// (the portability check refuses such a case, the fuzz generator draws none).
#include <gtest/gtest.h>

#include "case/huge_rays.h"
#include "parse_support.h"

namespace rayspec {
namespace {

// Two boxes of one instance (scaled by 1.5) whose hit group tests their
// spheres, and `ray`.
std::string boxesCase(const std::string& ray, const std::string& pipeline = "") {
  return "rules: [R-PREC]\n"
         "scene:\n"
         "  blas:\n"
         "    boxes: [{aabbs: [[-1, -1, -1, 1, 1, 1], [2, -1, -1, 3, 1, 1]], flags: [opaque]}]\n"
         "  instances: [{blas: boxes, mask: 1, transform: {scale: [1.5, 1.5, 1.5]}}]\n"
         "rays:\n"
         "  list: [" +
         ray +
         "]\n"
         "  tmax: 100\n"
         "pipeline:\n" +
         (pipeline.empty()
              ? "  hit_groups:\n"
                "    - intersection: [{if: {and: [sphere_hit, {ge: [sphere_far, ray_tmin]}]}, "
                "then: [{report: {t: {max: [sphere_near, ray_tmin]}, kind: 7}}]}]\n"
                "      closest_hit: [{record: [hit]}]\n"
              : pipeline) +
         "outputs:\n"
         "  per_ray: [hit]\n";
}

std::optional<HugeSphereRay> hugeOf(const std::string& text) {
  const ParseResult p = parse(text);
  EXPECT_TRUE(p.value) << allErrors(p);
  return p.value ? hugeRayAtSphereBox(*p.value) : std::nullopt;
}

const std::string kFar = "{origin: [-2e5, 0.5, 2e5], direction: [2e5, 0, -2e5]";

TEST(HugeRays, AFarRayAtASphereTestingBoxIsHuge) {
  const std::optional<HugeSphereRay> h = hugeOf(boxesCase(kFar + "}"));
  ASSERT_TRUE(h);
  EXPECT_EQ(h->ray, 0u);
  EXPECT_EQ(h->instance, 0u);
  EXPECT_EQ(h->primitive, 0u);
  EXPECT_EQ(h->hit_group, std::optional<size_t>(0));
  EXPECT_GT(h->distance, 1.8e5);  // object space: (2e5, 2e5) / 1.5 from box 0
}

TEST(HugeRays, NearRaysAndRaysThatMeetNoSphereTestAreNot) {
  // Near: 5 away.
  EXPECT_FALSE(hugeOf(boxesCase("{origin: [-3.5, 0.5, 3.5], direction: [1, 0, -1]}")));
  // Far, but skipping boxes, masked off, ending before the boxes, or
  // missing them by more than their extent.
  EXPECT_FALSE(hugeOf(boxesCase(kFar + ", flags: [skip_aabbs]}")));
  EXPECT_FALSE(hugeOf(boxesCase(kFar + ", cull_mask: 2}")));
  EXPECT_FALSE(hugeOf(boxesCase(kFar + ", tmax: 0.9}")));
  EXPECT_FALSE(hugeOf(boxesCase("{origin: [-2e5, 50, 2e5], direction: [2e5, 0, -2e5]}")));
  // Far at boxes whose program reports without a sphere test.
  EXPECT_FALSE(hugeOf(boxesCase(kFar + "}",
                                "  hit_groups:\n"
                                "    - intersection: [{report: {t: 1.0, kind: 7}}]\n"
                                "      closest_hit: [{record: [hit]}]\n")));
}

TEST(HugeRays, ARayQuerysSphereTestCountsToo) {
  const std::optional<HugeSphereRay> h =
      hugeOf(boxesCase(kFar + "}",
                       "  raygen:\n"
                       "    - ray_query:\n"
                       "        aabb: [{if: sphere_hit, then: [{generate: sphere_near}]}]\n"
                       "        after: [{record: {hit: committed.type}}]\n"));
  ASSERT_TRUE(h);
  EXPECT_FALSE(h->hit_group);
}

}  // namespace
}  // namespace rayspec
