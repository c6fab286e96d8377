// Launch rays alike, traced once (alike_rays.h).
#include "model/alike_rays.h"

#include <algorithm>
#include <cstring>

#include "results/record_layout.h"

namespace rayspec {
namespace {

// Bit for bit (-0 and 0 apart, a NaN like itself): what the model computes
// from a ray is a function of its bits. Every member is 4 bytes: no padding.
static_assert(sizeof(Ray) == 8 * sizeof(float) + 5 * sizeof(uint32_t),
              "a member of Ray added: is it one the memo must tell apart?");
bool sameBits(const Ray& a, const Ray& b) {
  return std::memcmp(&a, &b, sizeof(Ray)) == 0;
}

// The entries [begin, end) added again, named by launch ray `ray` (each
// copied before the push that may move the vector; no reserve, which would
// give up the vector's geometric growth: quadratic over a launch).
template <typename Entry>
void addAgain(std::vector<Entry>& entries, size_t begin, size_t end, uint32_t ray) {
  for (size_t k = begin; k < end; ++k) {
    Entry e = entries[k];
    e.ray = ray;
    entries.push_back(std::move(e));
  }
}

// `before` made what `now` has moved by since.
void movesSince(std::vector<uint64_t>& before, const std::vector<uint64_t>& now) {
  for (size_t k = 0; k < now.size(); ++k) before[k] = now[k] - before[k];
}

void addMoves(std::vector<uint64_t>& to, const std::vector<uint64_t>& moves) {
  for (size_t k = 0; k < moves.size(); ++k) to[k] += moves[k];
}

}  // namespace

bool AlikeRays::repeat(LaunchState& st, const Ray& ray, uint32_t i) const {
  if (!kept_ || !sameBits(ray, ray_)) return false;
  if (st.records) {
    const size_t words = recordWords();
    const uint32_t* from = st.records + size_t{index_} * words;
    std::copy(from, from + words, st.records + size_t{i} * words);
  }
  addMoves(st.counters, counter_moves_);
  addMoves(st.floors, floor_moves_);
  addAgain(st.ambiguous, ambiguous_.begin, ambiguous_.end, i);
  addAgain(st.t_bounds, t_bounds_.begin, t_bounds_.end, i);
  addAgain(st.object_origin_bounds, object_origin_bounds_.begin, object_origin_bounds_.end, i);
  addAgain(st.position_bounds, position_bounds_.begin, position_bounds_.end, i);
  return true;
}

void AlikeRays::starting(const LaunchState& st, const Ray& ray, const Ray* next) {
  keeping_ = on_ && next && sameBits(ray, *next);
  if (!keeping_) return;
  kept_ = false;
  ray_ = ray;
  counter_moves_ = st.counters;
  floor_moves_ = st.floors;
  ambiguous_.begin = st.ambiguous.size();
  t_bounds_.begin = st.t_bounds.size();
  object_origin_bounds_.begin = st.object_origin_bounds.size();
  position_bounds_.begin = st.position_bounds.size();
  undefined_before_ = st.undefined.size();
}

void AlikeRays::traced(const LaunchState& st, uint32_t i) {
  if (!keeping_) return;
  index_ = i;
  movesSince(counter_moves_, st.counters);
  movesSince(floor_moves_, st.floors);
  ambiguous_.end = st.ambiguous.size();
  t_bounds_.end = st.t_bounds.size();
  object_origin_bounds_.end = st.object_origin_bounds.size();
  position_bounds_.end = st.position_bounds.size();
  kept_ = st.undefined.size() == undefined_before_;
}

}  // namespace rayspec
