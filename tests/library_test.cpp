// Sweep files expand into their variants; case discovery finds them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "library/case_discovery.h"
#include "library/expand_sweep.h"
#include "results/file_name.h"

namespace rayspec {
namespace {

const char* kSweep = R"(sweep:
  name: "o${offset}-${kind}"
  rows:
    - {kind: tri, geometry: "{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}"}
    - {kind: box, geometry: "{aabbs: [[0, 0, 0, 1, 1, 1]]}"}
  product:
    offset: [0, 0x11]
rules: [R-SBT-HIT]
scene:
  blas:
    b: [${geometry}]
  instances: [{blas: b, sbt_offset: ${offset}}]
)";

TEST(ExpandSweep, RowsTimesProductWithValuesSubstituted) {
  const SweepExpansion ex = expandSweep(kSweep, "s.sweep.yaml", "sbt/s");
  ASSERT_TRUE(ex.errors.empty()) << ex.errors[0].format();
  ASSERT_EQ(ex.variants.size(), 4u);
  EXPECT_EQ(ex.variants[0].name, "sbt/s/o0-tri");
  EXPECT_EQ(ex.variants[1].name, "sbt/s/o0x11-tri");
  EXPECT_EQ(ex.variants[3].name, "sbt/s/o0x11-box");
  const std::string& text = ex.variants[3].text;
  EXPECT_NE(text.find("instances: [{blas: b, sbt_offset: 0x11}]"), std::string::npos) << text;
  EXPECT_NE(text.find("b: [{aabbs: [[0, 0, 0, 1, 1, 1]]}]"), std::string::npos) << text;
  // The sweep block is blanked, so the case keeps the file's line numbers.
  EXPECT_EQ(text.find("sweep"), std::string::npos);
  EXPECT_EQ(text.substr(0, 7), "\n\n\n\n\n\n\n");
  EXPECT_EQ(text.find("rules:"), 7u);
}

TEST(ExpandSweep, EachVariantKeepsItsParameters) {
  const SweepExpansion ex = expandSweep(kSweep, "s.sweep.yaml", "sbt/s");
  ASSERT_EQ(ex.variants.size(), 4u);
  using P = std::vector<std::pair<std::string, std::string>>;
  EXPECT_EQ(
      ex.variants[3].params,
      (P{{"kind", "box"}, {"geometry", "{aabbs: [[0, 0, 0, 1, 1, 1]]}"}, {"offset", "0x11"}}));
  EXPECT_EQ(ex.variants[0].params[2], (std::pair<std::string, std::string>{"offset", "0"}));
}

TEST(ExpandSweep, AListValueIsWrittenInFlowStyle) {
  const SweepExpansion ex = expandSweep(
      "sweep:\n  name: v${i}\n  product:\n    d: [[0, 0, -1]]\n    i: [1]\nrays: {direction: "
      "${d}}\n",
      "f.sweep.yaml", "x/f");
  ASSERT_TRUE(ex.errors.empty()) << ex.errors[0].format();
  EXPECT_NE(ex.variants[0].text.find("rays: {direction: [0, 0, -1]}"), std::string::npos)
      << ex.variants[0].text;
}

TEST(ExpandSweep, ValuesMayNameOtherParametersAndNamesMayNest) {
  const SweepExpansion ex = expandSweep(
      "sweep:\n  name: ${order}\n  rows: [{order: up, all: '[${a}, ${b}]'}, {order: down, all: "
      "'[${b}, ${a}]'}]\n  product:\n    a: [1]\n    b: [2]\n    list_up: ['[0, 1]']\n    "
      "list_down: ['[1, 0]']\nx: ${all}\ny: ${list_${order}}\n",
      "f.sweep.yaml", "x/f");
  ASSERT_TRUE(ex.errors.empty()) << ex.errors[0].format();
  ASSERT_EQ(ex.variants.size(), 2u);
  EXPECT_NE(ex.variants[1].text.find("x: [2, 1]\ny: [1, 0]"), std::string::npos)
      << ex.variants[1].text;
  const SweepExpansion loop =
      expandSweep("sweep:\n  name: n\n  product: {a: ['${a}']}\nx: ${a}\n", "f.sweep.yaml", "x/f");
  ASSERT_EQ(loop.errors.size(), 1u);
  EXPECT_NE(loop.errors[0].format().find(
                "f.sweep.yaml:4:1: the parameters' values name each other too deeply"),
            std::string::npos);
}

TEST(ExpandSweep, ASweepTooLargeIsAnErrorNotAnExhaustedMachine) {
  const SweepExpansion many = expandSweep(
      "sweep:\n  name: ${a}${b}${c}${d}\n  product:\n    a: [0, 1, 2, 3, 4, 5, 6, 7, 8, 9]\n    b: "
      "[0, 1, 2, 3, 4, 5, 6, 7, 8, 9]\n    c: [0, 1, 2, 3, 4, 5, 6, 7, 8, 9]\n    d: [0, 1, 2, 3, "
      "4, 5, 6, 7, 8, 9]\n    e: [0, 1]\n",
      "f.sweep.yaml", "x/f");
  ASSERT_EQ(many.errors.size(), 1u);
  EXPECT_EQ(many.errors[0].format(),
            "f.sweep.yaml:2:3: sweep: makes more than 1024 cases; split it");
  std::string doubling = "sweep:\n  name: n\n  product:\n    v0: [x]\n";
  for (int i = 1; i <= 24; ++i)
    doubling += "    v" + std::to_string(i) + ": ['${v" + std::to_string(i - 1) + "}${v" +
                std::to_string(i - 1) + "}']\n";
  const SweepExpansion wide = expandSweep(doubling + "x: ${v24}\n", "f.sweep.yaml", "x/f");
  ASSERT_EQ(wide.errors.size(), 1u);
  EXPECT_EQ(wide.errors[0].format(),
            "f.sweep.yaml:29:1: the parameters' values name each other too deeply (over 10000 "
            "substitutions, or a line over 64 KiB)");
}

TEST(ExpandSweep, ErrorsNameTheFileLineAndField) {
  auto first = [](const std::string& text) {
    const SweepExpansion ex = expandSweep(text, "f.sweep.yaml", "x/f");
    EXPECT_TRUE(ex.variants.empty());
    return ex.errors.empty() ? std::string("no error") : ex.errors[0].format();
  };
  EXPECT_EQ(first("sweep:\n  name: a${b}\n  product: {b: [1]}\nrules: [${c}]\n"),
            "f.sweep.yaml:4:9: '${c}' names no parameter of the sweep (parameters: b)");
  EXPECT_EQ(first("sweep:\n  name: same\n  product: {b: [1, 2]}\nrules: [R-MASK]\n"),
            "f.sweep.yaml:2:9: sweep.name: two variants are both named 'x/f/same': the name must "
            "use every parameter that varies");
  EXPECT_EQ(first("sweep:\n  name: a${b}\n  product: {b: []}\n"),
            "f.sweep.yaml:3:16: sweep.product.b: expected a non-empty list of values");
  EXPECT_EQ(first("sweep:\n  name: a${b}\n  rows: [{b: 1}, {c: 2}]\n"),
            "f.sweep.yaml:3:18: sweep.rows[1]: every row must name the same parameters as row 0");
  EXPECT_EQ(
      first("sweep:\n  name: a\n  prodcut: {b: [1]}\n"),
      "f.sweep.yaml:3:3: sweep: unknown key 'prodcut' (expected one of: name, rows, product)");
  EXPECT_EQ(first("rules: [R-MASK]\n"),
            "f.sweep.yaml:1:1: sweep: a .sweep.yaml file needs a top-level `sweep:` block "
            "(cases/README.md, Sweeps)");
  EXPECT_EQ(first("sweep:\n  name: [\n"),
            "f.sweep.yaml:3:1: sweep: malformed YAML: end of sequence flow not found");
}

// A parameter no variant brings in would make variants that differ in name
// only (or not at all): an error at the block, naming it.
TEST(ExpandSweep, AParameterNeverUsedIsAnError) {
  auto first = [](const std::string& text) {
    const SweepExpansion ex = expandSweep(text, "f.sweep.yaml", "x/f");
    return ex.errors.empty() ? std::string("no error") : ex.errors[0].format();
  };
  EXPECT_EQ(first("sweep:\n  name: a${b}\n  product: {b: [1, 2], c: [3]}\nrules: [R-MASK]\n"),
            "f.sweep.yaml:3:12: sweep.product.c: parameter 'c' is never used: no ${c} in the "
            "case or its name");
  EXPECT_EQ(first("sweep:\n  name: a${b}\n  rows: [{b: 1, c: 2}]\nrules: [R-MASK]\n"),
            "f.sweep.yaml:3:9: sweep.rows: parameter 'c' is never used: no ${c} in the case or "
            "its name");
  EXPECT_EQ(first("sweep:\n  name: a${b}\n  product: {b: ['${c}'], c: [3]}\nrules: [R-MASK]\n"),
            "no error")
      << "a parameter used only inside another's value is used";
}

TEST(CaseDiscovery, SweepVariantsAreCasesAndTheFilterMatchesEitherName) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "rayspec_library_test";
  fs::remove_all(dir);
  fs::create_directories(dir / "sbt");
  std::ofstream(dir / "sbt" / "s.sweep.yaml") << kSweep;
  std::ofstream(dir / "sbt" / "plain.yaml") << "rules: [R-SBT-HIT]\n";
  std::ofstream(dir / "sbt" / "bad.sweep.yaml") << "rules: [R-SBT-HIT]\n";
  const std::vector<CaseFile> all = findCases(dir.string(), "*");
  ASSERT_EQ(all.size(), 6u);
  EXPECT_EQ(all[0].name, "sbt/bad");  // a sweep that does not expand is one case, with its errors
  EXPECT_FALSE(all[0].errors.empty());
  EXPECT_EQ(all[1].name, "sbt/plain");
  EXPECT_EQ(all[2].name, "sbt/s/o0-box");
  EXPECT_TRUE(all[2].generated);
  EXPECT_EQ(findCases(dir.string(), "sbt/s").size(), 4u);
  EXPECT_EQ(findCases(dir.string(), "*-tri").size(), 2u);
  EXPECT_EQ(caseFilesFor((dir / "sbt" / "s.sweep.yaml").string(), dir.string()).size(), 4u);
  const std::optional<CaseFile> one = findCase("sbt/s/o0x11-box", "", dir.string());
  ASSERT_TRUE(one);
  EXPECT_NE(one->text.find("sbt_offset: 0x11"), std::string::npos);
  EXPECT_FALSE(findCase("sbt/s/o2-box", "", dir.string()));
  // Parsing a variant reports at the sweep file's own lines.
  const ParseResult parsed = loadCase(*one, dir.string());
  ASSERT_FALSE(parsed.errors.empty());
  EXPECT_EQ(parsed.errors[0].loc.file, (dir / "sbt" / "s.sweep.yaml").string());
  EXPECT_GE(parsed.errors[0].loc.line, 8);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rayspec

namespace rayspec {
namespace {

// Case names become folders of a run: names two files make, a name that is a
// folder of another case's, an empty sweep variant: each an error naming the
// files, one entry per name (the run had three rows and overwrote bundles).
TEST(CaseDiscovery, ClashingCaseNamesAreErrorsNamingTheFiles) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "rayspec_library_names_test";
  fs::remove_all(dir);
  fs::create_directories(dir / "fam" / "a");
  fs::create_directories(dir / "fam" / "x");
  std::ofstream(dir / "fam" / "a.yaml") << "rules: []\n";
  std::ofstream(dir / "fam" / "a" / "device.yaml")
      << "rules: []\n";                                      // fam/a/device: inside fam/a's folder
  std::ofstream(dir / "fam" / "a-b.yaml") << "rules: []\n";  // sorts between fam/a and fam/a/device
  std::ofstream(dir / "fam" / "x.yaml") << "rules: []\n";
  std::ofstream(dir / "fam" / "x.sweep.yaml")
      << "sweep:\n  name: \"${v}\"\n  product:\n    v: [p, q]\nrules: []\n";
  std::ofstream(dir / "fam" / "e.sweep.yaml")
      << "sweep:\n  name: \"${v}\"\n  product:\n    v: [\"\", r]\nrules: []\n";
  std::ofstream(dir / "fam" / "fine.yaml") << "rules: []\n";
  const std::vector<CaseFile> all = findCases(dir.string(), "*");
  std::map<std::string, std::string> errors;  // name -> its errors
  for (const CaseFile& f : all)
    for (const Error& e : f.errors) errors[f.name] += e.format() + "\n";
  EXPECT_NE(errors["fam/a"].find("is a folder of case 'fam/a/device'"), std::string::npos)
      << errors["fam/a"];
  EXPECT_NE(errors["fam/a/device"].find("lies inside the folder of case 'fam/a'"),
            std::string::npos);
  EXPECT_NE(errors["fam/x"].find("is a folder of case 'fam/x/p'"), std::string::npos)
      << errors["fam/x"];
  // The empty variant's name is none: its error goes under one that is.
  EXPECT_NE(errors["fam/e/_"].find("case name 'fam/e/' is no case name"), std::string::npos)
      << errors["fam/e/_"];
  EXPECT_EQ(errors.count("fam/e/r"), 0u);
  EXPECT_EQ(errors.count("fam/fine"), 0u);
  EXPECT_EQ(errors.count("fam/a-b"), 0u);
  // Two files making one name: one entry, its error naming both.
  std::vector<CaseFile> twice = {CaseFile{"one.yaml", "fam/t"}, CaseFile{"two.yaml", "fam/t"},
                                 CaseFile{"three.yaml", "fam/t"}};
  checkCaseNames(twice);
  ASSERT_EQ(twice.size(), 1u);
  ASSERT_EQ(twice[0].errors.size(), 2u);
  EXPECT_NE(twice[0].errors[0].format().find("is made twice: by one.yaml and by two.yaml"),
            std::string::npos)
      << twice[0].errors[0].format();
  fs::remove_all(dir);
}

// Issue 56: a case file named with a space or with bytes that are not UTF-8
// is a CaseError under a name that is a case name (it becomes summary.json's,
// the journal's and failures.csv's, whose readers refuse any other), the same
// in every run of the folder; its error names the file as text can show it.
TEST(CaseDiscovery, ABadlyNamedCaseFileIsAnErrorUnderANameThatIsOne) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "rayspec_library_bad_names_test";
  fs::remove_all(dir);
  fs::create_directories(dir / "fam");
  for (const char* name : {"my case", "bad\xff", "fine"})
    std::ofstream(dir / "fam" / (std::string(name) + ".yaml")) << "rules: []\n";
  std::map<std::string, std::string> errors;  // name -> its errors
  for (const CaseFile& f : findCases(dir.string(), "*")) {
    EXPECT_EQ(caseNameProblem(f.name), "") << f.name;
    for (const Error& e : f.errors) errors[f.name] += e.format();
  }
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NE(errors["fam/my_x20case"].find((dir / "fam/my case.yaml").string() +
                                          ":0:0: name: case name 'fam/my case' is no case name"),
            std::string::npos)
      << errors["fam/my_x20case"];
  EXPECT_NE(errors["fam/bad_xFF"].find((dir / "fam/bad\\xFF.yaml").string() +
                                       ":0:0: name: case name 'fam/bad\\xFF' is no case name"),
            std::string::npos)
      << errors["fam/bad_xFF"];
  EXPECT_NE(errors["fam/bad_xFF"].find("reported as 'fam/bad_xFF'"), std::string::npos);
  EXPECT_EQ(findCases(dir.string(), "fam/my_x20case").size(), 1u) << "found by the name it has";
  fs::remove_all(dir);
}

// A later variant is checked as the first: a line it makes over 64 KiB, or a
// value that brings itself back, is an error (it lost the line silently).
TEST(ExpandSweep, EveryVariantIsCheckedNotOnlyTheFirst) {
  const std::string big(70 << 10, 'x');
  const std::string long_line =
      "sweep:\n  name: \"n${i}\"\n  rows:\n    - {i: 0, v: a}\n    - {i: 1, v: " + big +
      "}\nrules: [R-${v}]\n";
  SweepExpansion ex = expandSweep(long_line, "long.sweep.yaml", "fam/long");
  ASSERT_FALSE(ex.errors.empty());
  EXPECT_NE(ex.errors[0].format().find("long.sweep.yaml:6:"), std::string::npos)
      << ex.errors[0].format();
  EXPECT_NE(ex.errors[0].format().find("(in variant fam/long/n1)"), std::string::npos)
      << ex.errors[0].format();
  EXPECT_TRUE(ex.variants.empty());
  const std::string self =
      "sweep:\n  name: \"${w}\"\n  product:\n    w: [p, \"${w}q\"]\nrules: [R-${w}]\n";
  ex = expandSweep(self, "self.sweep.yaml", "fam/self");
  ASSERT_FALSE(ex.errors.empty());
  EXPECT_NE(ex.errors[0].format().find("name each other too deeply"), std::string::npos)
      << ex.errors[0].format();
  // A ${...} that only a later variant's value brings, naming no parameter.
  const std::string later =
      "sweep:\n  name: \"${u}\"\n  product:\n    u: [p, \"${nope}\"]\nrules: [R-${u}]\n";
  ex = expandSweep(later, "later.sweep.yaml", "fam/later");
  ASSERT_FALSE(ex.errors.empty());
  EXPECT_NE(ex.errors[0].format().find("'${nope}' names no parameter of the sweep"),
            std::string::npos)
      << ex.errors[0].format();
}

}  // namespace
}  // namespace rayspec
