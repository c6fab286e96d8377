// Exact tier: each legal answer of an ambiguous launch ray replayed through
// the whole launch ray (Machine::replayLegalAnswers, legal_replays.cpp). A
// replay runs the ray again with a script saying which legal answer each of
// its ambiguous traces takes, in the order they are met; the scripts are
// every combination, each trace's answers as the choices before it leave
// them (an odometer over a tree). Each distinct outcome (record, counters)
// is kept in RayAmbiguity::replays; the judge holds the device's record to
// one of them as a whole (compare/compare_records.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rayspec {

// The most distinct outcomes kept per ray, and runs tried: beyond them the
// ray keeps no replays and is judged on what its answers share.
constexpr size_t kMaxLegalReplays = 64;
constexpr size_t kMaxReplayRuns = 256;

struct ReplayScript {
  // The answer each ambiguous trace takes, in the order met (beyond the
  // list: 0, the trace's actual run).
  std::vector<uint32_t> choices;
  // How many answers each ambiguous trace of this run had.
  std::vector<uint32_t> options;

  // The answer the next ambiguous trace takes, of `answers`.
  size_t choose(size_t answers) {
    const size_t j = options.size();
    options.push_back(static_cast<uint32_t>(answers));
    const size_t c = j < choices.size() ? choices[j] : 0;
    return c < answers ? c : 0;
  }
  // The next script after this run's, false after the last: the last trace
  // with an answer left takes its next, the traces after it their first.
  bool advance() {
    choices.resize(options.size(), 0);
    for (size_t j = options.size(); j-- > 0;)
      if (choices[j] + 1 < options[j]) {
        ++choices[j];
        choices.resize(j + 1);
        options.clear();
        return true;
      }
    return false;
  }
};

}  // namespace rayspec
