// rayspec export --format amber (export/export_amber.h): the script's text
// holds the case and the model's values (each EXPECT built here from the
// model, never typed), what the subset cannot express is refused by name
// (and what the C export refuses, as it refuses it), and where an Amber
// binary is at hand (RAYSPEC_AMBER, or `amber` on PATH) the script passes
// on lavapipe and a planted wrong expectation fails.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>

#include "compare/compare_parts.h"
#include "export/amber_sections.h"
#include "export/export_amber.h"
#include "export_play.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

std::string amberScript(const ExportCase& l, const Results& model) {
  const Result<std::string> text = exportCaseAsAmber(l.c, l.plan, model);
  EXPECT_TRUE(text) << l.c.name << ": " << (text ? "" : text.error().format());
  return text ? *text : "";
}

bool holds(const std::string& text, const std::string& line) {
  return text.find(line) != std::string::npos;
}

TEST(ExportAmber, TheScriptHoldsTheCaseInTheCtsSubset) {
  const ExportCase l = loadExportCase("culling/facing-cull");
  const std::string text = amberScript(l, exportModelOf(l));
  for (const char* line :
       {"#!amber\n", "DEVICE_FEATURE RayTracingPipelineFeaturesKHR.rayTracingPipeline\n",
        "SHADER ray_generation raygen SPIRV-HEX\n03 02 23 07 ",  // the SPIR-V magic, low byte first
        "SHADER closest_hit hit0_closest_hit SPIRV-HEX\n", "SHADER miss miss0 SPIRV-HEX\n",
        "# #version 460",
        "ACCELERATION_STRUCTURE BOTTOM_LEVEL blas0\n  GEOMETRY TRIANGLES\n"
        "    FLAGS OPAQUE\n    -1.0 -1.0 0.0\n    2.0 -1.0 0.0\n    -1.0 2.0 0.0\n  END\nEND\n",
        "ACCELERATION_STRUCTURE TOP_LEVEL tlas\n  BOTTOM_LEVEL_INSTANCE blas0\n",
        "PIPELINE raytracing pipeline\n  MAX_RAY_RECURSION_DEPTH 1\n",
        "  BIND ACCELERATION_STRUCTURE tlas DESCRIPTOR_SET 0 BINDING 0\n",
        "  BIND BUFFER records AS storage DESCRIPTOR_SET 0 BINDING 2\n",
        "  SHADER_GROUP group_hit0 hit0_closest_hit\n",
        "RUN pipeline RAYGEN sbt_raygen MISS sbt_miss HIT sbt_hit 8 1 1\n",
        "COPY records TO records_as_float\n"})
    EXPECT_TRUE(holds(text, line)) << line;
  // The record words bound directly: the variant's define, in every stage.
  EXPECT_TRUE(holds(text, "# #define RS_RECORDS_BOUND\n"));
}

TEST(ExportAmber, EveryExpectIsTheModelsValue) {
  const ExportCase l = loadExportCase("culling/facing-cull");
  const Results model = exportModelOf(l);
  const std::string text = amberScript(l, model);
  const size_t words = recordWords();
  const RecordField* hit = findRecordField("hit");
  const RecordField* t = findRecordField("hit_t");
  ASSERT_TRUE(hit && t);
  const ModelRayBounds bounds(l.c, model);
  for (uint32_t ray = 0; ray < 8; ++ray) {
    const uint32_t* m = &model.records[ray * words];
    const std::string at = "EXPECT records IDX ";
    EXPECT_TRUE(holds(text, at + std::to_string(4 * ray * words) + " EQ " +
                                std::to_string(m[kRecordWrittenMaskWord]) + "\n"));
    EXPECT_TRUE(holds(text, at + std::to_string(4 * (ray * words + hit->offset)) + " EQ " +
                                std::to_string(m[hit->offset]) + "\n"));
    if (!written(m, static_cast<int>(t->index))) continue;
    float v;
    std::memcpy(&v, &m[t->offset], 4);
    EXPECT_TRUE(holds(text, "EXPECT records_as_float IDX " +
                                std::to_string(4 * (ray * words + t->offset)) + " TOLERANCE " +
                                amberFloat(fieldTolerance(*t, bounds.of(ray)).allowance(v)) +
                                " EQ " + amberFloat(v) + "\n"))
        << ray;
  }
  // Counters: exact here (miss, closesthit), each its model count.
  EXPECT_TRUE(holds(text, "EXPECT counters IDX 0 EQ " + std::to_string(model.counters.at("miss"))));
  EXPECT_TRUE(
      holds(text, "EXPECT counters IDX 4 EQ " + std::to_string(model.counters.at("closesthit"))));
}

