// The schema of what an execution produced (results/): the record layout,
// the content hash, the bulk word buffers.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "results/content_hash.h"
#include "results/record_layout.h"
#include "results/results.h"

namespace rayspec {
namespace {

TEST(RecordLayout, FieldsAreContiguousUniqueAndFitTheWrittenMask) {
  std::set<std::string> names;
  uint32_t next = kRecordWrittenMaskWord + 1;
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
  // The written mask is one 32-bit word: a recordable field's bit is its
  // index, and the automatic fields (no bit) come after all of them.
  bool automatic_seen = false;
  for (const RecordField& f : recordFields()) {
    if (!f.automatic) {
      EXPECT_FALSE(automatic_seen) << f.name;
      EXPECT_LT(f.index, 32u) << f.name;
    }
    automatic_seen = automatic_seen || f.automatic;
  }
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
