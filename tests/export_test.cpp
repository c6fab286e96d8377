// rayspec export --format c (export/export_c.h): library cases exported,
// compiled with the C compiler and run on lavapipe, the player's verdict
// held to rayspec's (references/baselines/lavapipe.csv); expectations
// planted wrong (a flipped value, a model fault, a legal answer left out)
// make it fail; what the export does not play is refused by name.
#include <gtest/gtest.h>

#include "export/c_text.h"
#include "export/export_support.h"
#include "export_play.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

TEST(ExportC, CasesRayspecPassesPassOnLavapipe) {
  // Clear rays, a nested trace, shader record data, and two rays at tmin
  // and tmax whose legal answers (a hit or a miss) are replayed.
  for (const char* name : {"culling/facing-cull", "sbt/shader-record-data", "recursion/depth-three",
                           "candidates/triangle-open-interval"}) {
    const ExportCase l = loadExportCase(name);
    const Played p = exportAndPlay(l, exportModelOf(l), l.c.name);
    EXPECT_EQ(p.status, 0) << name << ":\n" << p.output;
    EXPECT_NE(p.output.find("PASS: "), std::string::npos) << p.output;
  }
}

TEST(ExportC, HitGroupsOfEveryKindAndCallablesAgreeWithRayspecOnLavapipe) {
  // Any-hit (terminating), procedural hit groups over AABBs (with the scene
  // data binding), callables from every stage, and lavapipe.csv's
  // intersection/tmax-after-report,Fail (a later report sees the tmax of an
  // ignored one).
  const std::pair<const char*, int> sample[] = {
      {"anyhit/terminate-accepts", 0},        {"intersection/closest-box-runs", 0},
      {"candidates/aabb-closed-interval", 0}, {"callable/from-every-stage", 0},
      {"intersection/tmax-after-report", 1},
  };
  for (const auto& [name, status] : sample) {
    const ExportCase l = loadExportCase(name);
    const Played p = exportAndPlay(l, exportModelOf(l), l.c.name);
    EXPECT_EQ(p.status, status) << name << ":\n" << p.output;
  }
}

TEST(ExportC, ExpectationsOfAModelWithOpenAabbIntervalsFail) {
  // The model as a device whose reportIntersectionEXT rejects t == tmin and
  // t == tmax (R-CAND-AABB-CLOSED broken): lavapipe, closed, fails it.
  const ExportCase l = loadExportCase("candidates/aabb-closed-interval");
  ModelFaults faults;
  faults.deviation = ModelDeviation::OpenAabbInterval;
  const Played p = exportAndPlay(l, exportModelOf(l, faults), "open-aabb-interval");
  EXPECT_EQ(p.status, 1) << p.output;
  EXPECT_NE(p.output.find("FAIL: "), std::string::npos) << p.output;
}

TEST(ExportC, LavapipesFirstVertexBugFailsAsRayspecSays) {
  // lavapipe.csv: accel/layouts-first-vertex,Fail (firstVertex added twice).
  const ExportCase l = loadExportCase("accel/layouts-first-vertex");
  const Played p = exportAndPlay(l, exportModelOf(l), "first-vertex");
  EXPECT_EQ(p.status, 1) << p.output;
  EXPECT_NE(p.output.find("FAIL: R-MISS-XOR-CHIT: ray 0: field 'hit': expected 1, observed 0"),
            std::string::npos)
      << p.output;
}

TEST(ExportC, AFlippedExpectedValueFails) {
  const ExportCase l = loadExportCase("culling/facing-cull");
  Results model = exportModelOf(l);
  const RecordField* f = findRecordField("closest_hit_runs");
  ASSERT_TRUE(f);
  // The first ray that ran closest-hit expects it to have run twice.
  size_t ray = 0;
  const size_t words = recordWords(), rays = model.records.size() / words;
  while (ray < rays && model.records[ray * words + f->offset] != 1) ++ray;
  ASSERT_LT(ray, rays);
  model.records[ray * words + f->offset] = 2;
  const Played p = exportAndPlay(l, model, "flipped");
  EXPECT_EQ(p.status, 1) << p.output;
  EXPECT_NE(p.output.find("ray " + std::to_string(ray) +
                          ": field 'closest_hit_runs': expected 2, observed 1"),
            std::string::npos)
      << p.output;
}

TEST(ExportC, ExpectationsOfAModelWithAPlantedFaultFail) {
  // The model as a device that takes triangles at exactly tmin and tmax
  // (R-CAND-TRI-OPEN broken): lavapipe, which keeps the interval open, fails it.
  const ExportCase l = loadExportCase("candidates/triangle-open-interval");
  ModelFaults faults;
  faults.deviation = ModelDeviation::ClosedTriangleInterval;
  const Played p = exportAndPlay(l, exportModelOf(l, faults), "closed-interval");
  EXPECT_EQ(p.status, 1) << p.output;
  EXPECT_NE(p.output.find("FAIL: "), std::string::npos) << p.output;
}

