// Hits recorded by hand into a hit object (record_hit: hitObjectRecordHitNV
// and hitObjectRecordHitWithIndexNV) and the hit object's shader record
// (hit_object_record_uint) in the model: the recorded hit holds what it was
// given and what its instance decides, its record is the instance's SBT
// offset plus offset and geometry times stride, or the index given, and
// executing it runs that record's closest-hit with those built-ins. The
// planted faults (R-HIT-OBJECT-RECORD) move each.
#include "model_support.h"

namespace rayspec::model_test {
namespace {

// Two instances of a two-geometry BLAS, the second translated and scaled,
// custom index 7 and SBT offset 2; five hit records, data 10 .. 50.
std::string recordHitCase(const std::string& record_hit) {
  return "rules: [R-HIT-OBJECT-RECORD]\n"
         "scene:\n"
         "  blas:\n"
         "    pair:\n"
         "      - triangles:\n"
         "          vertices: [[-1, -1, 0], [1, -1, 0], [-1, 1, 0]]\n"
         "      - triangles:\n"
         "          vertices: [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]\n"
         "          indices: [0, 1, 2, 0, 2, 3]\n"
         "  instances:\n"
         "    - {blas: pair}\n"
         "    - {blas: pair, transform: {translate: [3, 0, -2], scale: 2}, custom_index: 7, "
         "sbt_offset: 2}\n"
         "rays:\n"
         "  list:\n"
         "    - {origin: [1, 2, 5], direction: [0, 0, -1]}\n"
         "pipeline:\n"
         "  raygen:\n"
         "    - record_hit: {" +
         record_hit +
         "}\n"
         "    - record: {value1: hit_object.sbt_record_index, value2: "
         "hit_object.instance_custom_index, value3: {hit_object_record_uint: 0}, "
         "ray_tmax: hit_object.t}\n"
         "    - execute: {}\n"
         "    - record: {value: payload.value}\n"
         "  miss: [[count: miss]]\n"
         "  hit_groups:\n"
         "    - closest_hit: [count: closesthit, payload: {value: {shader_record_uint: 0}}, "
         "record: [primitive_id, geometry_index, hit_kind, hit_t, barycentrics, "
         "object_ray_origin]]\n"
         "  sbt:\n"
         "    hit:\n"
         "      - {group: 0, data: {uints: [10]}}\n"
         "      - {group: 0, data: {uints: [20]}}\n"
         "      - {group: 0, data: {uints: [30]}}\n"
         "      - {group: 0, data: {uints: [40]}}\n"
         "      - {group: 0, data: {uints: [50]}}\n"
         "outputs:\n"
         "  counters: [miss, closesthit]\n"
         "  per_ray: [value, value1, value2, value3, ray_tmax, primitive_id, geometry_index, "
         "hit_kind, hit_t, barycentrics, object_ray_origin]\n";
}

const std::string kRecordByOffset =
    "instance: 1, geometry: 1, primitive: 1, hit_kind: 255, attributes: [0.25, 0.5], "
    "sbt_offset: 0, sbt_stride: 1, tmax: 6.5";
const std::string kRecordByIndex =
    "instance: 1, geometry: 0, primitive: 0, hit_kind: 254, attributes: [0.5, 0.125], "
    "sbt_index: 1, tmax: 3.25";

TEST(HitObjectRecord, ARecordedHitHoldsWhatItWasGivenAndItsInstancesRecord) {
  const Results r = runTier(parseInline(recordHitCase(kRecordByOffset)), ModelTier::Exact);
  EXPECT_EQ(r.counters.at("closesthit"), 1u);
  EXPECT_EQ(r.counters.at("miss"), 0u);
  EXPECT_EQ(word(r, 0, "value1"), 3u);   // SBT offset 2 + 0 + geometry 1 x stride 1
  EXPECT_EQ(word(r, 0, "value2"), 7u);   // the instance's custom index
  EXPECT_EQ(word(r, 0, "value3"), 40u);  // record 3's data, through the handle
  EXPECT_EQ(word(r, 0, "value"), 40u);   // record 3's closest-hit ran
  EXPECT_EQ(fword(r, 0, "ray_tmax"), 6.5f);
  EXPECT_EQ(fword(r, 0, "hit_t"), 6.5f);
  EXPECT_EQ(word(r, 0, "primitive_id"), 1u);
  EXPECT_EQ(word(r, 0, "geometry_index"), 1u);
  EXPECT_EQ(word(r, 0, "hit_kind"), 255u);
  EXPECT_EQ(fword(r, 0, "barycentrics", 1), 0.5f);
  EXPECT_EQ(fword(r, 0, "object_ray_origin", 0), -1.0f);  // (1 - 3) / 2
}

TEST(HitObjectRecord, ARecordedHitByIndexRunsThatRecord) {
  const Results r = runTier(parseInline(recordHitCase(kRecordByIndex)), ModelTier::Exact);
  EXPECT_EQ(word(r, 0, "value1"), 1u);
  EXPECT_EQ(word(r, 0, "value3"), 20u);
  EXPECT_EQ(word(r, 0, "value"), 20u);
  EXPECT_EQ(word(r, 0, "hit_kind"), 254u);
}

TEST(HitObjectRecord, EachFaultMovesWhatItBreaks) {
  Case by_offset = parseInline(recordHitCase(kRecordByOffset)),
       by_index = parseInline(recordHitCase(kRecordByIndex));
  ModelOptions o{ModelTier::Exact, 2};
  o.faults.hit_object_record = HitObjectRecordFault::SbtNoInstanceOffset;
  EXPECT_EQ(word(runOnModel(by_offset, derivePlan(by_offset), o), 0, "value"), 20u);
  o.faults.hit_object_record = HitObjectRecordFault::IndexPlusInstanceOffset;
  EXPECT_EQ(word(runOnModel(by_index, derivePlan(by_index), o), 0, "value"), 40u);
  o.faults.hit_object_record = HitObjectRecordFault::CustomIndexIsId;
  EXPECT_EQ(word(runOnModel(by_offset, derivePlan(by_offset), o), 0, "value2"), 1u);
  o.faults.hit_object_record = HitObjectRecordFault::HandleOwn;
  EXPECT_EQ(word(runOnModel(by_offset, derivePlan(by_offset), o), 0, "value3"), 0u);
}

TEST(HitObjectRecord, AHitOutsideTheSceneIsUndefined) {
  const Results r =
      runTier(parseInline(recordHitCase(
                  "instance: 1, geometry: 0, primitive: 1, hit_kind: 254, attributes: "
                  "[0, 0], sbt_offset: 0, sbt_stride: 1")),
              ModelTier::Exact);
  ASSERT_EQ(r.undefined.size(), 1u);
  EXPECT_EQ(r.undefined[0].reason, UndefinedReason::HitObjectRecordOutsideScene);
  EXPECT_EQ(r.counters.at("closesthit"), 0u);
}

TEST(HitObjectRecord, OffsetAndIndexTogetherAndAMissingIdAreErrors) {
  const std::string text = recordHitCase(kRecordByOffset);
  EXPECT_NE(firstErrorAfter(text, "sbt_stride: 1", "sbt_stride: 1, sbt_index: 2").find("not both"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(text, "instance: 1, ", "").find("needs 'instance'"), std::string::npos);
}

}  // namespace
}  // namespace rayspec::model_test
