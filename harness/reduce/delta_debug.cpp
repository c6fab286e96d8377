#include "reduce/delta_debug.h"

#include <algorithm>

namespace rayspec {
namespace {

// current without the chunk-th of `chunks` nearly equal parts.
std::vector<size_t> withoutChunk(const std::vector<size_t>& current, size_t chunks, size_t chunk) {
  const size_t n = current.size();
  const size_t begin = n * chunk / chunks, end = n * (chunk + 1) / chunks;
  std::vector<size_t> out(current.begin(), current.begin() + begin);
  out.insert(out.end(), current.begin() + end, current.end());
  return out;
}

}  // namespace

DeltaResult deltaDebug(size_t count, const SubsetTest& test) {
  DeltaResult r;
  for (size_t i = 0; i < count; ++i) r.kept.push_back(i);
  if (count == 0) return r;
  ++r.tests;
  if (test({})) {
    r.kept.clear();
    return r;
  }
  size_t granularity = 2;
  while (r.kept.size() > 1) {
    const size_t chunks = std::min(granularity, r.kept.size());
    bool reduced = false;
    for (size_t k = 0; k < chunks; ++k) {
      std::vector<size_t> candidate = withoutChunk(r.kept, chunks, k);
      if (candidate.empty()) continue;  // the empty subset was tried first
      ++r.tests;
      if (test(candidate)) {
        r.kept = std::move(candidate);
        granularity = std::max<size_t>(chunks - 1, 2);
        reduced = true;
        break;
      }
    }
    if (reduced) continue;
    if (chunks >= r.kept.size()) break;  // single elements tried: 1-minimal
    granularity = std::min(chunks * 2, r.kept.size());
  }
  return r;
}

}  // namespace rayspec
