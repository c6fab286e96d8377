// An ambiguous ray's record held to its legal answers as a whole: the
// model's replays of each (model/legal_replays.h, RayAmbiguity::replays).
#include <algorithm>

#include "compare/compare_parts.h"

namespace rayspec {

bool replayMatches(const LegalReplay& r, const uint32_t* d,
                   const std::vector<const RecordField*>& fields, const RayBounds& bounds) {
  for (const RecordField* f : fields)
    if (!sameField(*f, d, r.record.data(), bounds)) return false;
  return true;
}

namespace {

bool anyReplayMatches(const std::vector<LegalReplay>& replays, const uint32_t* d,
                      const std::vector<const RecordField*>& fields, const RayBounds& bounds) {
  return std::any_of(replays.begin(), replays.end(),
                     [&](const LegalReplay& r) { return replayMatches(r, d, fields, bounds); });
}

}  // namespace

bool leakReplayMatches(const RayAmbiguity& a, const uint32_t* d,
                       const std::vector<const RecordField*>& fields, const RayBounds& bounds) {
  return anyReplayMatches(a.leak_replays, d, fields, bounds);
}

bool doubleReplayMatches(const RayAmbiguity& a, const uint32_t* d,
                         const std::vector<const RecordField*>& fields, const RayBounds& bounds) {
  return anyReplayMatches(a.double_replays, d, fields, bounds);
}

const RecordField* fieldNoReplayLeaves(const RayAmbiguity& a, const uint32_t* d,
                                       const std::vector<const RecordField*>& fields,
                                       const RayBounds& bounds) {
  const RecordField* nearest = nullptr;
  size_t fewest = fields.size() + 1;
  for (const LegalReplay& r : a.replays) {
    const RecordField* first = nullptr;
    size_t differ = 0;
    for (const RecordField* f : fields)
      if (!sameField(*f, d, r.record.data(), bounds)) {
        if (!first) first = f;
        ++differ;
      }
    if (differ == 0) return nullptr;
    if (differ < fewest) {
      fewest = differ;
      nearest = first;
    }
  }
  return nearest;
}

}  // namespace rayspec