TEST(ExportC, AnAmbiguousRayIsHeldToItsLegalAnswers) {
  // Ray 20 of triangle-open-interval: two legal answers. With one of them
  // left out the player passes only where the device took the one kept.
  const ExportCase l = loadExportCase("candidates/triangle-open-interval");
  const Results model = exportModelOf(l);
  const auto it = std::find_if(model.ambiguous.begin(), model.ambiguous.end(),
                               [](const RayAmbiguity& a) { return a.replays.size() == 2; });
  ASSERT_NE(it, model.ambiguous.end());
  const size_t index = static_cast<size_t>(it - model.ambiguous.begin());
  int passes = 0;
  for (size_t keep = 0; keep < 2; ++keep) {
    Results one = model;
    one.ambiguous[index].replays = {model.ambiguous[index].replays[keep]};
    const Played p = exportAndPlay(l, one, "one-answer-" + std::to_string(keep));
    ASSERT_TRUE(p.status == 0 || p.status == 1) << p.output;
    if (p.status == 0) {
      ++passes;
      continue;
    }
    EXPECT_NE(p.output.find("ray " + std::to_string(it->ray) +
                            " (numerically ambiguous: " + ambiguityReasonName(it->reason) +
                            "): the record is none of its 1 legal answers"),
              std::string::npos)
        << p.output;
  }
  EXPECT_EQ(passes, 1);
}

TEST(ExportC, RefusesWhatItDoesNotPlayNamingTheFeature) {
  const std::pair<const char*, const char*> refused[] = {
      {"accel/build-command/indirect",
       "export: case uses indirect builds (scene.build.command), not yet exported"},
      {"ray-query/dynamic-tlas-index",
       "export: case uses top levels indexed dynamically (tlas: expr), not yet exported"},
      // lavapipe.csv: NotSupported (no VK_EXT_opacity_micromap), which the player does not enable.
      {"cts-amber/basic2/as-written",
       "export: case uses opacity micromap instance flags (VK_EXT_opacity_micromap), not yet "
       "exported"},
  };
  for (const auto& [name, message] : refused) {
    const ExportCase l = loadExportCase(name);
    const Result<std::string> text = exportCaseAsC(l.c, l.plan, exportModelOf(l));
    ASSERT_FALSE(text) << name;
    EXPECT_EQ(text.error().kind, ErrorKind::NotSupported) << name;
    EXPECT_EQ(text.error().message, message) << name;
  }
}

TEST(ExportC, RefusesALaunchTooWideToEmbed) {
  ExportCase l = loadExportCase("culling/facing-cull");
  const Results model = exportModelOf(l);
  l.c.rays.width = static_cast<uint32_t>(kMaxExportedRays) + 1;
  l.c.rays.height = 1;
  const Result<std::string> text = exportCaseAsC(l.c, l.plan, model);
  ASSERT_FALSE(text);
  EXPECT_EQ(text.error().message,
            "export: case uses a launch of 65537 rays (at most 65536 are "
            "embedded), not yet exported");
}

TEST(ExportC, RefusesStructureQueriesOnTheHost) {
  // The player asks queries on the device only (tests/export_structures_test.cpp);
  // one that never asked them would pass a case whose findings it skipped.
  ExportCase l = loadExportCase("culling/facing-cull");
  l.c.scene.build.queries.queries = {StructureQuery::SerializationSize};
  l.c.scene.build.queries.command = QueryCommand::Host;
  const Result<std::string> text = exportCaseAsC(l.c, l.plan, exportModelOf(l));
  ASSERT_FALSE(text);
  EXPECT_EQ(text.error().message,
            "export: case uses structure queries on the host (scene.build.query_command host), "
            "not yet exported");
}

TEST(ExportC, ALayoutFaultIsCarriedIntoTheFile) {
  // What a reduction under offsets-ignored writes (run/fault_seam.h's
  // exportedLayoutFault): the builds are told offsets 0 over the same bytes,
  // reading the junk before them, so lavapipe FAILs; without it, PASS.
  ExportCase l = loadExportCase("accel/layouts-triangles");
  l.c.scene.build.instances_as_pointers = false;  // refused by the export; the rest stays
  const Results model = exportModelOf(l);
  const Result<std::string> text = exportCaseAsC(l.c, l.plan, model, LayoutFault::OffsetsIgnored);
  ASSERT_TRUE(text) << text.error().format();
  EXPECT_NE(text->find("the fault `offsets-ignored` misreads them"), std::string::npos);
  const Played faulty = playExport(*text, "offsets-ignored");
  EXPECT_EQ(faulty.status, 1) << faulty.output;
  const Played plain = exportAndPlay(l, model, "layouts-triangles");
  EXPECT_EQ(plain.status, 0) << plain.output;
}

TEST(ExportC, ANotSupportedVertexFormatExitsSeventySevenNamingIt) {
  // lavapipe.csv: accel/vertex-formats-listed/snorm16x3,NotSupported.
  const ExportCase l = loadExportCase("accel/vertex-formats-listed/snorm16x3");
  const Played p = exportAndPlay(l, exportModelOf(l), "snorm16x3");
  EXPECT_EQ(p.status, 77) << p.output;
  EXPECT_NE(p.output.find("NotSupported: triangles.vertex_format snorm16x3"), std::string::npos)
      << p.output;
}

TEST(CText, FloatsReadBackExactlyAndTextIsEscaped) {
  EXPECT_EQ(cFloat(1.5f), "0x1.8p+0f");
  EXPECT_EQ(cFloat(-0.0f), "-0x0p+0f");
  EXPECT_EQ(cString("a\"b\\c\n"), "\"a\\\"b\\\\c\\012\"");
  EXPECT_EQ(cComment("x \\\n\ny"), "// x \\ (line continues)\n//\n// y\n");
  EXPECT_EQ(cWordArray("w", {}), "static const uint32_t w[] = {\n  0\n};\n");
}

}  // namespace
}  // namespace rayspec
