// Vertex formats (R-VERTEX-FORMAT): the positions each format stores, what
// it cannot hold, the bytes of its vertex buffer, and the parse errors of
// triangles.vertex_format and index_type at their line and field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "case/vertex_format.h"
#include "parse/parse_case.h"
#include "parse_support.h"

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

// The normalized formats, each with its largest code and whether it is signed.
struct NormalizedRow {
  VertexFormat format;
  int32_t max_code;
  bool snorm;
};
const NormalizedRow kNormalizedRows[] = {
    {VertexFormat::Snorm16x4, 32767, true},  {VertexFormat::Snorm16x2, 32767, true},
    {VertexFormat::Unorm16x4, 65535, false}, {VertexFormat::Unorm16x2, 65535, false},
    {VertexFormat::Snorm8x4, 127, true},     {VertexFormat::Snorm8x2, 127, true},
    {VertexFormat::Unorm8x4, 255, false},    {VertexFormat::Unorm8x2, 255, false},
    {VertexFormat::Unorm10x3, 1023, false},  {VertexFormat::Snorm16x3, 32767, true}};

TEST(VertexFormat, EveryNormalizedFormatHoldsTheEndsOfItsRange) {
  for (const NormalizedRow& n : kNormalizedRows) {
    const char* name = vertexFormatName(n.format);
    EXPECT_TRUE(vertexNormalized(n.format)) << name;
    EXPECT_EQ(vertexMaxCode(n.format), uint32_t(n.max_code)) << name;
    EXPECT_EQ(vertexCode(n.format, 0.0f), 0) << name;
    EXPECT_EQ(vertexCode(n.format, 1.0f), n.max_code) << name;
    EXPECT_EQ(storedVertex(n.format, Vec3{1.0f, 0.0f, 0.0f}), (Vec3{1.0f, 0.0f, 0.0f})) << name;
    const float below_one = vertexCodeValue(n.format, n.max_code - 1);
    EXPECT_EQ(below_one, float(n.max_code - 1) / float(n.max_code)) << name;
    if (!n.snorm) continue;
    EXPECT_EQ(vertexCode(n.format, -1.0f), -n.max_code) << name;
    EXPECT_EQ(vertexCodeValue(n.format, -n.max_code), -1.0f) << name;
    // The one code below -max stands for -1 too (max(c / max, -1)).
    EXPECT_EQ(vertexCodeValue(n.format, -n.max_code - 1), -1.0f) << name;
  }
  for (VertexFormat f : {VertexFormat::Float3, VertexFormat::Float4, VertexFormat::Half3})
    EXPECT_FALSE(vertexNormalized(f)) << vertexFormatName(f);
}

// The model's value of every code is within vertexDecodeError of what a
// device computing the quotient another way gets: by reciprocal, in double,
// or with a fused multiply-add correction.
TEST(VertexFormat, DecodeErrorCoversOtherWaysToDivide) {
  for (const NormalizedRow& n : kNormalizedRows) {
    const float bound = vertexDecodeError(n.format), m = float(n.max_code), r = 1.0f / m;
    ASSERT_GT(bound, 0.0f);
    for (int32_t c = n.snorm ? -n.max_code : 0; c <= n.max_code; ++c) {
      const float model = vertexCodeValue(n.format, c), x = float(c);
      const float q0 = x * r, q1 = std::fmaf(-q0, m, x) * r + q0;
      for (float device : {q0, q1, float(double(c) / n.max_code)})
        ASSERT_LE(std::fabs(device - model), bound) << vertexFormatName(n.format) << " " << c;
    }
  }
  EXPECT_EQ(vertexDecodeError(VertexFormat::Half3), 0.0f);
  EXPECT_EQ(vertexDecodeError(VertexFormat::Float4), 0.0f);
}

TEST(VertexFormat, ProblemsOfTheNewFormatsNameTheirRange) {
  auto problem = [](VertexFormat f, Vec3 v) {
    return vertexFormatProblem(f, v);
  };
  EXPECT_EQ(problem(VertexFormat::Unorm8x4, {-0.01f, 0, 0}), "unorm8x4 stores 0 to 1 only");
  EXPECT_EQ(problem(VertexFormat::Unorm16x2, {0, 1.01f, 0}), "unorm16x2 stores 0 to 1 only");
  EXPECT_EQ(problem(VertexFormat::Unorm10x3, {0, 0, 2}), "unorm10x3 stores 0 to 1 only");
  EXPECT_EQ(problem(VertexFormat::Snorm8x2, {-1.5f, 0, 0}), "snorm8x2 stores -1 to 1 only");
  EXPECT_EQ(problem(VertexFormat::Unorm8x2, {0, 0, 0.5f}),
            "unorm8x2 stores x and y only: z must be 0");
  EXPECT_EQ(problem(VertexFormat::Unorm10x3, {NAN, 0, 0}), "unorm10x3 cannot store NaN");
  EXPECT_EQ(problem(VertexFormat::Half3, {0, 0, -70000.0f}),
            "half3 stores at most 65504 in magnitude");
  EXPECT_EQ(problem(VertexFormat::Float4, {1e30f, NAN, -3}), "");
  EXPECT_EQ(problem(VertexFormat::Snorm8x4, {-1, 1, 0}), "");
  EXPECT_EQ(problem(VertexFormat::Unorm10x3, {0, 1, 0.5f}), "");
}

