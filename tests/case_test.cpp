// Tests of the case IR's helpers: camera rays and transforms (the generators'
// own: case_generators_test.cpp, case_box_grid_test.cpp, case_vertex_format_test.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "case/camera_rays.h"
#include "case/transform.h"

namespace rayspec {
namespace {

TEST(CameraRays, AspectAndDegenerate) {
  CameraSpec cam;
  cam.width = 4;
  cam.height = 2;
  cam.origin = {0, 0, 0};
  cam.look_at = {0, 0, -1};
  cam.fov_degrees = 90;
  auto rays = cameraRays(cam, Ray{});
  ASSERT_EQ(rays.size(), 8u);
  // pixel (0, 0): u = -0.75 * 2 (aspect 2), v = 0.5
  const double len = std::sqrt(1.5 * 1.5 + 0.25 + 1);
  EXPECT_NEAR(rays[0].direction[0], -1.5 / len, 1e-7);
  EXPECT_NEAR(rays[0].direction[1], 0.5 / len, 1e-7);
  cam.up = {0, 0, 1};  // parallel to the view direction
  EXPECT_TRUE(cameraRays(cam, Ray{}).empty());
}

TEST(Transform, ComposeAndDeterminant) {
  TransformParts p;
  p.translate = {1, 2, 3};
  p.scale = {1, 2, 3};
  Transform t = composeTransform(p);
  EXPECT_EQ(t, (Transform{1, 0, 0, 1, 0, 2, 0, 2, 0, 0, 3, 3}));
  EXPECT_DOUBLE_EQ(linearDeterminant(t), 6);
  p.axis = {1, 0, 0};
  p.degrees = 180;
  p.scale = {1, 1, 1};
  t = composeTransform(p);
  EXPECT_NEAR(t[5], -1, 1e-7);
  EXPECT_NEAR(t[10], -1, 1e-7);
  EXPECT_NEAR(linearDeterminant(t), 1, 1e-6);
}

}  // namespace
}  // namespace rayspec
