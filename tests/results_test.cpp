// The schema of what an execution produced (results/): the record layout,
// the content hash, the bulk word buffers.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "base/error_bounds.h"
#include "results/content_hash.h"
#include "results/record_layout.h"
#include "results/results.h"
#include "results/tolerances.h"

namespace rayspec {
namespace {

TEST(RecordLayout, FieldsAreContiguousUniqueAndFitTheWrittenMask) {
  std::set<std::string> names;
  uint32_t next = kRecordWrittenMaskWord + kWrittenMaskWords;
  for (const RecordField& f : recordFields()) {
    EXPECT_TRUE(names.insert(f.name).second) << f.name;
    EXPECT_EQ(f.offset, next) << f.name;
    EXPECT_EQ(static_cast<int>(f.index), recordFieldIndex(f.name)) << f.name;
    EXPECT_EQ(&f, &recordFields()[f.index]) << f.name;
    EXPECT_GE(f.words, 1u);
    EXPECT_LE(f.words, 4u);
    next += f.words;
  }
  EXPECT_EQ(recordWords(), next);
  // A recordable field's bit is its index, and the automatic fields (no bit)
  // come after all of them; the mask has a word for every 32 of them.
  bool automatic_seen = false;
  for (const RecordField& f : recordFields()) {
    if (!f.automatic) {
      EXPECT_FALSE(automatic_seen) << f.name;
      EXPECT_LT(f.index, kWrittenFieldCount) << f.name;
    }
    automatic_seen = automatic_seen || f.automatic;
  }
  EXPECT_EQ(kWrittenMaskWords * 32 >= kWrittenFieldCount, true);
  EXPECT_LT((kWrittenMaskWords - 1) * 32, kWrittenFieldCount);
  EXPECT_LE(recordFields().size(), 64u) << "a FieldMask holds every field";
  EXPECT_TRUE(isFreeField("value7"));
  EXPECT_TRUE(isFreeField("value11"));
  EXPECT_TRUE(isFreeField("color3"));
  EXPECT_FALSE(isFreeField("value12"));
  EXPECT_FALSE(isFreeField("hit_t"));
  EXPECT_EQ(recordFieldIndex("hit"), 0);
  EXPECT_EQ(findRecordField("nonsense"), nullptr);
  EXPECT_TRUE(findRecordField("any_hit_runs")->automatic);
  EXPECT_FALSE(findRecordField("hit_t")->automatic);
}

// Each field's written bit: set and read back through one definition, each
// bit its own, none for an automatic field or an unknown one.
TEST(RecordLayout, WrittenBitsAreOnePerRecordableField) {
  for (const RecordField& f : recordFields()) {
    std::vector<uint32_t> rec(recordWords(), 0);
    if (f.automatic) {
      EXPECT_FALSE(written(rec.data(), static_cast<int>(f.index))) << f.name;
      continue;
    }
    markWritten(rec.data(), f.index);
    for (const RecordField& g : recordFields())
      EXPECT_EQ(written(rec.data(), static_cast<int>(g.index)), &g == &f)
          << f.name << " " << g.name;
    std::vector<uint32_t> none(recordWords(), 0);
    EXPECT_FALSE(sameWrittenMask(rec.data(), none.data())) << f.name;
    // The mask lies before the first field: marking moves no field's word.
    for (uint32_t w = kRecordWrittenMaskWord + kWrittenMaskWords; w < recordWords(); ++w)
      EXPECT_EQ(rec[w], 0u) << f.name;
  }
  std::vector<uint32_t> rec(recordWords(), ~0u);
  EXPECT_FALSE(written(rec.data(), -1));
}

// The table's columns as the judge reads them: the rules, tolerances and
// bounds that were written by hand beside it before.
TEST(RecordLayout, TheTableGivesEachFieldItsRuleToleranceAndBound) {
  EXPECT_STREQ(findRecordField("hit")->rule, "R-MISS-XOR-CHIT");
  EXPECT_STREQ(findRecordField("hit_t")->rule, "R-PREC");
  EXPECT_STREQ(findRecordField("color2")->rule, "R-PAYLOAD");
  EXPECT_STREQ(findRecordField("callable_runs")->rule, "R-CALLABLE");
  EXPECT_EQ(toleranceFor("barycentrics").abs, kBarycentricTolerance);
  EXPECT_EQ(toleranceFor("barycentrics").rel, 0.0);
  EXPECT_EQ(toleranceFor("color").abs, kColorTolerance);
  EXPECT_EQ(toleranceFor("hit_t").rel, kFieldTolerance);
  EXPECT_EQ(toleranceFor("color3").abs, kFieldTolerance);  // as before the table
  EXPECT_EQ(toleranceFor("no_such_field").abs, kFieldTolerance);
  EXPECT_EQ(findRecordField("ray_tmax")->bound, FieldBound::TBound);
  EXPECT_EQ(findRecordField("hit_position")->bound, FieldBound::PositionBound);
  EXPECT_EQ(findRecordField("object_ray_origin")->bound, FieldBound::OriginBound);
  EXPECT_TRUE(isHitIdentityField("geometry_index"));
  EXPECT_FALSE(isHitIdentityField("hit_kind"));
  EXPECT_TRUE(traversalDependent(*findRecordField("any_hit_repeats")));
  EXPECT_FALSE(traversalDependent(*findRecordField("miss_runs")));
}

// The any-hit slot: one formula, as numbers.
TEST(RecordLayout, AnyHitSlotIsTheFormulaMod32) {
  EXPECT_EQ(anyHitSlot(0, 0, 0), 0u);
  EXPECT_EQ(anyHitSlot(1, 0, 0), 13u);
  EXPECT_EQ(anyHitSlot(0, 1, 2), 7u);
  EXPECT_EQ(anyHitSlot(2, 1, 7), (26u + 5u + 7u) & 31u);
}

// The hash a bundle records is compared on another machine: it must be the
// same function everywhere (FNV-1a 64, whose published value for "a" this is).
TEST(ContentHash, IsFnv1aAndPrintsAsSixteenHexDigits) {
  EXPECT_EQ(contentHash(""), kContentHashSeed);
  EXPECT_EQ(contentHash("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_NE(contentHash("ab"), contentHash("ba"));
  EXPECT_EQ(contentHashText(0xaf63dc4c8601ec8cull), "af63dc4c8601ec8c");
  EXPECT_EQ(contentHashText(1), "0000000000000001");
}

// A hash read back is the text contentHashText writes, nothing else.
TEST(ContentHash, ReadsBackOnlyWhatItWrites) {
  EXPECT_EQ(contentHashFromText("af63dc4c8601ec8c"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(contentHashFromText(contentHashText(1)), 1u);
  for (const std::string bad : {"", "-1", "0x63dc4c8601ec8c", "AF63DC4C8601EC8C", "af63dc4c8601ec8",
                                "af63dc4c8601ec8c0", " f63dc4c8601ec8c", "af63dc4c8601ec8g"})
    EXPECT_FALSE(contentHashFromText(bad)) << bad;
}

// BulkWords (DefaultInitAllocator): words given a value keep it through a
// resize, grow and copy; assign(n, 0) zeroes; a copy compares equal.
TEST(Results, BulkWordsKeepWhatWasWritten) {
  BulkWords w;
  w.assign(5, 0);
  EXPECT_EQ(w, BulkWords(5, 0u));
  for (uint32_t i = 0; i < 5; ++i) w[i] = 10 + i;
  w.resize(1000);  // the new words are unwritten; the first five stay
  w.resize(3);
  EXPECT_EQ(w, (BulkWords{10, 11, 12}));
  w.push_back(7);
  BulkWords copy = w;
  EXPECT_EQ(copy, (BulkWords{10, 11, 12, 7}));
  copy.assign(4, 0);
  EXPECT_EQ(copy, BulkWords(4, 0u));
}

}  // namespace
}  // namespace rayspec
