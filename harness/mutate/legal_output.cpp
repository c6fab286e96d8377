#include "mutate/legal_output.h"

#include <algorithm>
#include <map>

#include "compare/counter_modes.h"
#include "fault/planted_fault.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

// The legal devices of another candidate order (R-ORDER-UNSPEC).
constexpr const char* kLegalOrders[] = {"reverse-order", "permuted-order-1", "permuted-order-2",
                                        "permuted-order-3"};

bool sameRecord(const Results& r, uint32_t ray, const std::vector<uint32_t>& record) {
  const size_t words = record.size();
  if (r.records.size() < (ray + 1) * words) return false;
  return std::equal(record.begin(), record.end(), r.records.begin() + ray * words);
}

// The replay of `ray` whose record is `record`; none where the ray is clear
// or no replay gives it.
const LegalReplay* replayGiving(const Results& model, uint32_t ray,
                                const std::vector<uint32_t>& record) {
  for (const RayAmbiguity& a : model.ambiguous) {
    if (a.ray != ray) continue;
    for (const LegalReplay& r : a.replays)
      if (r.record == record) return &r;
  }
  return nullptr;
}

// The legal devices of another candidate order: far to near, the shuffles,
// and each candidate after every other (lastCandidateDevices).
std::vector<Results> orderedDevices(const Case& c, const Plan& plan, const Results& model,
                                    const Results& base) {
  std::vector<Results> out;
  for (const char* name : kLegalOrders) {
    Results d = base;
    if (plantFault(name, c, plan, d, model).applied) out.push_back(std::move(d));
  }
  for (NamedDevice& d : lastCandidateDevices(c, plan, 0))
    if (d.device.ok()) out.push_back(std::move(d.device));
  return out;
}

// Every counter `device` moves from `base` moves with traversal order, or
// (replays_only) as the matched replays together move it.
bool countersLegal(const Case& c, const Results& base, const Results& device, bool replays_only,
                   const std::map<std::string, int64_t>& moves) {
  const std::map<std::string, CounterMode> modes = counterModes(c);
  for (const auto& [name, value] : device.counters) {
    const auto was = base.counters.find(name);
    const int64_t delta =
        static_cast<int64_t>(value) - (was == base.counters.end() ? 0 : int64_t(was->second));
    if (delta == 0) continue;
    const auto mode = modes.find(name);
    if (mode != modes.end() && mode->second == CounterMode::Informational) continue;
    const auto moved = moves.find(name);
    if (!replays_only || moved == moves.end() || moved->second != delta) return false;
  }
  return true;
}

}  // namespace

std::string legalOutput(const Case& c, const Plan& plan, const Results& model, const Results& base,
                        const Results& device, const std::vector<uint32_t>& rays) {
  const uint32_t words = recordWords();
  std::map<std::string, int64_t> moves;  // the matched replays' counter moves
  bool replays_only = true;
  std::vector<Results> ordered;  // run once a ray needs them
  for (uint32_t ray : rays) {
    if (device.records.size() < (ray + 1) * size_t{words}) return "";
    const std::vector<uint32_t> record(device.records.begin() + ray * words,
                                       device.records.begin() + (ray + 1) * words);
    if (const LegalReplay* r = replayGiving(model, ray, record)) {
      for (const auto& [name, delta] : r->counter_moves) moves[name] += delta;
      continue;
    }
    replays_only = false;
    if (ordered.empty()) ordered = orderedDevices(c, plan, model, base);
    if (std::none_of(ordered.begin(), ordered.end(),
                     [&](const Results& d) { return sameRecord(d, ray, record); }))
      return "";
  }
  if (!countersLegal(c, base, device, replays_only, moves)) return "";
  return "R-ORDER-UNSPEC: every changed ray's record is one a legal device gives it (its legal "
         "answers replayed, or another candidate order), and every counter it moved moves so "
         "too: the fault shows nothing here a legal device does not";
}

}  // namespace rayspec
