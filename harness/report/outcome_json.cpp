#include "report/outcome_json.h"

#include <filesystem>
#include <fstream>

#include "base/visible_text.h"
#include "base/whole_file.h"
#include "report/case_cost.h"
#include "report/case_journal.h"
#include "results/file_name.h"

namespace rayspec {
namespace {

constexpr BaselineMatch kMatches[] = {BaselineMatch::None,           BaselineMatch::Expected,
                                      BaselineMatch::UnexpectedPass, BaselineMatch::KnownFlake,
                                      BaselineMatch::Flake,          BaselineMatch::Skipped};

Result<Status> statusField(const nlohmann::json& j, const char* key) {
  Status s;
  if (!parseStatus(j.at(key).get<std::string>(), &s))
    return errorMessage(std::string("'") + key + "' is not a status: " + j.at(key).dump());
  return s;
}

// The verdict's findings and undefined rays, and the failing rays.
Result<void> outcomeVerdict(const nlohmann::json& j, CaseOutcome& o) {
  for (const nlohmann::json& f : j.at("findings")) {
    RAYSPEC_TRY(const Status status, statusField(f, "status"));
    o.verdict.findings.push_back(
        {status, f.at("rule").get<std::string>(), f.at("message").get<std::string>(),
         f.at("rays").get<std::vector<uint32_t>>(), f.at("ray_count").get<uint32_t>(),
         f.value("evidence", std::vector<std::string>{})});
  }
  for (const nlohmann::json& u : j.at("undefined")) {
    UndefinedRays r;
    if (!parseUndefinedReason(u.at("reason").get<std::string>(), &r.reason))
      return errorMessage("'reason' is not an undefined-behaviour reason: " +
                          u.at("reason").dump());
    r.ray_count = u.at("ray_count").get<uint32_t>();
    r.rays = u.at("rays").get<std::vector<uint32_t>>();
    r.what = u.at("what").get<std::string>();
    o.verdict.undefined.push_back(r);
  }
  for (const nlohmann::json& r : j.value("failing_rays", nlohmann::json::array()))
    o.failing_rays.push_back({r.at("ray").get<uint32_t>(), r.at("x").get<uint32_t>(),
                              r.at("y").get<uint32_t>(), r.at("field").get<std::string>(),
                              r.at("device").get<std::string>(), r.at("model").get<std::string>()});
  return {};
}

// Every field but the name. nlohmann-json's exceptions (a missing field, a
// value of the wrong type) go to outcomeFromJson, which catches them.
Result<void> outcomeFields(const nlohmann::json& j, CaseOutcome& o) {
  RAYSPEC_TRY(o.status, statusField(j, "status"));
  o.headline = j.at("headline").get<std::string>();
  o.seconds = j.at("seconds").get<double>();
  o.device_seconds = j.at("device_seconds").get<double>();
  o.model_seconds = j.at("model_seconds").get<double>();
  o.rules = j.at("rules").get<std::vector<std::string>>();
  const std::string match = j.value("baseline", "");
  bool known = false;
  for (BaselineMatch m : kMatches)
    if (match == baselineMatchName(m)) o.baseline = m, known = true;
  if (!known) return errorMessage("'baseline' is not a baseline result: " + match);
  o.baseline_note = visibleLine(j.value("baseline_note", ""));  // a note is one line
  o.device_name = j.value("device_name", "");
  o.images = j.value("images", std::vector<std::string>{});
  for (const std::string& im : o.images)  // each becomes a file name in the report's links
    if (const std::string problem = fileNameProblem(im); !problem.empty())
      return errorMessage("'images': '" + visibleText(im, 80) + "' " + problem);
  if (j.contains("cost")) {
    RAYSPEC_TRY(o.cost, caseCostFromJson(j.at("cost")));
  }
  return outcomeVerdict(j, o);
}

}  // namespace

const char* baselineMatchName(BaselineMatch m) {
  return nameOf(m);
}

nlohmann::json outcomeJson(const CaseOutcome& o) {
  nlohmann::json c{{"name", o.name},
                   {"status", statusName(o.status)},
                   {"headline", o.headline},
                   {"seconds", o.seconds},
                   {"device_seconds", o.device_seconds},
                   {"model_seconds", o.model_seconds},
                   {"rules", o.rules},
                   {"baseline", baselineMatchName(o.baseline)},
                   {"baseline_note", o.baseline_note},
                   {"device_name", o.device_name},
                   {"images", o.images}};
  c["cost"] = caseCostJson(o.cost);
  c["findings"] = nlohmann::json::array();
  for (const Finding& f : o.verdict.findings) {
    nlohmann::json finding{{"status", statusName(f.status)},
                           {"rule", f.rule},
                           {"message", f.message},
                           {"rays", f.rays},
                           {"ray_count", f.ray_count}};
    // The claims it is evidence against, where the case claims any (compare/verdict.h).
    if (!f.evidence.empty()) finding["evidence"] = f.evidence;
    c["findings"].push_back(std::move(finding));
  }
  // Apart from the findings: rays never judged (R-UB).
  c["undefined"] = nlohmann::json::array();
  for (const UndefinedRays& u : o.verdict.undefined)
    c["undefined"].push_back({{"reason", undefinedReasonName(u.reason)},
                              {"ray_count", u.ray_count},
                              {"rays", u.rays},
                              {"what", u.what}});
  c["failing_rays"] = nlohmann::json::array();
  for (const RayRow& r : o.failing_rays)
    c["failing_rays"].push_back({{"ray", r.ray},
                                 {"x", r.x},
                                 {"y", r.y},
                                 {"field", r.field},
                                 {"device", r.device},
                                 {"model", r.model}});
  return c;
}

Result<CaseOutcome> outcomeFromJson(const nlohmann::json& j) {
  CaseOutcome o;
  try {
    o.name = j.at("name").get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    return errorMessage(e.what());
  }
  if (const std::string problem = caseNameProblem(o.name); !problem.empty())
    return errorMessage("cases: name '" + o.name.substr(0, 120) + "' is no case name: " + problem);
  try {
    if (const Result<void> read = outcomeFields(j, o); !read)
      return errorMessage("case " + o.name + ": " + read.error().message);
  } catch (const nlohmann::json::exception& e) {
    return errorMessage("case " + o.name + ": " + e.what());
  }
  o.verdict.status = o.status;
  return o;
}

Result<SavedRun> readSavedRun(const std::string& dir) {
  SavedRun run;
  const std::string path = dir + "/summary.json";
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    return errorMessage("cannot read " + path + " (not a rayspec run folder?)");
  const Result<std::string> text = readWholeFile(path, kMaxSummaryJsonBytes);
  if (!text) return inOneMessage(text.error());
  try {
    const nlohmann::json j = nlohmann::json::parse(*text);
    run.info.device = j.at("device").get<std::string>();
    run.info.model_tier = j.at("model_tier").get<std::string>();
    run.info.started = j.at("started").get<std::string>();
    run.info.baseline = j.value("baseline", "");
    run.info.icd = j.value("icd", "");
    run.info.variant = j.value("variant", "");
    run.info.validation = j.at("validation").get<bool>();
    run.info.teardown_errors = j.at("teardown_validation_errors").get<std::vector<std::string>>();
    run.info.planned_cases = j.at("planned_cases").get<size_t>();
    run.info.interrupted = j.at("interrupted").get<bool>();
    for (const nlohmann::json& c : j.at("cases")) {
      Result<CaseOutcome> outcome = outcomeFromJson(c);
      if (!outcome) return withContext(path + ": ", outcome.error());
      run.outcomes.push_back(std::move(*outcome));
    }
  } catch (const std::exception& e) {
    return errorMessage(path + ": " + e.what());
  }
  // A run that did not finish: its journal holds every case that ended.
  if (run.info.interrupted) {
    Result<std::optional<std::vector<CaseOutcome>>> journal = readJournal(dir);
    if (!journal) return journal.error();
    if (*journal) run.outcomes = std::move(**journal);
  }
  return run;
}

}  // namespace rayspec