TEST(ExportAmber, RefusesWhatTheSubsetCannotExpressNamingIt) {
  const std::pair<const char*, const char*> refused[] = {
      // Played by the C export, not by an Amber script.
      {"accel/update-order/twice",
       "export: case uses acceleration structure updates (scene.update), which an Amber script "
       "cannot express"},
      // Ambiguous rays (tmin, tmax): the count is the model's.
      {"candidates/triangle-open-interval",
       "export: case uses numerically ambiguous rays (N with several legal answers; an EXPECT "
       "holds one value), which an Amber script cannot express"},
      {"ray-query/candidates-count",
       "export: case uses ray queries (Amber requests no rayQuery feature), which an Amber "
       "script cannot express"},
  };
  for (const auto& [name, pattern] : refused) {
    const ExportCase l = loadExportCase(name);
    const Results model = exportModelOf(l);
    const Result<std::string> text = exportCaseAsAmber(l.c, l.plan, model);
    ASSERT_FALSE(text) << name;
    std::string message = pattern;
    if (const size_t n = message.find("(N with"); n != std::string::npos)
      message.replace(n + 1, 1, std::to_string(model.ambiguous.size()));
    EXPECT_EQ(text.error().kind, ErrorKind::NotSupported) << name;
    EXPECT_EQ(text.error().message, message) << name;
  }
}

TEST(ExportAmber, RefusesIndicesAndRecordData) {
  ExportCase l = loadExportCase("culling/facing-cull");
  const Results model = exportModelOf(l);
  // Structure queries, which the C export asks: a script would skip them.
  l.c.scene.build.queries.queries = {StructureQuery::CompactedSize};
  Result<std::string> asked = exportCaseAsAmber(l.c, l.plan, model);
  ASSERT_FALSE(asked);
  EXPECT_NE(asked.error().message.find("acceleration structure queries"), std::string::npos);
  l = loadExportCase("culling/facing-cull");
  l.c.scene.blases[0].geometries[0].indices = {0, 1, 2};
  Result<std::string> text = exportCaseAsAmber(l.c, l.plan, model);
  ASSERT_FALSE(text);
  EXPECT_NE(text.error().message.find("an index buffer (triangles.indices"), std::string::npos);
  l = loadExportCase("culling/facing-cull");
  l.plan.zero_records = true;
  text = exportCaseAsAmber(l.c, l.plan, model);
  ASSERT_FALSE(text);
  EXPECT_NE(text.error().message.find("an all-zero SBT record"), std::string::npos);
}

TEST(AmberText, FloatsReadBackExactlyWithTheirPoint) {
  EXPECT_EQ(amberFloat(1.0), "1.0");
  EXPECT_EQ(amberFloat(-0.0), "-0.0");
  EXPECT_EQ(amberFloat(1e-05), "1.0000000000000001e-05");
  EXPECT_EQ(amberFloat(1e20), "1.0e+20");
  EXPECT_EQ(amberFloat(std::nan("")), "nan");
  for (float f : {0.1f, -3.4028235e38f, 1.17549435e-38f, 1e-45f, 0.333333343f})
    EXPECT_EQ(static_cast<float>(std::strtod(amberFloat(f).c_str(), nullptr)), f);
  EXPECT_EQ(amberComment("a\n\nb"), "# a\n#\n# b\n");
}

// The Amber binary: RAYSPEC_AMBER, else `amber` on PATH; "" without one.
std::string amberBinary() {
  if (const char* a = std::getenv("RAYSPEC_AMBER"); a && *a) return a;
  return std::system("command -v amber > /dev/null 2>&1") == 0 ? "amber" : "";
}

// The script run by Amber on lavapipe (-d: without the validation layer, whose
// ray tracing checks the layer of Debian 12 predates); its exit status.
Played playAmber(const std::string& amber, const std::string& text, const std::string& name) {
  const std::string dir = freshTempDir("export-amber/" + name);
  std::ofstream(dir + "/repro.amber") << text;
  const int s = std::system(
      (amber + " -v 1.2 -d " + dir + "/repro.amber > " + dir + "/out.txt 2>&1").c_str());
  return {WIFEXITED(s) ? WEXITSTATUS(s) : -1, slurpExportFile(dir + "/out.txt")};
}

TEST(ExportAmber, PassesOnLavapipeAndAPlantedWrongValueFails) {
  const std::string amber = amberBinary();
  if (amber.empty()) GTEST_SKIP() << "no Amber binary (RAYSPEC_AMBER, or amber on PATH)";
  const ExportCase l = loadExportCase("culling/facing-cull");
  Results model = exportModelOf(l);
  const Played good = playAmber(amber, amberScript(l, model), "facing-cull");
  EXPECT_EQ(good.status, 0) << good.output;
  // The first ray that ran closest-hit expects it to have run twice.
  const RecordField* f = findRecordField("closest_hit_runs");
  const size_t words = recordWords();
  size_t ray = 0;
  while (model.records[ray * words + f->offset] != 1) ++ray;
  model.records[ray * words + f->offset] = 2;
  const Played wrong = playAmber(amber, amberScript(l, model), "facing-cull-wrong");
  EXPECT_EQ(wrong.status, 1) << wrong.output;
  EXPECT_NE(wrong.output.find("2"), std::string::npos) << wrong.output;
}

}  // namespace
}  // namespace rayspec