// A2B10G10R10_UNORM_PACK32: R (x) in bits 0..9, G (y) in 10..19, B (z) in
// 20..29, A in 30..31 (written as its largest code).
TEST(VertexFormat, PackedTenBitCodesLieWhereTheFormatTableSays) {
  const std::vector<uint8_t> b = encodeVertices(VertexFormat::Unorm10x3, {{1.0f, 0.5f, 0.25f}});
  ASSERT_EQ(b.size(), 4u);
  uint32_t word = 0;
  std::memcpy(&word, b.data(), 4);
  EXPECT_EQ(word & 0x3FF, 1023u);
  EXPECT_EQ((word >> 10) & 0x3FF, 512u);  // 511.5 rounds away from zero
  EXPECT_EQ((word >> 20) & 0x3FF, 256u);  // 255.75
  EXPECT_EQ(word >> 30, 3u);
  EXPECT_EQ(vertexComponentBytes(VertexFormat::Unorm10x3), 4u);
  EXPECT_EQ(storedVertex(VertexFormat::Unorm10x3, {1.0f, 0.5f, 0.25f})[2], 256.0f / 1023.0f);
}

TEST(VertexFormat, EightAndSixteenBitCodesAndFloatsLieInTheirBytes) {
  const std::vector<uint8_t> u8 = encodeVertices(VertexFormat::Unorm8x4, {{1.0f, 0.0f, 0.5f}});
  EXPECT_EQ(u8, (std::vector<uint8_t>{255, 0, 128, 255}));
  const std::vector<uint8_t> s8 = encodeVertices(VertexFormat::Snorm8x2, {{-1.0f, 0.5f, 0}});
  EXPECT_EQ(s8, (std::vector<uint8_t>{0x81, 64}));
  const std::vector<uint8_t> u16 = encodeVertices(VertexFormat::Unorm16x4, {{0.0f, 1.0f, 0.5f}});
  EXPECT_EQ(u16, (std::vector<uint8_t>{0, 0, 0xFF, 0xFF, 0x00, 0x80, 0xFF, 0xFF}));
  const std::vector<uint8_t> f4 = encodeVertices(VertexFormat::Float4, {{2.0f, -3.0f, 4.0f}});
  ASSERT_EQ(f4.size(), 16u);
  float w = 0;
  std::memcpy(&w, &f4[12], 4);
  EXPECT_EQ(w, 1.0f);
  EXPECT_EQ(encodeVertices(VertexFormat::Half3, {{1, 2, 3}}).size(), 6u);
  EXPECT_EQ(storedVertex(VertexFormat::Half3, {0.3f, 0, 0})[0], 0.30004883f);
  for (VertexFormat f : enumValues<VertexFormat>())
    EXPECT_EQ(encodeVertices(f, {{0, 0, 0}, {0, 0, 0}}).size(), 2 * vertexStride(f))
        << vertexFormatName(f);
}

// Every format's bytes, read back, are the stored positions: at the ends of
// its range and between them.
TEST(VertexFormat, DecodedBytesAreTheStoredPositions) {
  for (VertexFormat f : enumValues<VertexFormat>()) {
    const bool signed_range =
        vertexEncoding(f) != VertexEncoding::Unorm && vertexEncoding(f) != VertexEncoding::Packed10;
    const float lo = signed_range ? -1.0f : 0.0f;
    std::vector<Vec3> v = {{lo, 1.0f, 0.30001f}, {0.0f, lo, 1.0f}, {0.7f, 0.123f, lo}};
    if (vertexComponents(f) == 2)
      for (Vec3& x : v) x[2] = 0.0f;
    std::vector<Vec3> stored;
    for (const Vec3& x : v) stored.push_back(storedVertex(f, x));
    EXPECT_EQ(decodeVertices(f, encodeVertices(f, v), vertexStride(f), v.size()), stored)
        << vertexFormatName(f);
  }
  const std::vector<Vec3> past = decodeVertices(
      VertexFormat::Unorm8x2, encodeVertices(VertexFormat::Unorm8x2, {{1, 0, 0}}), 2, 2);
  EXPECT_EQ(past[0], (Vec3{1, 0, 0}));
  EXPECT_TRUE(std::isnan(past[1][0])) << "a vertex past the bytes";
}

ParseResult parseTriangles(const std::string& extra) {
  return parseCaseText(oneTriangleText("R-VERTEX-FORMAT", "", extra), "t.yaml", "t/t");
}

TEST(VertexFormat, ParseErrorsNameTheLineAndField) {
  struct Bad {
    std::string extra, field, message;
  } bad[] = {{"vertex_format: half5", "vertex_format", "unknown vertex format 'half5'"},
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
