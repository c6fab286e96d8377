#include "compare/trace_shape.h"

#include <algorithm>
#include <functional>
#include <set>

#include "program/hit_object.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

size_t countKind(const Program& p, Stmt::Kind kind) {
  size_t n = 0;
  walkStatements(p, [&](const Stmt& s) { n += s.kind == kind; });
  return n;
}

// A ray_queries statement holds its RayQuery statements: each counts once.
size_t countQueries(const Program& p) {
  return countKind(p, Stmt::Kind::RayQuery);
}

// The ray queries of p whose blocks or `after` record a field that shows a
// trace's answer (the hit flag, the hit's identity: checkAmbiguous reads them).
size_t queriesWritingHitFields(const Program& p) {
  auto writes = [](const Program& body) {
    bool any = false;
    walkStatements(body, [&](const Stmt& s) {
      if (s.kind == Stmt::Kind::Record)
        for (const auto& [field, value] : s.assigns)
          any = any || field == "hit" || field == "primitive_id" || field == "instance_id" ||
                field == "geometry_index";
    });
    return any;
  };
  size_t n = 0;
  walkStatements(p, [&](const Stmt& s) {
    n += s.kind == Stmt::Kind::RayQuery && (writes(s.then_) || writes(s.else_));
  });
  return n;
}

void forEachNonRaygen(const Pipeline& pipe, const std::function<void(const Program&)>& visit) {
  for (const Program& p : pipe.miss) visit(p);
  for (const Program& p : pipe.callables) visit(p);
  for (const HitGroup& g : pipe.hit_groups)
    for (const auto* p : {&g.closest_hit, &g.any_hit, &g.intersection})
      if (*p) visit(**p);
}

// A trace's flags may hold skip_closest_hit: a flags expression that is not a
// literal without the bit.
bool traceMaySkipClosestHit(const Stmt& s) {
  for (const Expr& e : s.trace.flags) {
    if (e.kind != Expr::Kind::Literal || e.literal.empty()) return true;
    if (static_cast<uint32_t>(e.literal[0]) & kRaySkipClosestHit) return true;
  }
  return false;
}

bool anyRaySkipsClosestHit(const Case& c) {
  if (c.rays.defaults.flags & kRaySkipClosestHit) return true;
  for (const Ray& r : c.rays.rays)
    if (r.flags & kRaySkipClosestHit) return true;
  bool skips = false;
  walkStatements(c.pipeline.raygen, [&](const Stmt& s) {
    if (s.kind == Stmt::Kind::Trace) skips = skips || traceMaySkipClosestHit(s);
  });
  return skips;
}

// Top-level `count` statements of p before any ignore or terminate (after
// one, the rest of the program does not run), per counter; counters counted
// anywhere else in p go to `conditional`.
void topLevelCounts(const Program& p, std::map<std::string, uint32_t>& counts,
                    std::set<std::string>& conditional) {
  std::set<std::string> top;
  bool ended = false;
  for (const Stmt& s : p) {
    if (mayEndProgram(s)) ended = true;
    if (s.kind == Stmt::Kind::Count && !ended) ++counts[s.counter];
  }
  std::map<std::string, uint32_t> every;
  walkStatements(p, [&](const Stmt& s) {
    if (s.kind == Stmt::Kind::Count) ++every[s.counter];
  });
  for (const auto& [name, n] : every) {
    const auto it = counts.find(name);
    if (it == counts.end() || it->second != n) conditional.insert(name);
  }
}

struct StagePrograms {
  const char* run_field;
  std::vector<const Program*> programs;
};

std::vector<StagePrograms> stagesWithRunCounts(const Pipeline& pipe) {
  std::vector<StagePrograms> out = {{"raygen_runs", {&pipe.raygen}},
                                    {"miss_runs", {}},
                                    {"closest_hit_runs", {}},
                                    {"any_hit_runs", {}},
                                    {"callable_runs", {}}};
  for (const Program& p : pipe.miss) out[1].programs.push_back(&p);
  for (const HitGroup& g : pipe.hit_groups) {
    if (g.closest_hit) out[2].programs.push_back(&*g.closest_hit);
    if (g.any_hit) out[3].programs.push_back(&*g.any_hit);
  }
  for (const Program& p : pipe.callables) out[4].programs.push_back(&p);
  return out;
}

}  // namespace

TraceShape traceShape(const Case& c) {
  const Pipeline& pipe = c.pipeline;
  TraceShape t;
  size_t top_traces = 0;
  for (const Stmt& s : pipe.raygen) top_traces += s.kind == Stmt::Kind::Trace;
  size_t other_traces = 0;
  forEachNonRaygen(pipe,
                   [&](const Program& p) { other_traces += countKind(p, Stmt::Kind::Trace); });
  t.single_trace =
      top_traces == 1 && countKind(pipe.raygen, Stmt::Kind::Trace) == 1 && other_traces == 0;
  size_t hit_queries = queriesWritingHitFields(pipe.raygen);
  t.ray_queries = countQueries(pipe.raygen);
  forEachNonRaygen(pipe, [&](const Program& p) {
    t.ray_queries += countQueries(p);
    hit_queries += queriesWritingHitFields(p);
  });
  t.several_traces = (!t.single_trace || hit_queries > 0) &&
                     countKind(pipe.raygen, Stmt::Kind::Trace) + other_traces + hit_queries > 0;
  size_t top_calls = 0, other_calls = 0;
  for (const Stmt& s : pipe.raygen) top_calls += s.kind == Stmt::Kind::Call;
  forEachNonRaygen(pipe, [&](const Program& p) { other_calls += countKind(p, Stmt::Kind::Call); });
  t.calls_fixed = top_calls == countKind(pipe.raygen, Stmt::Kind::Call) && other_calls == 0;
  t.hit_runs_closest_hit = !anyRaySkipsClosestHit(c);
  for (const HitGroup& g : pipe.hit_groups)
    t.hit_runs_closest_hit = t.hit_runs_closest_hit && g.closest_hit;
  for (const SbtRecord& r : pipe.sbt_hit)
    t.hit_runs_closest_hit = t.hit_runs_closest_hit && r.group;
  t.miss_runs_miss = !pipe.miss.empty();
  for (const SbtRecord& r : pipe.sbt_miss) t.miss_runs_miss = t.miss_runs_miss && r.group;
  // A trace into a hit object runs its closest-hit or miss only when (and
  // each time) it is executed.
  bool hit_objects = usesHitObject(pipe.raygen);
  forEachNonRaygen(pipe, [&](const Program& p) { hit_objects = hit_objects || usesHitObject(p); });
  if (hit_objects) t.hit_runs_closest_hit = t.miss_runs_miss = false;
  return t;
}

