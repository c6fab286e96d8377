// pipeline.sbt.record_data and padding: how they are read, and the errors for
// record data or shader record reads that do not fit in a record's data bytes
// (each at file:line:column and field).
#include <gtest/gtest.h>

#include <string>

#include "parse/parse_case.h"
#include "parse_support.h"

namespace rayspec {
namespace {

ParseResult parseRecord(const std::string& text) {
  return parseCaseText(text, "s.yaml", "sbt/s");
}

// An error at line:column (0: any column) of field (empty: any field) whose
// message holds text.
bool recordErrorAt(const ParseResult& r, int line, int column, const std::string& field,
                   const std::string& text) {
  for (const Error& e : r.errors)
    if (e.loc.file == "s.yaml" && e.loc.line == line && (column == 0 || e.loc.column == column) &&
        (field.empty() || e.loc.field == field) && e.message.find(text) != std::string::npos)
      return true;
  return false;
}

#define EXPECT_RECORD_ERROR_AT(r, line, column, field, text)                             \
  EXPECT_TRUE(recordErrorAt(r, line, column, field, text))                               \
      << "expected s.yaml:" << line << ":" << column << ": " << field << ": ..." << text \
      << "...; got:\n"                                                                   \
      << allErrors(r)

// A miss shader, a hit group and a callable, each reading @READ@; raygen
// reads @RAYGEN@; the sbt block is @SBT@ (line 15 on).
std::string caseText(const std::string& sbt, const std::string& read = "0",
                     const std::string& raygen_read = "0",
                     const std::string& raygen_data = "{uints: []}") {
  std::string s = R"(rules: [R-SBT-RECORD]
scene:
  blas:
    tri: [{triangles: {vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]}}]
  instances: [{blas: tri}]
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
pipeline:
  raygen: [trace: {}, record: {value: @RAYGEN@}]
  raygen_data: @RAYGEN_DATA@
  miss: [[payload: {value: @READ@}]]
  hit_groups: [{closest_hit: [payload: {value: @READ@}]}]
  callables: [[call_data: {value: @READ@}]]
  sbt:
@SBT@
outputs:
  per_ray: [value]
)";
  auto put = [&](const std::string& key, const std::string& value) {
    for (size_t at; (at = s.find(key)) != std::string::npos;) s.replace(at, key.size(), value);
  };
  put("@SBT@", sbt);
  put("@READ@", read);
  put("@RAYGEN_DATA@", raygen_data);
  put("@RAYGEN@", raygen_read);
  return s;
}

TEST(SbtRecordShape, DefaultsAndValues) {
  ParseResult r = parseRecord(caseText("    miss: [0]"));
  ASSERT_TRUE(r.value) << allErrors(r);
  EXPECT_EQ(r.value->pipeline.sbt_record_data, 32u);
  EXPECT_EQ(r.value->pipeline.sbt_padding.hit, 0u);

  r = parseRecord(caseText("    record_data: 0\n    padding: 4000"));
  ASSERT_TRUE(r.value) << allErrors(r);
  EXPECT_EQ(r.value->pipeline.sbt_record_data, 0u);
  EXPECT_EQ(r.value->pipeline.sbt_padding.miss, 4000u);
  EXPECT_EQ(r.value->pipeline.sbt_padding.hit, 4000u);
  EXPECT_EQ(r.value->pipeline.sbt_padding.callable, 4000u);

  r = parseRecord(caseText("    record_data: 0x10\n    padding: {hit: 32, callable: 65536}"));
  ASSERT_TRUE(r.value) << allErrors(r);
  EXPECT_EQ(r.value->pipeline.sbt_record_data, 16u);
  EXPECT_EQ(r.value->pipeline.sbt_padding.miss, 0u);
  EXPECT_EQ(r.value->pipeline.sbt_padding.hit, 32u);
  EXPECT_EQ(r.value->pipeline.sbt_padding.callable, 65536u);
}

TEST(SbtRecordShape, BadValuesAreFieldErrors) {
  EXPECT_RECORD_ERROR_AT(parseRecord(caseText("    record_data: 6")), 15, 18,
                         "pipeline.sbt.record_data", "multiple of 4");
  EXPECT_RECORD_ERROR_AT(parseRecord(caseText("    record_data: 36")), 15, 18,
                         "pipeline.sbt.record_data", "");
  EXPECT_RECORD_ERROR_AT(parseRecord(caseText("    padding: 65537")), 15, 14,
                         "pipeline.sbt.padding", "");
  EXPECT_RECORD_ERROR_AT(parseRecord(caseText("    padding: -1")), 15, 14, "pipeline.sbt.padding",
                         "");
  EXPECT_RECORD_ERROR_AT(parseRecord(caseText("    padding: {raygen: 32}")), 15, 15,
                         "pipeline.sbt.padding.raygen", "unknown key");
  EXPECT_RECORD_ERROR_AT(parseRecord(caseText("    padding: {hit: 70000}")), 15, 0,
                         "pipeline.sbt.padding.hit", "");
  EXPECT_RECORD_ERROR_AT(parseRecord(caseText("    stride: 64")), 15, 5, "pipeline.sbt.stride",
                         "unknown key");
}

