// Vertex formats (R-VERTEX-FORMAT): the positions each format stores, what
// it cannot hold, the bytes of its vertex buffer, and the parse errors of
// triangles.vertex_format and index_type at their line and field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "case/parse_case.h"
#include "case/vertex_format.h"
#include "case_support.h"

namespace rayspec {
namespace {

TEST(VertexFormat, StoredPositionsAreRoundedAsTheFormatDefines) {
  const Vec3 v{0.30001f, -0.5f, 0.25f};
  EXPECT_EQ(storedVertex(VertexFormat::Float3, v), v);
  EXPECT_EQ(storedVertex(VertexFormat::Half4, v)[0], 0.30004883f);  // 1229 / 4096
  EXPECT_EQ(storedVertex(VertexFormat::Snorm16x4, v)[0], 9830.0f / 32767.0f);
  EXPECT_EQ(storedVertex(VertexFormat::Snorm16x4, v)[1], -16384.0f / 32767.0f);
  EXPECT_EQ(storedVertex(VertexFormat::Half2, Vec3{1.0f, 2.0f, 0.0f})[2], 0.0f);
  EXPECT_EQ(storedVertex(VertexFormat::Snorm16x2, Vec3{-1.0f, 1.0f, 0.0f}),
            (Vec3{-1.0f, 1.0f, 0.0f}));
}

TEST(VertexFormat, HalfRoundsToNearestEvenThroughTheWholeRange) {
  auto half = [](float x) {
    return storedVertex(VertexFormat::Half2, Vec3{x, 0, 0})[0];
  };
  EXPECT_EQ(half(1.0f), 1.0f);
  EXPECT_EQ(half(1000.3f), 1000.5f);    // spacing 0.5 between 512 and 1024
  EXPECT_EQ(half(1000.25f), 1000.0f);   // a tie: to the even neighbour
  EXPECT_EQ(half(1000.75f), 1001.0f);   // a tie: to the even neighbour
  EXPECT_EQ(half(65504.0f), 65504.0f);  // the largest half
  EXPECT_EQ(half(-2.0f), -2.0f);
  EXPECT_EQ(half(std::ldexp(1.0f, -24)), std::ldexp(1.0f, -24));  // the smallest subnormal
  EXPECT_EQ(half(std::ldexp(1.0f, -26)), 0.0f);
  EXPECT_EQ(half(std::ldexp(3.0f, -26)), std::ldexp(1.0f, -24));
  EXPECT_TRUE(std::isnan(half(NAN)));
  EXPECT_EQ(half(0.1f), 0.0999755859375f);
}

TEST(VertexFormat, ProblemsNameWhatTheFormatCannotHold) {
  EXPECT_EQ(vertexFormatProblem(VertexFormat::Half4, Vec3{1, 2, 3}), "");
  EXPECT_NE(vertexFormatProblem(VertexFormat::Half2, Vec3{1, 2, 3}).find("z must be 0"),
            std::string::npos);
  EXPECT_NE(vertexFormatProblem(VertexFormat::Snorm16x4, Vec3{1.5f, 0, 0}).find("-1 to 1"),
            std::string::npos);
  EXPECT_NE(vertexFormatProblem(VertexFormat::Half4, Vec3{70000.0f, 0, 0}).find("65504"),
            std::string::npos);
  EXPECT_EQ(vertexFormatProblem(VertexFormat::Half4, Vec3{NAN, 0, 0}), "");
  EXPECT_NE(vertexFormatProblem(VertexFormat::Snorm16x4, Vec3{NAN, 0, 0}).find("NaN"),
            std::string::npos);
}

TEST(VertexFormat, EncodedBytesHoldTheStoredValues) {
  const std::vector<Vec3> v = {{0.5f, -1.0f, 0.25f}};
  const std::vector<uint8_t> half = encodeVertices(VertexFormat::Half4, v);
  ASSERT_EQ(half.size(), 8u);
  uint16_t w = 0;
  std::memcpy(&w, &half[6], 2);
  EXPECT_EQ(w, 0x3C00);  // 1.0 in half
  const std::vector<uint8_t> snorm = encodeVertices(VertexFormat::Snorm16x2, {{0.5f, -1.0f, 0}});
  ASSERT_EQ(snorm.size(), 4u);
  int16_t y = 0;
  std::memcpy(&y, &snorm[2], 2);
  EXPECT_EQ(y, -32767);
  EXPECT_EQ(encodeVertices(VertexFormat::Float3, v).size(), 12u);
}

ParseResult parseTriangles(const std::string& extra) {
  return parseCaseText(oneTriangleText("R-VERTEX-FORMAT", "", extra), "t.yaml", "t/t");
}

TEST(VertexFormat, ParseErrorsNameTheLineAndField) {
  struct Bad {
    std::string extra, field, message;
  } bad[] = {{"vertex_format: half3", "vertex_format", "unknown vertex format 'half3'"},
             {"vertex_format: snorm16x4, indices: [0, 1, 2], index_type: uint8", "index_type",
              "unknown index type 'uint8'"},
             {"index_type: uint16", "index_type", "uint16 needs indices"}};
  for (const Bad& b : bad) {
    const ParseResult r = parseTriangles(b.extra);
    EXPECT_FALSE(r.value) << b.extra;
    const std::string e = r.errors.empty() ? "(no error)" : r.errors[0].format();
    EXPECT_NE(e.find("t.yaml:4"), std::string::npos) << e;
    EXPECT_NE(e.find("scene.blas.t[0].triangles." + b.field), std::string::npos) << e;
    EXPECT_NE(e.find(b.message), std::string::npos) << e;
  }
  const ParseResult ok = parseTriangles(
      "vertex_format: half2, indices: [0, 1, 2], "
      "index_type: uint16");
  ASSERT_TRUE(ok.value) << (ok.errors.empty() ? "" : ok.errors[0].format());
  EXPECT_TRUE(ok.value->scene.blases[0].geometries[0].index16);
}

}  // namespace
}  // namespace rayspec
