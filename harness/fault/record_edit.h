// Reading and changing one field of one ray in a Results, images and counters
// kept consistent (internal to fault/).
#pragma once

#include <functional>
#include <set>
#include <string>

#include "case/case.h"
#include "results/results.h"

namespace rayspec {

// Reading one field of one ray of a Results.
struct RecordView {
  const Results& r;
  uint32_t rays() const;
  bool written(uint32_t ray, const std::string& field) const;  // automatic fields: always
  uint32_t get(uint32_t ray, const std::string& field, uint32_t word = 0) const;
  float getFloat(uint32_t ray, const std::string& field, uint32_t word = 0) const;
};

// Changing it, images and counters kept consistent.
struct RecordEdit : RecordView {
  explicit RecordEdit(Results& results) : RecordView{results}, w(results) {}
  Results& w;
  // Sets word `word` of the field (marks it written) and the pixel of every
  // image that shows that field.
  void set(uint32_t ray, const std::string& field, uint32_t value, uint32_t word = 0);
  void setFloat(uint32_t ray, const std::string& field, float value, uint32_t word = 0);
  // Adds delta to the first counter of `names` (in that order) that exists;
  // returns its name, empty when none.
  std::string bumpCounter(const std::vector<std::string>& names, int delta);
};

// Counters a `count` statement names in these programs, in the order of the
// case's outputs.counters.
std::vector<std::string> countersIn(
    const Case& c, const std::function<void(std::function<void(const Program&)>)>& each);
std::vector<std::string> missCounters(const Case& c);
std::vector<std::string> closestHitCounters(const Case& c);
std::vector<std::string> anyHitCounters(const Case& c);

std::set<uint32_t> ambiguousRays(const Results& model);

// One assignment of a `record` statement, with the stage of its program.
struct FieldWrite {
  Stage stage;
  std::string field;
  const Expr* value;
};
std::vector<FieldWrite> fieldWrites(const Case& c);

}  // namespace rayspec
