// The CTS's own ray tracing Amber scripts, rewritten as cases (cases/cts-amber/):
// each case file names the numbers of its script's EXPECT line in a comment,
//   # cts-expect: FIELD [FIELD ...] = V0 V1 ...
// one value per launch ray and field, in launch order (the fields of one ray
// together, as written), and the model's exact tier must
// give exactly those (a field no stage wrote reads 0, as the script's images
// start filled with 0). FIELD may also be `round(100*barycentrics.x)`: the
// model's barycentric x times 100, rounded half to even (barycentrics.amber).
// A script without an EXPECT line is marked `# cts-expect: none (why)`: its
// case must still parse and run on the model. A change to the model that
// breaks agreement with the CTS fails here.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <fstream>
#include <sstream>

#include "model/model_engine.h"
#include "plan/plan.h"
#include "results/record_layout.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

struct CtsExpect {
  std::vector<std::string> fields;
  std::vector<std::string> values;
};

// The `# cts-expect:` line of a case file; an empty field when there is none.
CtsExpect ctsExpect(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  const std::string tag = "# cts-expect:";
  while (std::getline(in, line)) {
    if (line.rfind(tag, 0) != 0) continue;
    std::istringstream s(line.substr(tag.size()));
    CtsExpect e;
    std::string v;
    while (s >> v && v != "=") e.fields.push_back(v);
    while (s >> v) e.values.push_back(v);
    return e;
  }
  return {};
}

const std::string kRoundedBarycentric = "round(100*barycentrics.x)";

// The field of ray `ray` as the script's image would hold it.
bool sameAsExpected(const std::string& field, const uint32_t* rec, const std::string& expected) {
  if (field == kRoundedBarycentric) {
    const float x = std::bit_cast<float>(rec[findRecordField("barycentrics")->offset]);
    return std::nearbyint(x * 100.0f) == std::stof(expected);
  }
  const RecordField& f = *findRecordField(field);
  const uint32_t word = rec[f.offset];
  if (f.type == FieldType::Float) return std::bit_cast<float>(word) == std::stof(expected);
  return word == static_cast<uint32_t>(std::stoul(expected));
}

TEST(CtsAmber, TheModelGivesEachScriptsExpectedValues) {
  size_t ported = 0;
  for (const CaseFile& file : suiteCases()) {
    if (file.name.rfind("cts-amber/", 0) != 0) continue;
    ++ported;
    const CtsExpect e = ctsExpect(file.path);
    ASSERT_FALSE(e.fields.empty()) << file.path << ": no `# cts-expect: FIELD = ...` line";
    if (e.fields[0] == "none") {
      const ParseResult parsed = loadSuiteCase(file);
      ASSERT_TRUE(parsed.value) << file.name;
      const Results r = runOnModel(*parsed.value, derivePlan(*parsed.value), ModelOptions{});
      EXPECT_TRUE(r.ok()) << file.name << ": " << r.statusText();
      continue;
    }
    for (const std::string& field : e.fields)
      ASSERT_TRUE(field == kRoundedBarycentric || findRecordField(field))
          << file.path << ": unknown field " << field;
    const ParseResult parsed = loadSuiteCase(file);
    ASSERT_TRUE(parsed.value) << file.name;
    const Results r = runOnModel(*parsed.value, derivePlan(*parsed.value), ModelOptions{});
    ASSERT_TRUE(r.ok()) << file.name << ": " << r.statusText();
    const uint32_t words = recordWords();
    const size_t per_ray = e.fields.size();
    ASSERT_EQ(r.records.size() / words * per_ray, e.values.size())
        << file.name << ": one value a ray and field";
    for (size_t i = 0; i < e.values.size(); ++i) {
      const std::string& field = e.fields[i % per_ray];
      EXPECT_TRUE(sameAsExpected(field, &r.records[i / per_ray * words], e.values[i]))
          << file.name << " ray " << i / per_ray << ": " << field << " is not " << e.values[i];
    }
  }
  EXPECT_GE(ported, 8u) << "cases/cts-amber/ holds fewer scripts than were ported";
}

}  // namespace
}  // namespace rayspec