std::optional<std::set<std::string>> queryReachedFields(const Case& c) {
  size_t elsewhere = 0;
  forEachNonRaygen(c.pipeline, [&](const Program& p) { elsewhere += countQueries(p); });
  const Program& raygen = c.pipeline.raygen;
  const auto first = std::find_if(raygen.begin(), raygen.end(), [](const Stmt& s) {
    return s.kind == Stmt::Kind::RayQuery || s.kind == Stmt::Kind::RayQueries;
  });
  // The first query in raygen's order at its top level: none before it, nested.
  size_t before = 0;
  for (auto it = raygen.begin(); it != first; ++it) before += countQueries({*it});
  if (elsewhere || first == raygen.end() || before) return std::nullopt;
  std::set<std::string> reached;
  bool beyond = false;  // a trace or callable after it
  for (auto it = first; it != raygen.end(); ++it)
    walkStatements({*it}, [&](const Stmt& s) {
      beyond = beyond || s.kind == Stmt::Kind::Trace || s.kind == Stmt::Kind::Call;
      if (s.kind == Stmt::Kind::Record)
        for (const auto& [field, value] : s.assigns) reached.insert(field);
    });
  if (beyond) return std::nullopt;
  return reached;
}

std::map<std::string, CounterSource> counterSources(const Case& c) {
  std::map<std::string, std::set<std::string>>
      stages_of;  // counter -> run fields of the stages counting it
  std::set<std::string> conditional;
  std::vector<std::pair<std::string, std::vector<std::map<std::string, uint32_t>>>> per_program;
  for (const StagePrograms& s : stagesWithRunCounts(c.pipeline)) {
    std::vector<std::map<std::string, uint32_t>> counts;
    for (const Program* p : s.programs) {
      counts.emplace_back();
      topLevelCounts(*p, counts.back(), conditional);
      walkStatements(*p, [&](const Stmt& st) {
        if (st.kind == Stmt::Kind::Count) stages_of[st.counter].insert(s.run_field);
      });
    }
    per_program.push_back({s.run_field, std::move(counts)});
  }
  // Intersection programs count what no run field follows.
  for (const HitGroup& g : c.pipeline.hit_groups)
    if (g.intersection)
      walkStatements(*g.intersection, [&](const Stmt& st) {
        if (st.kind == Stmt::Kind::Count) conditional.insert(st.counter);
      });
  std::map<std::string, CounterSource> out;
  for (const auto& [counter, stages] : stages_of) {
    if (stages.size() != 1 || conditional.count(counter)) continue;
    for (const auto& [field, programs] : per_program) {
      if (field != *stages.begin()) continue;
      std::set<uint32_t> ks;
      for (const auto& counts : programs) {
        const auto it = counts.find(counter);
        ks.insert(it == counts.end() ? 0 : it->second);
      }
      if (ks.size() == 1 && *ks.begin() > 0) out[counter] = {field, *ks.begin()};
    }
  }
  return out;
}

bool countedByProgramsAlone(const Case& c, const std::string& counter) {
  bool alone = true;
  auto visit = [&](const Program& p) {
    size_t top = 0, all = 0;
    bool ended = false;
    for (const Stmt& s : p) {
      if (mayEndProgram(s)) ended = true;
      if (s.kind == Stmt::Kind::Count && s.counter == counter && !ended) ++top;
    }
    size_t calls_top = 0, calls = 0;
    for (const Stmt& s : p)
      calls_top += s.kind == Stmt::Kind::Call && s.call_index.kind == Expr::Kind::Literal;
    walkStatements(p, [&](const Stmt& s) {
      all += s.kind == Stmt::Kind::Count && s.counter == counter;
      calls += s.kind == Stmt::Kind::Call;
    });
    alone = alone && top == all && calls_top == calls;
  };
  visit(c.pipeline.raygen);
  forEachNonRaygen(c.pipeline, visit);
  return alone;
}

size_t countStatements(const Case& c, const std::string& counter) {
  size_t n = 0;
  auto visit = [&](const Program& p) {
    walkStatements(
        p, [&](const Stmt& s) { n += s.kind == Stmt::Kind::Count && s.counter == counter; });
  };
  visit(c.pipeline.raygen);
  forEachNonRaygen(c.pipeline, visit);
  return n;
}

size_t raysRunningOtherPrograms(const Results& model) {
  size_t n = 0;
  for (const RayAmbiguity& a : model.ambiguous) {
    std::set<std::pair<uint32_t, uint32_t>> hits;
    bool miss = false;
    for (const Candidate& k : a.candidates) {
      if (k.hit)
        hits.insert({k.instance, k.geometry});
      else
        miss = true;
    }
    n += (miss && !hits.empty()) || hits.size() > 1;
  }
  return n;
}

}  // namespace rayspec
