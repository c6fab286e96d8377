// The sample case, plan and results the compare tests edit (shared by
// tests/compare_*_test.cpp).
#pragma once

#include <bit>
#include <string>

#include "compare/compare_results.h"
#include "results/record_layout.h"

namespace rayspec {

inline Stmt count(const std::string& name) {
  Stmt s;
  s.kind = Stmt::Kind::Count;
  s.counter = name;
  return s;
}

// A case with a miss, a closest-hit and an any-hit counter; 4 rays.
inline Case sampleCase() {
  Case c;
  c.pipeline.miss.push_back({count("miss")});
  HitGroup g;
  g.closest_hit = Program{count("chit")};
  g.any_hit = Program{count("ahit")};
  c.pipeline.hit_groups.push_back(g);
  c.outputs.counters = {"miss", "chit", "ahit"};
  c.outputs.per_ray = {"hit", "primitive_id", "hit_t"};
  return c;
}

inline Plan samplePlan(const Case& c) {
  Plan p;
  p.counters = c.outputs.counters;
  p.record_fields = c.outputs.per_ray;
  p.records = true;
  return p;
}

inline void setUint(Results& r, uint32_t ray, const char* field, uint32_t v) {
  const RecordField* f = findRecordField(field);
  uint32_t* rec = &r.records[ray * recordWords()];
  rec[f->offset] = v;
  if (!f->automatic) markWritten(rec, f->index);
}

inline void setFloat(Results& r, uint32_t ray, const char* field, float v) {
  setUint(r, ray, field, std::bit_cast<uint32_t>(v));
}

// Rays 0,1 hit primitives 0,1 at t=2; rays 2,3 miss.
inline Results sampleResults(const std::string& backend) {
  Results r;
  r.backend = backend;
  r.width = 4;
  r.height = 1;
  r.records.assign(4 * recordWords(), 0);
  for (uint32_t i = 0; i < 4; ++i) {
    setUint(r, i, "raygen_runs", 1);
    if (i < 2) {
      setUint(r, i, "hit", 1);
      setUint(r, i, "primitive_id", i);
      setFloat(r, i, "hit_t", 2.0f);
      setUint(r, i, "closest_hit_runs", 1);
      setUint(r, i, "any_hit_runs", 1);
    } else {
      setUint(r, i, "hit", 0);
      setUint(r, i, "miss_runs", 1);
    }
  }
  r.counters = {{"miss", 2}, {"chit", 2}, {"ahit", 2}};
  r.images.push_back({"primitive", "primitive_id", 4, 1, 1, false, {0, 1, 0, 0}});
  return r;
}

// The sample case's counters as its shaders count them: once per run of
// miss, closest-hit and any-hit (a device's counters agree with its records).
inline void countFromRecords(Results& r) {
  const std::pair<const char*, const char*> pairs[] = {
      {"miss", "miss_runs"}, {"chit", "closest_hit_runs"}, {"ahit", "any_hit_runs"}};
  for (const auto& [counter, runs] : pairs) {
    uint64_t total = 0;
    for (size_t i = 0; i < r.records.size() / recordWords(); ++i)
      total += r.records[i * recordWords() + findRecordField(runs)->offset];
    r.counters[counter] = total;
  }
}

// A finding of status s whose rule or message holds text, or that names the
// rule text among the claims it is evidence against.
inline bool findingNames(const Verdict& v, Status s, const std::string& text) {
  for (const Finding& f : v.findings)
    if (f.status == s && (f.rule.find(text) != std::string::npos ||
                          f.message.find(text) != std::string::npos || findingNames(f, text)))
      return true;
  return false;
}
}  // namespace rayspec
