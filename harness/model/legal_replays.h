// Exact tier: each legal answer of an ambiguous launch ray replayed through
// the whole launch ray (Machine::replayLegalAnswers, legal_replays.cpp). The
// model's own run is the first replay (every trace its actual answer); a
// replay runs the ray again with a script saying which legal answer each of
// its ambiguous traces takes, in the order they are met; the scripts are
// every combination, each trace's answers as the choices before it leave
// them (an odometer over a tree), and a trace before the one whose choice
// changed is not classified again. Each distinct outcome (record, counters)
// is kept in RayAmbiguity::replays; the judge holds the device's record to
// one of them as a whole (compare/compare_records.cpp). Where the ray's
// first ambiguous trace has leak answers, a second pass (the leak pass)
// runs the scripts again with each trace's leak answers among its choices:
// the outcomes of runs that took one, none of the legal ones, are kept in
// RayAmbiguity::leak_replays. Where a trace of the ray has double hits
// (TraceClassifier::tryDoubleHits: two or more triangles of a group closing
// around the ray hit, R-WATERTIGHT), a third pass (the double pass) runs
// the scripts with each trace's double hits among its choices, and keeps
// the new outcomes of runs that took one in RayAmbiguity::double_replays.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/model_what_if.h"

namespace rayspec {

// The most distinct outcomes kept per ray, and runs tried: beyond them the
// ray keeps no replays and is judged on what its answers share.
constexpr size_t kMaxLegalReplays = 64;
constexpr size_t kMaxReplayRuns = 256;

struct ReplayScript {
  // The answer each ambiguous trace takes, in the order met (beyond the
  // list: 0, the trace's actual run).
  std::vector<uint32_t> choices;
  // How many answers each ambiguous trace of this run had, and which of the
  // run's classified traces it was.
  std::vector<uint32_t> options;
  std::vector<size_t> ambiguous_at;
  // The legal answers of each classified trace of the run (none: a clear
  // trace), kept for the next run up to the trace whose choice it changes:
  // the same launch ray, the same choices before, the same classification.
  std::vector<std::vector<WhatIf>> known;
  // How many of each known trace's answers are legal (the rest are leaks,
  // or double hits in the double pass).
  std::vector<size_t> known_legal;
  size_t traces = 0;  // classified traces so far in this run
  // The leak pass (Machine::replayExtra): each trace's answers are its
  // legal ones, then its leak answers (RayAmbiguity::leak_answers);
  // `leaked`: this run took a leak answer at some trace.
  bool leaks = false;
  bool leaked = false;
  // The double pass (Machine::replayExtra): each trace's answers are its
  // legal ones, then its double hits; `leaked` then says this run took one.
  bool doubles = false;
  // Some trace classified so far has double hits (the double pass is run).
  bool has_doubles = false;
  // The model's own run (the choices all 0): its first ambiguous trace is
  // the ray's RayAmbiguity.
  bool own = true;

  // A new launch ray's own run (the vectors keep their capacity).
  void reset() {
    choices.clear();
    options.clear();
    ambiguous_at.clear();
    known.clear();
    known_legal.clear();
    traces = 0;
    own = true;
    leaks = false;
    leaked = false;
    doubles = false;
    has_doubles = false;
  }
  // The legal answers of the trace now, if an earlier run classified it.
  const std::vector<WhatIf>* knownAnswers() const {
    return traces < known.size() ? &known[traces] : nullptr;
  }
  // The trace now classified, with its answers (none: clear), the first
  // `legal` of them legal.
  void classified(const std::vector<WhatIf>& answers, size_t legal) {
    if (traces == known.size()) {
      known.push_back(answers);
      known_legal.push_back(legal);
    }
    ++traces;
  }
  // The answer the trace just classified takes, of `answers`.
  size_t choose(size_t answers) {
    const size_t j = options.size();
    options.push_back(static_cast<uint32_t>(answers));
    ambiguous_at.push_back(traces - 1);
    const size_t c = j < choices.size() ? choices[j] : 0;
    const size_t taken = c < answers ? c : 0;
    leaked = leaked || taken >= known_legal[traces - 1];
    return taken;
  }
  // The next script after this run's, false after the last: the last trace
  // with an answer left takes its next, the traces after it their first.
  bool advance() {
    choices.resize(options.size(), 0);
    for (size_t j = options.size(); j-- > 0;)
      if (choices[j] + 1 < options[j]) {
        ++choices[j];
        choices.resize(j + 1);
        known.resize(ambiguous_at[j] + 1);
        known_legal.resize(ambiguous_at[j] + 1);
        options.clear();
        ambiguous_at.clear();
        traces = 0;
        own = false;
        leaked = false;
        return true;
      }
    return false;
  }
};

}  // namespace rayspec
