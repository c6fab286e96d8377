// parseCaseFile / parseCaseText: the top level of a case file.
#include "parse/parse_case.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/visible_text.h"
#include "base/whole_file.h"
#include "case/ray_query_inlining.h"
#include "parse/parse_parts.h"
#include "parse/yaml_shape.h"
#include "results/content_hash.h"
#include "results/file_name.h"
#include "results/record_layout.h"

namespace rayspec {

namespace {

// A rule label: "R-", then words of capitals and digits joined by single
// '-' (R-AHIT-DUP), at most 64 characters. A plain scanner: no regular
// expression runs on input text.
bool isRuleLabel(const std::string& s) {
  if (s.size() > 64 || s.rfind("R-", 0) != 0) return false;
  bool word = false;  // the current word has a character
  for (size_t i = 2; i < s.size(); ++i) {
    const char c = s[i];
    if ((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9')) {
      word = true;
    } else if (c == '-' && word) {
      word = false;
    } else {
      return false;
    }
  }
  return word;
}

void parseRules(YamlReader& r, const YAML::Node& n, const std::vector<std::string>* catalog,
                std::vector<std::string>& rules) {
  if (!r.expectSeq(n, "rules")) return;
  if (n.size() == 0) r.error(n, "rules", "at least one rule label is required");
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string f = "rules[" + std::to_string(i) + "]";
    auto s = r.string(n[i], f);
    if (!s) continue;
    if (!isRuleLabel(*s)) {
      r.error(n[i], f,
              "'" + visibleText(*s, 80) +
                  "' is not a rule label (R-NAME, see references/spec-rules.yaml)");
      continue;
    }
    if (catalog && std::find(catalog->begin(), catalog->end(), *s) == catalog->end()) {
      r.error(
          n[i], f,
          "unknown rule label '" + *s + "' (not in the rule catalog, references/spec-rules.yaml)");
      continue;
    }
    rules.push_back(*s);
  }
}

// Undefined behaviour the parser found (R-UB): in a robustness probe (a case
// that claims R-UB) it is what the case is about, kept for `show`; in any other
// case it is an error at the field that causes it.
void judgeStaticUndefined(YamlReader& r, Case& c) {
  if (c.claims("R-UB")) {
    c.static_undefined = r.undefinedBehaviour();
    return;
  }
  for (const StaticUndefined& u : r.undefinedBehaviour())
    r.error(u.loc, u.message + " [" + undefinedReasonName(u.reason) +
                       "; fix the case, or claim R-UB to make it a robustness probe]");
}

// The case's name becomes folder names of a run (OUT/<family>/<name>/).
// pipeline.traces: ray_query in a case its ray query form cannot express.
void checkRayQueryForm(YamlReader& r, const Case& c, const YAML::Node& pipeline) {
  if (!c.pipeline.ray_query && !c.pipeline.ray_query_in_hit) return;
  const std::string why =
      c.pipeline.ray_query ? rayQueryObstacle(c, true) : rayQueryInHitObstacle(c, true);
  if (!why.empty())
    r.error(YamlReader::get(pipeline, "traces"), "pipeline.traces",
            std::string(c.pipeline.ray_query ? "ray_query" : "ray_query_in_hit") +
                " cannot express this case: " + why);
}

void checkCaseName(YamlReader& r, const Case& c) {
  std::string part;
  std::istringstream parts(c.name);
  while (std::getline(parts, part, '/'))
    if (const std::string problem = fileNameProblem(part); !problem.empty())
      r.error(SourceLoc{c.file, 1, 1, "case name"},
              "'" + c.name + "' cannot name a results folder: '" + part + "' " + problem);
}

// The bytes the launch's per-ray records and images take (each image at most
// 4 words a texel), against kMaxOutputBytes: a case that would make the run
// hold more is refused before anything is allocated.
void checkOutputBytes(YamlReader& r, const YAML::Node& outputs, const Case& c) {
  const uint64_t rays = c.rays.launchRays();
  const uint64_t record_bytes = c.outputs.per_ray.empty() ? 0 : rays * recordWords() * 4;
  const uint64_t image_bytes = c.outputs.images.size() * rays * 16;
  if (record_bytes + image_bytes <= kMaxOutputBytes) return;
  r.error(outputs, "outputs",
          "the launch's " + std::to_string(rays) + " rays would write " +
              std::to_string((record_bytes + image_bytes) >> 20) +
              " MiB of per-ray records and images: at most 1 GiB (docs/robustness.md, "
              "Limits); record fewer rays, or only counters");
}

// expect_rejected: [shader names] (R-STAGE-INTERFACE); checkPrograms finds
// what each does that its stage cannot.
void parseExpectedRejections(YamlReader& r, const YAML::Node& n, Case& c) {
  if (!r.expectSeq(n, "expect_rejected")) return;
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string f = "expect_rejected[" + std::to_string(i) + "]";
    if (auto name = r.string(n[i], f)) c.expected_rejections.push_back({*name, {}, r.loc(n[i], f)});
  }
  if (!c.claims("R-STAGE-INTERFACE"))
    r.error(n, "expect_rejected",
            "a case that expects a rejection claims R-STAGE-INTERFACE (and runs no launch)");
}

void parseTop(YamlReader& r, const YAML::Node& root, const std::vector<std::string>* catalog,
              Case& c) {
  r.checkDuplicateKeys(root);
  if (!r.expectMap(
          root, "",
          {"rules", "description", "scene", "rays", "pipeline", "outputs", "expect_rejected"}))
    return;
  if (r.require(root, "", "rules")) parseRules(r, YamlReader::get(root, "rules"), catalog, c.rules);
  if (auto d = YamlReader::get(root, "description"); d.IsDefined())
    if (auto s = r.string(d, "description")) c.description = *s;
  if (auto s = YamlReader::get(root, "scene"); s.IsDefined() && !s.IsNull())
    parseScene(r, s, c.scene);
  if (r.require(root, "", "rays")) parseRays(r, YamlReader::get(root, "rays"), c.scene, c.rays);
  if (const YAML::Node s = YamlReader::get(root, "scene"); s.IsMap() && YamlReader::has(s, "split"))
    parseSceneSplit(r, YamlReader::get(s, "split"), c.scene);
  if (auto o = YamlReader::get(root, "outputs"); o.IsDefined() && !o.IsNull()) {
    parseOutputs(r, o, c.outputs);
    if (!c.outputs.images.empty() && c.rays.rays.empty() && r.errorCount() == 0)
      r.error(c.outputs.images[0].loc,
              "a launch with a zero dimension (rays.launch) has no texels for an image");
    checkOutputBytes(r, o, c);
  }
  const YAML::Node pipeline = YamlReader::get(root, "pipeline");
  parsePipeline(r, pipeline, c.pipeline);
  if (auto e = YamlReader::get(root, "expect_rejected"); e.IsDefined())
    parseExpectedRejections(r, e, c);
  checkPrograms(r, c, pipeline);
  checkRayQueryForm(r, c, pipeline);
  checkRecordReads(r, c);
  checkRecordHits(r, c);
  checkDataWords(r, c);
  checkWideLaunch(r, c);
  checkEmptyLayout(r, c, pipeline);
  if (r.errorCount() == 0) checkTraceConstants(r, c);
  judgeStaticUndefined(r, c);
}

}  // namespace

