#include "reduce/portability_check.h"

#include <map>

#include "mutate/case_portability.h"

namespace rayspec {
namespace {

// Each legal device that fails `p`'s case, with the finding it fails by (the
// model's own answers failing count as one, kOwnAnswers).
constexpr const char* kOwnAnswers = "the model's own answers";

std::map<std::string, std::string> failingDevices(const CasePortability& p) {
  std::map<std::string, std::string> out;
  if (!p.own_answers.empty()) out[kOwnAnswers] = p.own_answers;
  for (const NotPortable& problem : p.problems) {
    out.emplace(problem.device, problem.finding);
    for (const std::string& other : problem.also) out.emplace(other, problem.finding);
  }
  return out;
}

}  // namespace

PortabilityCheck::PortabilityCheck(const Case& original, unsigned threads)
    : threads_(threads), original_false_alarms_(falseAlarms(original)) {}

std::set<std::string> PortabilityCheck::falseAlarms(const Case& c) const {
  std::set<std::string> names;
  for (const auto& [name, finding] : failingDevices(checkPortability(c, threads_)))
    names.insert(name);
  return names;
}

std::string PortabilityCheck::whyNotPortable(const Case& variant) const {
  for (const auto& [name, finding] : failingDevices(checkPortability(variant, threads_)))
    if (!original_false_alarms_.count(name))
      return name == kOwnAnswers ? "not portable: " + name + " fail: " + finding
                                 : "not portable: legal device " + name + " fails: " + finding;
  return "";
}

}  // namespace rayspec
