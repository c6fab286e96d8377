// The candidate orders of the exact tier (candidate_orders.h).
#include "model/candidate_orders.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include "results/record_layout.h"

namespace rayspec {
namespace {

// The full order of n candidates with the places of `matter` taken, in
// turn, by `perm`.
std::vector<uint32_t> placed(size_t n, const std::vector<uint32_t>& matter,
                             const std::vector<uint32_t>& perm) {
  std::vector<uint32_t> order(n);
  for (size_t k = 0; k < n; ++k) order[k] = static_cast<uint32_t>(k);
  for (size_t j = 0; j < matter.size(); ++j) order[matter[j]] = perm[j];
  return order;
}

// The record words an order may not move: every field but those traversal
// order moves anyway (any_hit_runs, intersection_runs and the any-hit slots).
const std::vector<bool>& comparedWords() {
  static const std::vector<bool> words = [] {
    std::vector<bool> w(recordWords(), true);
    for (const RecordField& f : recordFields())
      if (traversalDependent(f))
        for (uint32_t k = 0; k < f.words; ++k) w[f.offset + k] = false;
    return w;
  }();
  return words;
}

bool sameVal(const Val& a, const Val& b) {
  return a.u == b.u && a.b == b.b && a.x == b.x && a.sized == b.sized &&
         std::memcmp(a.f.data(), b.f.data(), sizeof(float) * a.f.size()) == 0;
}

bool samePayload(const Payload& a, const Payload& b) {
  return a.value == b.value && a.words == b.words && a.sized == b.sized &&
         std::memcmp(a.color.data(), b.color.data(), sizeof(float) * a.color.size()) == 0;
}

bool sameCallData(const CallData& a, const CallData& b) {
  return a.value == b.value && a.words == b.words && a.sized == b.sized &&
         std::memcmp(&a.color, &b.color, sizeof a.color) == 0 &&
         std::memcmp(&a.position, &b.position, sizeof a.position) == 0 &&
         std::memcmp(&a.normal, &b.normal, sizeof a.normal) == 0;
}

bool sameFrame(const QueryFrameSaved& a, const QueryFrameSaved& b) {
  return a.locals.size() == b.locals.size() &&
         std::equal(a.locals.begin(), a.locals.end(), b.locals.begin(), sameVal) &&
         samePayload(a.payload, b.payload) && samePayload(a.child, b.child) &&
         sameCallData(a.callee, b.callee) && a.restarts == b.restarts &&
         a.restart.has_value() == b.restart.has_value() &&
         (!a.restart || (sameRay(a.restart->ray, b.restart->ray) &&
                         sameIdentity(a.restart->keep, b.restart->keep)));
}

}  // namespace

std::vector<std::vector<uint32_t>> everyOrder(size_t n, const std::vector<uint32_t>& matter) {
  std::vector<std::vector<uint32_t>> out;
  std::vector<uint32_t> perm = matter;
  do out.push_back(placed(n, matter, perm));
  while (std::next_permutation(perm.begin(), perm.end()));
  return out;
}

std::vector<std::vector<uint32_t>> sampleOrders(size_t n, const std::vector<uint32_t>& matter) {
  std::vector<std::vector<uint32_t>> out;
  out.push_back(placed(n, matter, matter));
  for (size_t first = 1; first < matter.size(); ++first) {
    std::vector<uint32_t> perm = matter;
    std::rotate(perm.begin(), perm.begin() + static_cast<long>(first),
                perm.begin() + static_cast<long>(first) + 1);
    out.push_back(placed(n, matter, perm));
  }
  std::vector<uint32_t> perm(matter.rbegin(), matter.rend());
  out.push_back(placed(n, matter, perm));
  for (size_t r = 1; r < matter.size(); ++r) {
    perm = matter;
    std::rotate(perm.begin(), perm.begin() + static_cast<long>(r), perm.end());
    out.push_back(placed(n, matter, perm));
  }
  std::mt19937 rng(0x5eed);  // a fixed seed: the same sample on every run
  for (size_t s = 0; s < kSampledOrders; ++s) {
    perm = matter;
    std::shuffle(perm.begin(), perm.end(), rng);
    out.push_back(placed(n, matter, perm));
  }
  return out;
}

bool sameIdentity(const Committed& a, const Committed& b) {
  return a.valid == b.valid && (!a.valid || (a.instance == b.instance && a.geometry == b.geometry &&
                                             a.primitive == b.primitive));
}

bool sameOutcome(const OrderOutcome& a, const OrderOutcome& b, double t_tol) {
  if (!sameIdentity(a.best, b.best)) return false;
  if (a.best.valid && (a.best.kind != b.best.kind || a.best.words != b.best.words ||
                       a.best.sized != b.best.sized || !(std::fabs(a.best.t - b.best.t) <= t_tol)))
    return false;
  const std::vector<bool>& compared = comparedWords();
  if (a.record.size() != b.record.size()) return false;
  for (size_t w = 0; w < a.record.size(); ++w)
    if (compared[w % compared.size()] && a.record[w] != b.record[w]) return false;
  if (!samePayload(a.payload, b.payload)) return false;
  return a.frame.has_value() == b.frame.has_value() && (!a.frame || sameFrame(*a.frame, *b.frame));
}

}  // namespace rayspec