std::string caseFamily(const std::string& name) {
  const size_t slash = name.find('/');
  return slash == std::string::npos ? std::string() : name.substr(0, slash);
}

ParseResult parseCaseText(const std::string& yaml, const std::string& file_name,
                          const std::string& name, const std::vector<std::string>* catalog) {
  ParseResult result;
  YamlReader r(file_name, result.errors);
  Case c;
  c.name = name;
  c.file = file_name;
  c.source_hash = contentHash(yaml);
  c.family = caseFamily(name);
  checkCaseName(r, c);
  auto at = [&](const YAML::Mark& m) {
    return SourceLoc{file_name, m.line >= 0 ? m.line + 1 : 1, m.column >= 0 ? m.column + 1 : 1, ""};
  };
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::DeepRecursion& e) {
    r.error(at(e.mark), yamlTooDeepMessage());
    return result;
  } catch (const YAML::Exception& e) {
    r.error(at(e.mark), "malformed YAML: " + (e.msg.empty() ? std::string(e.what()) : e.msg) +
                            " (expected YAML syntax: `key: value` maps, `- item` or [a, b] lists)");
    return result;
  }
  if (const auto problem = yamlShapeProblem(root)) {
    r.error(at(problem->mark), problem->message);
    return result;
  }
  if (!root.IsDefined() || root.IsNull()) {
    r.error(SourceLoc{file_name, 1, 1, ""},
            "empty case file (expected a map: rules, scene, rays, pipeline, outputs)");
    return result;
  }
  try {
    parseTop(r, root, catalog, c);
  } catch (const YAML::Exception& e) {
    // A value of a shape the reader did not expect (yaml-cpp throws on some):
    // reported at the field being read.
    SourceLoc loc = at(e.mark);
    loc.field = r.lastField();
    r.error(loc, "unexpected value (" + (e.msg.empty() ? std::string(e.what()) : e.msg) +
                     "): see cases/README.md for what this field holds");
  } catch (const std::exception& e) {
    r.error(SourceLoc{file_name, 1, 1, r.lastField()},
            std::string("internal error while parsing: ") + e.what());
  }
  result.undefined = r.undefinedBehaviour();
  if (result.errors.empty()) result.value = std::move(c);
  return result;
}

ParseResult parseCaseFile(const std::string& path, const std::string& cases_root,
                          const std::vector<std::string>* catalog) {
  namespace fs = std::filesystem;
  const Result<std::string> text = readWholeFile(path, kMaxCaseFileBytes);
  if (!text) {
    ParseResult result;
    result.errors.push_back(text.error());
    return result;
  }
  std::error_code ec;
  fs::path rel =
      fs::weakly_canonical(path, ec).lexically_relative(fs::weakly_canonical(cases_root, ec));
  if (rel.empty() || *rel.begin() == "..") rel = fs::path(path).filename();
  rel.replace_extension();
  return parseCaseText(*text, path, rel.generic_string(), catalog);
}

}  // namespace rayspec
