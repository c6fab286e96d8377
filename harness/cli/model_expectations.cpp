#include "cli/model_expectations.h"

#include <algorithm>
#include <sstream>
#include <utility>
#include <vector>

#include "bundle/results_io.h"

namespace rayspec {
namespace {

uint32_t automaticCount(const char* name, const uint32_t* rec) {
  const RecordField* f = findRecordField(name);
  return f ? rec[f->offset] : 0;
}

// Which of closest-hit and miss ran for the ray ("" where neither did: a ray
// query, or a hit group without closest-hit).
std::string stagesRun(const uint32_t* rec) {
  const uint32_t hit = automaticCount("closest_hit_runs", rec),
                 miss = automaticCount("miss_runs", rec);
  if (hit && !miss) return "closest-hit ran";
  if (miss && !hit) return "miss ran";
  if (hit && miss)
    return "closest-hit ran " + std::to_string(hit) + ", miss " + std::to_string(miss);
  return "";
}

// "ambiguous (REASON): legal answers instance I geometry G primitives A, B;
// a miss", the primitives of each instance and geometry together.
std::string legalAnswers(const RayAmbiguity& a) {
  std::vector<std::pair<std::pair<uint32_t, uint32_t>, std::string>> groups;
  bool miss = false;
  for (const Candidate& cand : a.candidates) {
    if (!cand.hit) {
      miss = true;
      continue;
    }
    const std::pair<uint32_t, uint32_t> at{cand.instance, cand.geometry};
    auto g =
        std::find_if(groups.begin(), groups.end(), [&](const auto& e) { return e.first == at; });
    if (g == groups.end()) g = groups.insert(groups.end(), {at, ""});
    g->second += (g->second.empty() ? "" : ", ") + std::to_string(cand.primitive);
  }
  std::string out = "ambiguous (" + std::string(ambiguityReasonName(a.reason)) + "): legal answers";
  std::string sep = " ";
  for (const auto& [at, primitives] : groups) {
    out += sep + "instance " + std::to_string(at.first) + " geometry " + std::to_string(at.second) +
           (primitives.find(',') == std::string::npos ? " primitive " : " primitives ") +
           primitives;
    sep = "; ";
  }
  return miss ? out + sep + "a miss" : out;
}

std::string rayLine(const Case& c, const Results& model, size_t ray, const RayAmbiguity* a) {
  const uint32_t* rec = model.records.data() + ray * recordWords();
  std::string line = "  ray " + std::to_string(ray) + ":";
  std::string sep = " ";
  if (const std::string run = stagesRun(rec); !run.empty()) {
    line += sep + run;
    sep = "; ";
  }
  for (const std::string& field : c.outputs.per_ray) {
    const std::string value = formatField(field, rec);
    line += sep + field + " " + (value.empty() ? "(not written)" : value);
    sep = ", ";
  }
  if (a) line += "; " + legalAnswers(*a);
  return line + "\n";
}

}  // namespace

std::string describeModelExpectations(const Case& c, const Results& model) {
  std::ostringstream s;
  s << "Model (exact tier) expects:\n";
  if (!model.ok()) {
    s << "  nothing: the model did not run the case: " << model.statusText() << '\n';
    return s.str();
  }
  const size_t rays = model.records.size() / recordWords();
  const auto ambiguous = ambiguityByRay(model);
  for (size_t i = 0; i < rays && i < kShownRays; ++i) {
    const auto a = ambiguous.find(static_cast<uint32_t>(i));
    s << rayLine(c, model, i, a == ambiguous.end() ? nullptr : a->second);
  }
  if (rays > kShownRays)
    s << "  ... " << rays - kShownRays << " more rays (all of them: rayspec run --no-device)\n";
  if (!model.counters.empty()) {
    s << "  counters:";
    for (const auto& [name, value] : model.counters) s << ' ' << name << ' ' << value;
    s << '\n';
  }
  return s.str();
}

}  // namespace rayspec
