// rayspec export --format c of the scene's structure operations: updates
// (scene.update: in place, into other structures, top levels rebuilt),
// copies (scene.build.copy: clone, compact, serialize) in the order
// scene.build.order gives, and several top levels, each played on lavapipe as
// rayspec's builds run them (harness/vulkan/scene_builder.cpp) and
// held to rayspec's verdict (references/baselines/lavapipe.csv: Pass);
// expectations of the scene as first built (an update the model ignored)
// make an update case fail. Structure queries (scene.build.queries) asked
// on the device and held to the specification: lavapipe 25.0.7 writes another
// UUID where a serialized header's driverUUID belongs
// (references/driver-reports/lavapipe-serialized-header-uuid.md).
#include <gtest/gtest.h>

#include "export_play.h"

namespace rayspec {
namespace {

TEST(ExportStructures, UpdatesAndCopiesInEveryOrderPassOnLavapipe) {
  // Updates of BLASes and two top levels around a compact copy; top levels
  // rebuilt after a compact copy (into structures of their build size); every
  // update into another structure; a serialized and deserialized scene.
  for (const char* name :
       {"accel/update-order/compact-between", "accel/update-tlas-rebuilt-after-copy/compact-first",
        "accel/update-inactive/other", "accel/copy/serialize-update-allowed"}) {
    const ExportCase l = loadExportCase(name);
    const Played p = exportAndPlay(l, exportModelOf(l), l.c.name);
    EXPECT_EQ(p.status, 0) << name << ":\n" << p.output;
    EXPECT_NE(p.output.find("PASS: "), std::string::npos) << p.output;
  }
}

TEST(ExportStructures, ExpectationsOfTheSceneAsFirstBuiltFail) {
  // The planted fault update-ignored on rayspec's side: the model traces the
  // scene as first built (fault/mutate_structures.cpp), the file updates it.
  const ExportCase l = loadExportCase("accel/update/everything-fast_trace");
  ExportCase first = l;
  first.c.scene = *l.c.scene.earlier.front();
  const Played p = exportAndPlay(l, exportModelOf(first), "update-ignored");
  EXPECT_EQ(p.status, 1) << p.output;
  EXPECT_NE(p.output.find("FAIL: "), std::string::npos) << p.output;
}

TEST(ExportStructures, ExpectationsOfACopyThatLostAnInstanceFail) {
  // The planted fault copy-drops-instance on rayspec's side: the model
  // traces the scene without its last instance; the file's compacted copies
  // keep it.
  const ExportCase l = loadExportCase("accel/copy/compact-fast-trace");
  ExportCase dropped = l;
  Instance& last = dropped.c.scene.instances.back();
  ASSERT_TRUE(last.blas);
  last.blas.reset();
  const Played p = exportAndPlay(l, exportModelOf(dropped), "copy-drops-instance");
  EXPECT_EQ(p.status, 1) << p.output;
  EXPECT_NE(p.output.find("FAIL: "), std::string::npos) << p.output;
}

TEST(ExportStructures, QueriesAreAskedAndHeldToTheSpecification) {
  // The sizes lavapipe answers within the rules: PASS. With the
  // serialization size, every serialized header is checked: lavapipe 25.0.7
  // FAILs each under R-AS-SERIAL-HEADER, as rayspec does (lavapipe.csv:
  // accel/queries/device-serialized,Fail).
  ExportCase l = loadExportCase("culling/facing-cull");
  l.c.scene.build.queries.queries = {StructureQuery::CompactedSize, StructureQuery::Size};
  const Played sizes = exportAndPlay(l, exportModelOf(l), "queried-sizes");
  EXPECT_EQ(sizes.status, 0) << sizes.output;
  l.c.scene.build.queries.queries.push_back(StructureQuery::SerializationSize);
  const Played serialized = exportAndPlay(l, exportModelOf(l), "queried-serialized");
  EXPECT_EQ(serialized.status, 1) << serialized.output;
  EXPECT_NE(serialized.output.find("FAIL: R-AS-SERIAL-HEADER: TLAS 0: serialized header's "
                                   "driverUUID is not the device's driverUUID"),
            std::string::npos)
      << serialized.output;
}

}  // namespace
}  // namespace rayspec
