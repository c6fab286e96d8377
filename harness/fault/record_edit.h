// Reading and changing one field of one ray in a Results, images and counters
// kept consistent (internal to fault/).
#pragma once

#include <functional>
#include <set>
#include <string>

#include "case/case.h"
#include "results/results.h"

namespace rayspec {

struct RecordEdit {
  Results& r;
  uint32_t rays() const;
  bool written(uint32_t ray, const std::string& field) const;  // automatic fields: always
  uint32_t get(uint32_t ray, const std::string& field) const;
  float getFloat(uint32_t ray, const std::string& field) const;
  // Sets word 0 of the field (marks it written) and the pixel of every image
  // that shows that field.
  void set(uint32_t ray, const std::string& field, uint32_t value);
  void setFloat(uint32_t ray, const std::string& field, float value);
  // The whole record of `ray` and its pixels as `from` has them (results of
  // the same case and plan).
  void copyRay(uint32_t ray, const Results& from);
  // Adds delta to the first counter of `names` (in that order) that exists;
  // returns its name, empty when none.
  std::string bumpCounter(const std::vector<std::string>& names, int delta);
};

// Counters a `count` statement names in these programs, in the order of the
// case's outputs.counters.
std::vector<std::string> countersIn(const Case& c, const std::function<void(std::function<void(const Program&)>)>& each);
std::vector<std::string> missCounters(const Case& c);
std::vector<std::string> closestHitCounters(const Case& c);
std::vector<std::string> anyHitCounters(const Case& c);

std::set<uint32_t> ambiguousRays(const Results& model);

}  // namespace rayspec
