// Delta debugging by removal (Zeller's ddmin, complements only): the
// smallest subset of a list's elements that still passes a test, found by
// trying to drop halves, then quarters, ..., then single elements. The
// order of attempts depends only on the list's length and the test's
// answers, so the same test gives the same subset.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace rayspec {

// True when a variant keeping only these elements (indices into the list,
// ascending) still fails the same way.
using SubsetTest = std::function<bool(const std::vector<size_t>& kept)>;

struct DeltaResult {
  std::vector<size_t> kept;  // ascending
  size_t tests = 0;          // how many times the test was asked
};

// The kept elements of `count`: first the empty subset is tried, then
// chunks are removed at ever finer granularity. When it ends, removing any
// one kept element fails the test (1-minimal). The full list is taken to
// pass the test (it is never asked).
DeltaResult deltaDebug(size_t count, const SubsetTest& test);

}  // namespace rayspec
