#include "compare/any_hit_repeat_verdict.h"

#include <algorithm>

#include "compare/counter_modes.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

// The judged counters a repeat moves (any-hit's own are informational anyway).
std::vector<std::string> judgedRepeatCounters(const Case& c, const Results& model) {
  const std::map<std::string, CounterMode> modes = counterModes(c);
  std::vector<std::string> out;
  for (const std::string& name : model.repeat_counters)
    if (const auto it = modes.find(name);
        it != modes.end() && it->second != CounterMode::Informational)
      out.push_back(name);
  return out;
}

// "3 rays (first: 0 4 9), fields value color; counters hits".
std::string whatRepeatChanges(const Results& model, const std::vector<std::string>& counters) {
  std::string s;
  FieldMask fields = 0;
  for (const RepeatDependentRay& d : model.repeat_dependent) fields |= d.fields;
  if (!model.repeat_dependent.empty()) {
    s = std::to_string(model.repeat_dependent.size()) + " rays (first:";
    for (size_t i = 0; i < std::min<size_t>(8, model.repeat_dependent.size()); ++i)
      s += " " + std::to_string(model.repeat_dependent[i].ray);
    s += "), fields";
    for (const RecordField& f : recordFields())
      if (fields & fieldBit(f.index)) s += std::string(" ") + f.name;
  }
  if (!counters.empty()) {
    s += s.empty() ? "counters" : "; counters";
    for (const std::string& name : counters) s += " " + name;
  }
  return s;
}

}  // namespace

bool judgeAnyHitRepeat(const Case& c, const Results& model, Verdict& v) {
  const std::vector<std::string> counters = judgedRepeatCounters(c, model);
  if (model.repeat_dependent.empty() && counters.empty()) return true;
  const std::string what = whatRepeatChanges(model, counters);
  if (std::find(c.rules.begin(), c.rules.end(), "R-AHIT-DUP") == c.rules.end()) {
    v.add({Status::CaseError,
           "R-AHIT-DUP",
           "not portable: an any-hit that writes the payload or a record runs on geometry without "
           "no_duplicate_any_hit, and a device may run it more than once for a primitive "
           "(R-AHIT-DUP), which changes " +
               what +
               "; give those geometries no_duplicate_any_hit, or claim R-AHIT-DUP to be judged on "
               "the rest",
           {},
           0});
    return false;
  }
  v.add(
      {Status::Pass,
       "R-AHIT-DUP",
       "left out: what a device running any-hit more than once for a primitive may change: " + what,
       {},
       0});
  return true;
}

}  // namespace rayspec
