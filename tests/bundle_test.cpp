// Results bundles on disk (bundle/results_io.h, image_files.h): every field
// round-trips, bad bundles are clear errors.
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <set>

#include "bundle/image_files.h"
#include "bundle/results_io.h"
#include "result_support.h"
#include "results/record_layout.h"
#include "temp_dir.h"
#include "test_dir.h"

namespace rayspec {
namespace {

Results sampleResults() {
  Results r;
  r.case_name = "family/sample";
  r.backend = "vulkan";
  r.device = "test device";
  r.width = 3;
  r.height = 2;
  r.seconds = 0.25;
  r.case_hash = 0xfedcba9876543210ull;
  r.counters = {{"miss", 4}, {"closesthit", 2}};
  r.records.assign(6 * recordWords(), 0);
  const RecordField* t = findRecordField("hit_t");
  r.records[recordWords() + t->offset] = std::bit_cast<uint32_t>(1.5f);
  markWritten(&r.records[recordWords()], t->index);
  Image im{"primitive", "primitive_id", 3, 2, 1, false, {0, 1, 2, 3, 4, 5}};
  r.images.push_back(im);
  Image color{"color", "color", 3, 2, 4, true, BulkWords(24, 0x3f800000u)};
  r.images.push_back(color);
  r.ambiguous.push_back({4,
                         AmbiguityReason::Edge,
                         {{true, 0, 0, 1}, {true, 0, 0, 2}},
                         {{true, 0, 0, 1}, {true, 0, 0, 2}}});
  // Two replays of ray 4's legal answers: the second moves "miss" down by one.
  std::vector<uint32_t> replay(recordWords(), 0);
  replay[findRecordField("hit_t")->offset] = std::bit_cast<uint32_t>(2.5f);
  r.ambiguous[0].replays = {{replay, {}},
                            {std::vector<uint32_t>(recordWords(), 7), {{"miss", -1}}}};
  r.ambiguous[0].from_query = true;
  r.t_bounds.push_back({5, 0.25f});
  r.object_origin_bounds.push_back({3, 0.0625f});
  r.position_bounds.push_back({4, 0.125f});
  r.repeat_dependent.push_back(
      {2, (1u << recordFieldIndex("value")) | (1u << recordFieldIndex("color"))});
  r.repeat_counters = {"miss"};
  r.order_dependent = {"the ray_queries at a.yaml:3 (x): y"};
  r.endless_restarts = {"the restart_query at a.yaml:4: z"};
  return r;
}

TEST(ResultsIo, BundleRoundTripsEveryField) {
  const std::string dir = testing::TempDir() + "/rayspec-results-io";
  std::filesystem::remove_all(dir);
  Results r = sampleResults();
  // A double-hit replay (RayAmbiguity::double_replays) after the two.
  r.ambiguous[0].double_replays = {{std::vector<uint32_t>(recordWords(), 9), {{"miss", 2}}}};
  ASSERT_TRUE(writeResults(r, dir, {"hit_t"}).ok());
  std::string error;
  const Results back = orError(readResults(dir), &error);
  ASSERT_EQ(error, "");
  EXPECT_EQ(back.case_name, r.case_name);
  EXPECT_EQ(back.device, r.device);
  EXPECT_EQ(back.case_hash, r.case_hash);
  EXPECT_EQ(back.counters, r.counters);
  EXPECT_EQ(back.records, r.records);
  ASSERT_EQ(back.images.size(), 2u);
  EXPECT_EQ(back.images[0].texels, r.images[0].texels);
  EXPECT_TRUE(back.images[1].is_float);
  ASSERT_EQ(back.ambiguous.size(), 1u);
  EXPECT_EQ(back.ambiguous[0].candidates.size(), 2u);
  EXPECT_EQ(back.ambiguous[0].candidates[1].primitive, 2u);
  EXPECT_EQ(back.ambiguous[0].shared_triangles.size(), 2u);
  EXPECT_EQ(back.ambiguous[0].replays, r.ambiguous[0].replays);
  EXPECT_EQ(back.ambiguous[0].double_replays, r.ambiguous[0].double_replays);
  EXPECT_TRUE(back.ambiguous[0].from_query);
  ASSERT_EQ(back.repeat_dependent.size(), 1u);
  EXPECT_EQ(back.repeat_dependent[0].ray, 2u);
  EXPECT_EQ(back.repeat_dependent[0].fields, r.repeat_dependent[0].fields);
  EXPECT_EQ(back.repeat_counters, r.repeat_counters);
  EXPECT_EQ(back.order_dependent, r.order_dependent);
  EXPECT_EQ(back.endless_restarts, r.endless_restarts);
  ASSERT_EQ(back.t_bounds.size(), 1u);
  EXPECT_EQ(back.t_bounds[0].ray, 5u);
  EXPECT_EQ(back.t_bounds[0].bound, 0.25f);
  ASSERT_EQ(back.object_origin_bounds.size(), 1u);
  EXPECT_EQ(back.object_origin_bounds[0].ray, 3u);
  EXPECT_EQ(back.object_origin_bounds[0].bound, 0.0625f);
  ASSERT_EQ(back.position_bounds.size(), 1u);
  EXPECT_EQ(back.position_bounds[0].ray, 4u);
  EXPECT_EQ(back.position_bounds[0].bound, 0.125f);
  // records.csv: header + one row per ray, the written hit_t shown, unwritten empty.
  std::ifstream csv(dir + "/records.csv");
  std::string header, row0, row1;
  std::getline(csv, header);
  std::getline(csv, row0);
  std::getline(csv, row1);
  EXPECT_EQ(header.rfind("x,y,hit_t,", 0), 0u) << header;
  EXPECT_EQ(row0.rfind("0,0,,", 0), 0u) << row0;
  EXPECT_EQ(row1.rfind("1,0,1.5,", 0), 0u) << row1;
  if (imageFilesSupported()) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/primitive.png"));
    EXPECT_TRUE(std::filesystem::exists(dir + "/color.exr"));
  }
}

// The difference picture of two images: written where they differ; a file
// that cannot be written is the harness's error (none without OpenImageIO).
TEST(ImageFiles, DiffImageIsWrittenOrItsErrorSaid) {
  Image a;
  a.name = "color";
  a.width = 2;
  a.height = 1;
  a.channels = 1;
  a.texels = {1, 2};
  Image b = a;
  b.texels = {1, 3};
  const std::string dir = testing_support::testDir() + "/diff-image";
  std::filesystem::remove_all(dir);
  ASSERT_EQ(errorText(writeDiffImage(a, b, dir)), "");
  EXPECT_EQ(std::filesystem::exists(dir + "/color.png"), imageFilesSupported());
  const Result<void> nowhere = writeDiffImage(a, b, "/dev/null/diff");
  EXPECT_EQ(nowhere.ok(), !imageFilesSupported());
  if (!nowhere) {
    EXPECT_EQ(nowhere.error().kind, ErrorKind::Harness);
    EXPECT_NE(nowhere.error().message.find("/dev/null/diff/color.png"), std::string::npos)
        << nowhere.error().message;
  }
}

// A saved bundle is input: a value of the wrong type names its field, a file
// of the wrong size names the file and both sizes, a name that would climb out
// of the bundle is refused before any file of that name is read.
// results.json is input too: one over its limit is refused, before it is
// read, by the error naming it.
TEST(ResultsIo, AResultsJsonOverItsLimitIsRefused) {
  const std::string dir = freshTempDir("rayspec-results-huge");
  sparseFile(dir + "/results.json", kMaxResultsJsonBytes + 1);
  std::string error;
  orError(readResults(dir), &error);
  EXPECT_NE(error.find(dir + "/results.json: "), std::string::npos) << error;
  EXPECT_NE(error.find("more than the"), std::string::npos) << error;
}

TEST(ResultsIo, BadBundlesNameTheFieldOrFile) {
  const std::string dir = testing::TempDir() + "/rayspec-results-bad";
  const auto edited = [&](const std::string& from, const std::string& to) {
    std::filesystem::remove_all(dir);
    EXPECT_TRUE(writeResults(sampleResults(), dir, {"hit_t"}).ok());
    std::ifstream in(dir + "/results.json");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    std::ofstream(dir + "/results.json") << text;
    std::string error;
    orError(readResults(dir), &error);
    return error;
  };
  EXPECT_NE(
      edited("\"seconds\": 0.25", "\"seconds\": \"soon\"").find("results.json: field 'seconds': "),
      std::string::npos);
  EXPECT_NE(edited("\"channels\": 4", "\"channels\": true")
                .find("results.json: images.channels: true is no unsigned integer"),
            std::string::npos);
  EXPECT_NE(edited("\"fields\": [\n", "\"fields\": [\"no_such_field\",\n")
                .find("unknown field 'no_such_field'"),
            std::string::npos);
  EXPECT_NE(edited("\"name\": \"color\"", "\"name\": \"../color\"")
                .find("images: name '../color' holds '/'"),
            std::string::npos);
  EXPECT_NE(
      edited("\"case\": \"family/sample\"", "\"case\": \"/etc\"").find("'/etc' is no case name"),
      std::string::npos);
  EXPECT_NE(edited("\"miss\": -1", "\"hit\": -1")
                .find("ambiguous.replays.counter_moves.hit: no such counter"),
            std::string::npos);
  EXPECT_NE(edited("\"miss\": -1", "\"miss\": 18446744073709551615")
                .find("ambiguous.replays.counter_moves.miss: not a signed 64-bit integer"),
            std::string::npos);
  // replays.bin one word short.
  edited("\"width\": 3", "\"width\": 3");
  std::filesystem::resize_file(dir + "/replays.bin",
                               std::filesystem::file_size(dir + "/replays.bin") - 4);
  std::string replay_error;
  orError(readResults(dir), &replay_error);
  EXPECT_NE(replay_error.find("replays.bin holds " + std::to_string(2 * recordWords() * 4 - 4) +
                              " bytes; results.json says replays x record words 2 x"),
            std::string::npos)
      << replay_error;
  // records.bin one word short.
  edited("\"width\": 3", "\"width\": 3");
  std::filesystem::resize_file(dir + "/records.bin",
                               std::filesystem::file_size(dir + "/records.bin") - 4);
  std::string error;
  orError(readResults(dir), &error);
  EXPECT_NE(error.find("records.bin holds " + std::to_string(6 * recordWords() * 4 - 4) +
                       " bytes; results.json says width x height x record words 3 x 2 x"),
            std::string::npos)
      << error;
}

// An image whose width x height x channels x 4 bytes wraps 64 bits (issue
// 44: 2^30 x 2^30 x 4 channels matched an empty .raw) is an error, as is a
// channel count no image has.
TEST(ResultsIo, ImageSizesThatWrapAreErrors) {
  const std::string dir = testing::TempDir() + "/rayspec-results-wrap";
  const auto edited = [&](uint64_t width, uint64_t height, uint64_t channels) {
    std::filesystem::remove_all(dir);
    EXPECT_TRUE(writeResults(sampleResults(), dir, {}).ok());
    nlohmann::json j = nlohmann::json::parse(std::ifstream(dir + "/results.json"));
    j["images"][1]["width"] = width;
    j["images"][1]["height"] = height;
    j["images"][1]["channels"] = channels;
    std::ofstream(dir + "/results.json") << j.dump();
    std::filesystem::resize_file(dir + "/color.raw", 0);
    std::string error;
    orError(readResults(dir), &error);
    return error;
  };
  EXPECT_NE(edited(1u << 30, 1u << 30, 4).find("more words than a file can hold"),
            std::string::npos);
  EXPECT_NE(edited(1u << 30, 1u << 30, 1).find("color.raw holds 0 bytes"), std::string::npos);
  EXPECT_NE(edited(3, 2, 5).find("1 to 4 channels"), std::string::npos);
  EXPECT_NE(edited(3, 2, 0).find("1 to 4 channels"), std::string::npos);
}

TEST(ResultsIo, MissingBundleIsAnError) {
  std::string error;
  orError(readResults("/nonexistent/rayspec"), &error);
  EXPECT_NE(error.find("results.json"), std::string::npos);
}

TEST(ResultsIo, PreviewGivesDistinctColoursToIdsAndBlackToZero) {
  Image im{"p", "primitive_id", 3, 1, 1, false, {0, 1, 2}};
  const auto px = previewPixels(im);
  ASSERT_EQ(px.size(), 12u);
  EXPECT_EQ(px[0] + px[1] + px[2], 0);
  EXPECT_NE(std::memcmp(&px[4], &px[8], 3), 0);
}

}  // namespace
}  // namespace rayspec
