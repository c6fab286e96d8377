// What every legal answer of a ray shares, read from the shape of the case's
// programs: how many traces a ray makes and which shader each of them runs,
// and which counters follow from the per-ray run counts. An ambiguous ray
// (several legal answers) is still held to all of it.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>

#include "case/case.h"
#include "results/results.h"

namespace rayspec {

struct TraceShape {
  // raygen traces exactly once, at its top level, and no other stage traces
  // (or calls): a launch ray makes one trace, whatever it hits (ray queries
  // aside: they run no shader)
  bool single_trace = false;
  // ray_query statements in every program (each query of a ray_queries one)
  size_t ray_queries = 0;
  // a launch ray may make more than one traversal that writes the record's
  // hit fields (a later one may have written them): not single_trace, or a
  // ray query that records the hit flag or a hit's identity; and some stage
  // traces, or some such query, at all
  bool several_traces = false;
  // each hit of that trace runs exactly one closest-hit: every hit group has
  // one, no hit record is all zero, no ray or trace may skip closest-hit
  bool hit_runs_closest_hit = false;
  // each miss runs a miss shader: no miss record is all zero
  bool miss_runs_miss = false;
  // every callable call is at the top level of raygen: each launch ray runs
  // the same number of callables whatever its trace finds
  bool calls_fixed = false;
};
TraceShape traceShape(const Case& c);

// The record fields an ambiguous ray query's answer may reach: every field
// recorded from raygen's first ray query on (its blocks, its `after` and
// every statement after it), where that query stands at raygen's top level,
// no trace or callable call follows it and no other program holds a query.
// Every other field is written before the query or by the shaders of a
// trace before it, alike for each of the query's answers. nullopt where
// the answer may reach further.
std::optional<std::set<std::string>> queryReachedFields(const Case& c);

// A counter every run of one stage counts the same number of times: counted
// only by `count` statements at the top level of that stage's programs (the
// raygen, miss or closest-hit stage, or any-hit), `per_run` times in each of
// them. Then counter == per_run * (sum of that stage's per-ray run counts),
// on any device, legal or not, that records both.
struct CounterSource {
  std::string run_field;  // raygen_runs, miss_runs, closest_hit_runs or any_hit_runs
  uint32_t per_run = 0;
};
// The counters with such a source.
std::map<std::string, CounterSource> counterSources(const Case& c);

// Every `count` of the counter is at the top level of its program (before any
// ignore or terminate), and every callable call is at the top level with a
// literal index: then what a ray counts follows from which programs its
// answer runs (miss, or the hit record of an instance and geometry) alone.
bool countedByProgramsAlone(const Case& c, const std::string& counter);
// How many `count` statements name the counter, over every program.
size_t countStatements(const Case& c, const std::string& counter);

// Ambiguous rays whose legal answers may run other programs: a hit and a
// miss, or hits in different instances or geometries (other hit records).
size_t raysRunningOtherPrograms(const Results& model);

}  // namespace rayspec
