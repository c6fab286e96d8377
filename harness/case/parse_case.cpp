// parseCaseFile / parseCaseText: the top level of a case file.
#include "case/parse_case.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "case/case_parts.h"

namespace rayspec {

std::string CaseError::format() const {
  std::ostringstream s;
  s << loc.file << ":" << loc.line << ":" << loc.column << ": ";
  if (!loc.field.empty()) s << loc.field << ": ";
  s << message;
  return s.str();
}

namespace {

void parseRules(YamlReader& r, const YAML::Node& n, std::vector<std::string>& rules) {
  if (!r.expectSeq(n, "rules")) return;
  if (n.size() == 0) r.error(n, "rules", "at least one rule label is required");
  static const std::regex label("R-[A-Z0-9]+(-[A-Z0-9]+)*");
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string f = "rules[" + std::to_string(i) + "]";
    auto s = r.string(n[i], f);
    if (!s) continue;
    if (!std::regex_match(*s, label)) {
      r.error(n[i], f, "'" + *s + "' is not a rule label (R-NAME, see shared/spec-rules.md)");
      continue;
    }
    rules.push_back(*s);
  }
}

void parseTop(YamlReader& r, const YAML::Node& root, Case& c) {
  if (!r.expectMap(root, "", {"rules", "description", "scene", "rays", "pipeline", "outputs"})) return;
  if (r.require(root, "", "rules")) parseRules(r, YamlReader::get(root, "rules"), c.rules);
  if (auto d = YamlReader::get(root, "description"); d.IsDefined())
    if (auto s = r.string(d, "description")) c.description = *s;
  if (auto s = YamlReader::get(root, "scene"); s.IsDefined() && !s.IsNull()) parseScene(r, s, c.scene);
  if (r.require(root, "", "rays")) parseRays(r, YamlReader::get(root, "rays"), c.rays);
  if (auto o = YamlReader::get(root, "outputs"); o.IsDefined() && !o.IsNull()) parseOutputs(r, o, c.outputs);
  const YAML::Node pipeline = YamlReader::get(root, "pipeline");
  parsePipeline(r, pipeline, c.pipeline);
  checkPrograms(r, c, pipeline);
}

}  // namespace

ParseResult parseCaseText(const std::string& yaml, const std::string& file_name, const std::string& name) {
  ParseResult result;
  YamlReader r(file_name, result.errors);
  Case c;
  c.name = name;
  c.file = file_name;
  c.family = name.substr(0, name.find('/'));
  try {
    const YAML::Node root = YAML::Load(yaml);
    if (!root.IsDefined() || root.IsNull()) {
      r.error(SourceLoc{file_name, 1, 1, ""}, "empty case file");
      return result;
    }
    parseTop(r, root, c);
  } catch (const YAML::Exception& e) {
    SourceLoc loc{file_name, e.mark.line >= 0 ? e.mark.line + 1 : 0,
                  e.mark.column >= 0 ? e.mark.column + 1 : 0, ""};
    r.error(loc, e.msg.empty() ? std::string(e.what()) : "malformed YAML: " + e.msg);
  } catch (const std::exception& e) {
    r.error(SourceLoc{file_name, 0, 0, ""}, std::string("internal error while parsing: ") + e.what());
  }
  if (result.errors.empty()) result.value = std::move(c);
  return result;
}

ParseResult parseCaseFile(const std::string& path, const std::string& cases_root) {
  namespace fs = std::filesystem;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    ParseResult result;
    result.errors.push_back({SourceLoc{path, 0, 0, ""}, "cannot open the case file"});
    return result;
  }
  std::stringstream text;
  text << in.rdbuf();
  std::error_code ec;
  fs::path rel = fs::weakly_canonical(path, ec).lexically_relative(fs::weakly_canonical(cases_root, ec));
  if (rel.empty() || *rel.begin() == "..") rel = fs::path(path).filename();
  rel.replace_extension();
  return parseCaseText(text.str(), path, rel.generic_string());
}

}  // namespace rayspec
