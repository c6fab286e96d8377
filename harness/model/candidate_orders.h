// The candidate orders the exact tier tries where a trace's candidate
// programs may depend on the order candidates arrive in (R-ORDER-UNSPEC,
// model/order_dependence.h), and what each order's what-if run leaves
// behind (model_exact_orders.cpp, TraceClassifier::tryPermutations).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "model/model_what_if.h"
#include "model/query_run.h"

namespace rayspec {

// Up to this many candidates that matter, every order is tried (6! = 720
// what-if runs; cases/README.md, "Ray queries"); beyond it, sampleOrders.
constexpr size_t kMaxOrderedCandidates = 6;

// Every processing order of `n` candidates (indices 0 .. n-1 in the model's
// order) that reorders only those in `matter` (sorted; the others keep their
// places): all permutations of `matter`, the model's own first.
std::vector<std::vector<uint32_t>> everyOrder(size_t n, const std::vector<uint32_t>& matter);
// Past kMaxOrderedCandidates, a stated sample of those orders: each candidate
// of `matter` first (the rest in order), the reverse, every rotation, and
// kSampledOrders orders shuffled with a fixed seed; the model's own first.
constexpr size_t kSampledOrders = 32;
std::vector<std::vector<uint32_t>> sampleOrders(size_t n, const std::vector<uint32_t>& matter);

// The most what-if runs (orders of the candidates each set of decisions
// leaves in play, times the tie rules, summed over the sets) that combine
// the orders with the legal decisions of a trace's unsure candidates (an
// edge or vertex triangle missed or hit, a grazed box offered or not):
// TraceClassifier::tryPermutations. Past it no combination is tried and the
// case is a CaseError `order-dependent` saying so (the model cannot list
// every legal answer: a device's may be one left untried). About 12 us a
// run with its replays (fuzz seed 150215's ray 1: 5,208 runs, 0.06 s): the
// bound holds one trace to about 0.8 s. Of the 2,000 Mesa 26.2.6 fuzz
// cases of s73, three rays made 17,280 to 17,760 and none more.
constexpr size_t kMaxCombinedOrderRuns = 65536;

// What one what-if run leaves behind: the committed hit, the launch ray's
// record (but the fields traversal order moves anyway: any_hit_runs ..,
// results/record_layout.h traversalDependent), the payload and, for a ray
// query, the frame its blocks ran in. Counters are left out: those candidate
// programs bump are informational (compare/counter_modes.h).
struct OrderOutcome {
  Committed best;
  std::vector<uint32_t> record;
  Payload payload;
  std::optional<QueryFrameSaved> frame;
};
// Whether two outcomes differ in the committed hit's identity (instance,
// geometry, primitive, kind, attribute words; t within `t_tol`) or in what
// is left behind.
bool sameOutcome(const OrderOutcome& a, const OrderOutcome& b, double t_tol);
// Whether they commit the same primitive (or both nothing).
bool sameIdentity(const Committed& a, const Committed& b);

}  // namespace rayspec
