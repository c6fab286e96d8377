// Each legal answer of an ambiguous launch ray replayed through the ray
// (legal_replays.h): Machine::replayLegalAnswers.
#include <algorithm>

#include "model/model_machine.h"
#include "results/record_layout.h"

namespace rayspec {

LegalReplay Machine::replayOutcome(const LaunchState::Saved& own) const {
  LegalReplay r;
  if (state_.rec) r.record.assign(state_.rec, state_.rec + recordWords());
  for (size_t k = 0; k < state_.counters.size(); ++k)
    if (state_.counters[k] != own.counters[k])
      r.counter_moves[sh_.plan->counters[k]] =
          static_cast<int64_t>(state_.counters[k]) - static_cast<int64_t>(own.counters[k]);
  return r;
}

LegalReplay Machine::replayRun(uint32_t i, const LaunchState::Saved& own) {
  state_.counters = counters_before_;
  if (state_.rec) std::fill(state_.rec, state_.rec + recordWords(), 0u);
  runRay(i);
  return replayOutcome(own);
}

std::vector<LegalReplay> Machine::replayExtra(uint32_t i, const LaunchState::Saved& own,
                                              const std::vector<LegalReplay>& legal, bool doubles,
                                              ReplayScript& script) {
  auto kept = [](const std::vector<LegalReplay>& list, const LegalReplay& r) {
    return std::find(list.begin(), list.end(), r) != list.end();
  };
  const size_t undefined_before = state_.undefined.size();
  std::vector<LegalReplay> leaks;
  script.reset();
  script.own = false;
  script.leaks = !doubles;
  script.doubles = doubles;
  bool complete = true;
  size_t runs = 0;
  do {
    LegalReplay r = replayRun(i, own);
    // A leak whose path is undefined, or pins a t no one t is, keeps none.
    if (++runs > kMaxReplayRuns || state_.undefined.size() > undefined_before ||
        state_.ray_t_free) {
      complete = false;
      break;
    }
    if (script.leaked && !kept(legal, r) && !kept(leaks, r)) leaks.push_back(std::move(r));
    complete = leaks.size() <= kMaxLegalReplays;
  } while (complete && script.advance());
  state_.undefined.resize(undefined_before);
  return complete ? leaks : std::vector<LegalReplay>{};
}

void Machine::replayLegalAnswers(uint32_t i, size_t ambiguity, ReplayScript& script) {
  const LaunchState::Saved own = state_.save();
  const size_t undefined_before = state_.undefined.size();
  std::vector<LegalReplay> replays{replayOutcome(own)};
  bool complete = true;
  // A legal hit at no one t (LaunchState::ray_t_free): a replay pins what is
  // computed from its t, so the ray keeps none (held to what its answers share).
  bool t_free = state_.ray_t_free;
  size_t runs = 1;
  state_.replay = &script;
  while (complete && script.advance()) {
    if (++runs > kMaxReplayRuns) {
      complete = false;
      break;
    }
    LegalReplay r = replayRun(i, own);
    // A legal answer whose path is undefined makes the ray undefined (R-UB).
    if (state_.undefined.size() > undefined_before) complete = false;
    t_free = t_free || state_.ray_t_free;
    if (std::find(replays.begin(), replays.end(), r) == replays.end())
      replays.push_back(std::move(r));
    if (replays.size() > kMaxLegalReplays) complete = false;
  }
  std::vector<LegalReplay> leaks, doubles;
  const bool has_doubles = script.has_doubles;
  if (complete && !t_free && !state_.ambiguous[ambiguity].leak_answers.empty())
    leaks = replayExtra(i, own, replays, false, script);
  if (complete && !t_free && has_doubles) {
    std::vector<LegalReplay> known = replays;
    known.insert(known.end(), leaks.begin(), leaks.end());
    doubles = replayExtra(i, own, known, true, script);
  }
  state_.replay = nullptr;
  const bool undefined = state_.undefined.size() > undefined_before;
  state_.undefined.resize(undefined ? undefined_before + 1 : undefined_before);
  state_.restore(own);
  state_.ray_ambiguous = true;
  state_.ray_undefined = undefined;
  if (complete && !t_free) {
    state_.ambiguous[ambiguity].replays = std::move(replays);
    state_.ambiguous[ambiguity].leak_replays = std::move(leaks);
    state_.ambiguous[ambiguity].double_replays = std::move(doubles);
  }
}

}  // namespace rayspec