TEST(SbtRecordShape, RecordDataPastTheRecordIsAnErrorAtTheData) {
  ParseResult r = parseRecord(
      caseText("    record_data: 8\n    hit: [{group: 0, data: {uints: [1, 2]}}]\n    miss: "
               "[{group: 0, data: {floats: [1, 2, 3]}}]"));
  EXPECT_RECORD_ERROR_AT(
      r, 17, 0, "pipeline.sbt.miss[0].data",
      "3 word(s) (12 bytes) of shader record data do not fit in pipeline.sbt.record_data (8 bytes");
  EXPECT_EQ(r.errors.size(), 1u) << allErrors(r);  // the hit record's 2 words fit

  r = parseRecord(caseText("    record_data: 0\n    callable: [{group: 0, data: {uints: [7]}}]"));
  EXPECT_RECORD_ERROR_AT(r, 16, 0, "pipeline.sbt.callable[0].data", "do not fit");

  // raygen's data too, wherever the sbt block stands.
  r = parseRecord(caseText("    record_data: 4", "0", "0", "{uints: [1, 2]}"));
  EXPECT_RECORD_ERROR_AT(r, 10, 16, "pipeline.raygen_data",
                         "2 word(s) (8 bytes) of shader record data do not fit");
  EXPECT_TRUE(parseRecord(caseText("    record_data: 4", "0", "0", "{uints: [1]}")).value);
}

TEST(SbtRecordShape, ReadsPastTheRecordDataAreErrorsAtTheRead) {
  // Word 1 is bytes 4..7: inside 8 bytes, outside 4.
  EXPECT_TRUE(parseRecord(caseText("    record_data: 8", "{shader_record_uint: 1}")).value);
  ParseResult r = parseRecord(caseText("    record_data: 4", "{shader_record_uint: 1}"));
  for (int line : {11, 12, 13})  // miss, closest-hit, callable
    EXPECT_RECORD_ERROR_AT(r, line, 0, "",
                           "shader_record_uint(1) reads bytes 4..7 of its shader record, past "
                           "pipeline.sbt.record_data (4 bytes per record)");
  EXPECT_EQ(r.errors.size(), 3u) << allErrors(r);
  EXPECT_NE(allErrors(r).find("pipeline.hit_groups[0].closest_hit"), std::string::npos)
      << allErrors(r);

  r = parseRecord(caseText("    record_data: 0", "0", "{uint: {shader_record_float: 0}}"));
  EXPECT_RECORD_ERROR_AT(r, 9, 0, "", "shader_record_float(0) reads bytes 0..3");
  EXPECT_NE(allErrors(r).find("pipeline.raygen"), std::string::npos) << allErrors(r);

  // A read nested in an expression, and one in a branch.
  r = parseRecord(caseText("    record_data: 28", "{add: [1, {shader_record_uint: 7}]}"));
  EXPECT_EQ(r.errors.size(), 3u) << allErrors(r);
  EXPECT_TRUE(
      parseRecord(caseText("    record_data: 32", "{add: [1, {shader_record_uint: 7}]}")).value);
}

TEST(SbtRecordShape, LightsReadSixOrEightFloats) {
  auto with_light = [](const std::string& k, const std::string& light) {
    std::string s = caseText("    record_data: " + k);
    s.replace(s.find("[[call_data: {value: 0}]]"), 25, "[[light: " + light + "]]");
    return parseRecord(s);
  };
  EXPECT_TRUE(with_light("24", "point").value);
  EXPECT_TRUE(with_light("24", "directional").value);
  EXPECT_TRUE(with_light("32", "spot").value);
  ParseResult r = with_light("28", "spot");
  EXPECT_RECORD_ERROR_AT(r, 13, 0, "",
                         "light: spot reads floats 0..7 (bytes 0..31) of its shader record");
  r = with_light("20", "point");
  EXPECT_RECORD_ERROR_AT(r, 13, 0, "", "light: point reads floats 0..5 (bytes 0..23)");

  // The light_* ops read the same floats, in any stage.
  const std::string op = "{uint: {x: {light_directional: [[0.0, 0.0, 0.0], [0.0, 0.0, 1.0]]}}}";
  EXPECT_TRUE(parseRecord(caseText("    record_data: 24", op)).value);
  r = parseRecord(caseText("    record_data: 16", op));
  EXPECT_EQ(r.errors.size(), 3u) << allErrors(r);
  EXPECT_RECORD_ERROR_AT(r, 12, 0, "", "light_directional reads floats 0..5 (bytes 0..23)");
}

}  // namespace
}  // namespace rayspec
