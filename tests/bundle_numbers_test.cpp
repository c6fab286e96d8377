// Counters, sizes, rays and ids in results.json are unsigned integers, and
// case_hash is the hash as written (issue 56 item 13): 64.9 is no 64, -1 no
// 2^64 - 1, 1e3 no 1000 and 2^64 no 0. Each other value is an error naming
// results.json and the field.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "bundle/results_io.h"
#include "result_support.h"
#include "results/record_layout.h"
#include "temp_dir.h"

namespace rayspec {
namespace {

// A bundle with one of every numbered field: counters, a 2 x 1 launch and
// image, an ambiguous ray and its candidates, bounds, an undefined and a
// repeat-dependent ray.
Results numberedResults() {
  Results r;
  r.case_name = "family/numbers";
  r.backend = "vulkan";
  r.device = "test device";
  r.width = 2;
  r.height = 1;
  r.case_hash = 0x0123456789abcdefull;
  r.counters = {{"miss", 3}};
  r.records.assign(2 * recordWords(), 0);
  r.images.push_back(Image{"primitive", "primitive_id", 2, 1, 1, false, {0, 1}});
  r.ambiguous.push_back({1, AmbiguityReason::Edge, {{true, 0, 0, 1}, {true, 0, 0, 2}}, {}});
  r.t_bounds.push_back({1, 0.25f});
  r.object_origin_bounds.push_back({0, 0.5f});
  r.position_bounds.push_back({1, 0.5f});
  r.undefined.push_back({0, UndefinedReason::RayParameters, "a NaN origin"});
  r.repeat_dependent.push_back({1, 1u << recordFieldIndex("value")});
  return r;
}

// The bundle written, the value at `path` (a JSON pointer) replaced by the
// text `value` as it stands, read back: the error ("" none).
std::string readWithValue(const std::string& dir, const std::string& path,
                          const std::string& value) {
  std::filesystem::remove_all(dir);
  EXPECT_TRUE(writeResults(numberedResults(), dir, {}).ok());
  nlohmann::json j = nlohmann::json::parse(std::ifstream(dir + "/results.json"));
  EXPECT_TRUE(j.contains(nlohmann::json::json_pointer(path))) << path;
  j[nlohmann::json::json_pointer(path)] = "@@value@@";
  std::string text = j.dump(1);
  text.replace(text.find("\"@@value@@\""), 11, value);
  std::ofstream(dir + "/results.json") << text;
  std::string error;
  orError(readResults(dir), &error);
  return error;
}

TEST(ResultsNumbers, TheBundleAsWrittenReadsBack) {
  const std::string dir = freshTempDir("rayspec-results-numbers");
  ASSERT_EQ(readWithValue(dir, "/counters/miss", "3"), "");
  ASSERT_EQ(readWithValue(dir, "/width", "2"), "");
}

TEST(ResultsNumbers, ACounterOrSizeThatIsNoUnsignedIntegerNamesTheField) {
  const std::string dir = freshTempDir("rayspec-results-numbers");
  const std::pair<const char*, const char*> fields[] = {
      {"/counters/miss", "counters.miss"},
      {"/width", "width"},
      {"/height", "height"},
      {"/record_words", "record_words"},
      {"/library_handles_compared", "library_handles_compared"},
      {"/images/0/width", "images.width"},
      {"/images/0/height", "images.height"},
      {"/images/0/channels", "images.channels"},
      {"/ambiguous/0/ray", "ambiguous.ray"},
      {"/ambiguous/0/candidates/1/primitive", "ambiguous.candidates.primitive"},
      {"/ambiguous/0/candidates/1/instance", "ambiguous.candidates.instance"},
      {"/t_bounds/0/ray", "t_bounds.ray"},
      {"/object_origin_bounds/0/ray", "object_origin_bounds.ray"},
      {"/position_bounds/0/ray", "position_bounds.ray"},
      {"/undefined/0/ray", "undefined.ray"},
      {"/repeat_dependent/0/ray", "repeat_dependent.ray"},
  };
  for (const auto& [path, field] : fields)
    for (const std::string value :
         {"64.9", "-1", "1e3", "1.0", "-0", "18446744073709551616", "1e30", "\"3\"", "true"}) {
      const std::string error = readWithValue(dir, path, value);
      EXPECT_NE(error.find(dir + "/results.json"), std::string::npos) << path << " " << value;
      EXPECT_NE(error.find(field), std::string::npos) << path << " = " << value << ": " << error;
    }
}

// An unsigned integer too large for what it counts is refused, naming the
// field and the limit: sizes to 2^30, rays and ids to 2^32 - 1.
TEST(ResultsNumbers, AValueTooLargeForItsFieldNamesTheField) {
  const std::string dir = freshTempDir("rayspec-results-numbers");
  std::string error = readWithValue(dir, "/width", "1073741825");
  EXPECT_NE(error.find("width: 1073741825 is too large (at most 1073741824)"), std::string::npos)
      << error;
  error = readWithValue(dir, "/images/0/channels", "4294967297");
  EXPECT_NE(error.find("images.channels: 4294967297 is too large"), std::string::npos) << error;
  error = readWithValue(dir, "/ambiguous/0/ray", "4294967296");
  EXPECT_NE(error.find("ambiguous.ray: 4294967296 is too large (at most 4294967295)"),
            std::string::npos)
      << error;
  // A counter is 64 bits: the largest reads back as itself.
  EXPECT_EQ(readWithValue(dir, "/counters/miss", "18446744073709551615"), "");
  std::string read_error;
  const Results r = orError(readResults(dir), &read_error);
  EXPECT_EQ(r.counters.at("miss"), 18446744073709551615ull);
}

TEST(ResultsNumbers, ACaseHashIsSixteenLowerCaseHexDigits) {
  const std::string dir = freshTempDir("rayspec-results-numbers");
  EXPECT_EQ(readWithValue(dir, "/case_hash", "\"0123456789abcdef\""), "");
  for (const std::string value :
       {"\"-1\"", "\"0x0123456789abcd\"", "\"0123456789ABCDEF\"", "\"0123456789abcdefff\"",
        "\"123\"", "\" 0123456789abcde\"", "\"0123456789abcdez\""}) {
    const std::string error = readWithValue(dir, "/case_hash", value);
    EXPECT_NE(error.find("results.json: case_hash: "), std::string::npos) << value << ": " << error;
  }
}

}  // namespace
}  // namespace rayspec
