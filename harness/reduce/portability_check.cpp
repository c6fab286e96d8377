#include "reduce/portability_check.h"

#include "model/model_engine.h"
#include "mutate/legal_devices.h"
#include "plan/plan.h"

namespace rayspec {

namespace {

// The legal devices of a case judged against the model's exact tier (as
// `rayspec mutate` judges them); none when the model cannot run it.
std::vector<LegalDevice> legalDevices(const Case& c, unsigned threads) {
  if (!modelInThisBuild()) return {};
  const Plan plan = derivePlan(c);
  ModelOptions mo;
  mo.tier = ModelTier::Exact;
  mo.threads = threads;
  const Results model = runOnModel(c, plan, mo);
  if (!model.ok()) return {};
  return judgeLegalDevices(c, plan, model, threads);
}

}  // namespace

PortabilityCheck::PortabilityCheck(const Case& original, unsigned threads)
    : threads_(threads), original_false_alarms_(falseAlarms(original)) {}

std::set<std::string> PortabilityCheck::falseAlarms(const Case& c) const {
  std::set<std::string> names;
  for (const LegalDevice& d : legalDevices(c, threads_))
    if (d.false_alarm) names.insert(d.name);
  return names;
}

std::string PortabilityCheck::whyNotPortable(const Case& variant) const {
  for (const LegalDevice& d : legalDevices(variant, threads_))
    if (d.false_alarm && !original_false_alarms_.count(d.name))
      return "not portable: legal device " + d.name + " fails: " + d.headline;
  return "";
}

}  // namespace rayspec
