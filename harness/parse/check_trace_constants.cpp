// Static diagnosis of undefined behaviour (R-UB) in the traces and calls of a
// case, where the values are constants: a hit record that an instance, a
// geometry and the trace's sbt_offset / sbt_stride reach beyond the hit
// region (R-SBT-HIT), a callable index beyond the callable region
// (R-SBT-CALL), and a trace's own negative or NaN tmin / tmax, or tmax below
// tmin. A value that depends on anything read at run time is left to the
// model, and so is a miss index beyond the miss region (R-SBT-MISS): that is
// undefined only for a ray that misses (a pipeline whose rays all hit needs
// no miss shader), which the model finds ray by ray.
#include <bit>
#include <cmath>
#include <sstream>

#include "case/flag_names.h"
#include "parse/parse_parts.h"
#include "program/constant_value.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

// A launch ray's trace parameters (everything but origin and direction), and
// where they are written.
struct LaunchParameters {
  Ray ray;
  SourceLoc from;
};

bool sameParameters(const Ray& a, const Ray& b) {
  return std::bit_cast<uint32_t>(a.tmin) == std::bit_cast<uint32_t>(b.tmin) &&
         std::bit_cast<uint32_t>(a.tmax) == std::bit_cast<uint32_t>(b.tmax) && a.flags == b.flags &&
         a.cull_mask == b.cull_mask && a.sbt_offset == b.sbt_offset &&
         a.sbt_stride == b.sbt_stride && a.miss == b.miss;
}

// The distinct parameters of the launch rays (a camera or a grid has one set).
std::vector<LaunchParameters> launchParameters(const Rays& rays) {
  std::vector<LaunchParameters> out;
  for (size_t i = 0; i < rays.rays.size(); ++i) {
    bool seen = false;
    for (const LaunchParameters& p : out) seen = seen || sameParameters(p.ray, rays.rays[i]);
    if (!seen)
      out.push_back(
          {rays.rays[i], i < rays.list_locs.size() ? rays.list_locs[i] : rays.defaults_loc});
  }
  return out;
}

// What a trace passes where it is a constant; a missing argument comes from
// `base` (the launch ray in raygen, the `rays` defaults elsewhere).
struct TraceValues {
  std::optional<uint32_t> flags, cull_mask, sbt_offset, sbt_stride, miss;
  std::optional<double> tmin, tmax;
};

std::optional<uint32_t> uintArg(const std::vector<Expr>& given, uint32_t base) {
  return given.empty() ? std::optional<uint32_t>(base) : constantUint(given.front());
}
std::optional<double> floatArg(const std::vector<Expr>& given, float base) {
  return given.empty() ? std::optional<double>(base) : constantFloat(given.front());
}

TraceValues traceValues(const TraceArgs& t, const Ray& base) {
  return {uintArg(t.flags, base.flags),
          uintArg(t.cull_mask, base.cull_mask),
          uintArg(t.sbt_offset, base.sbt_offset),
          uintArg(t.sbt_stride, base.sbt_stride),
          uintArg(t.miss, base.miss),
          floatArg(t.tmin, base.tmin),
          floatArg(t.tmax, base.tmax)};
}

std::string regionSize(size_t records, const char* region, const char* per) {
  return "the " + std::string(region) + " region has " + std::to_string(records) +
         " record(s) (pipeline.sbt." + region + ", else one per " + per + ")";
}

// The first instance x geometry whose hit record lies beyond the hit region
// for these trace values, described; empty when all are inside (or unknown).
std::string hitOutOfRange(const Case& c, const TraceValues& v) {
  if (!v.flags || !v.cull_mask || !v.sbt_offset || !v.sbt_stride) return {};
  const Pipeline& p = c.pipeline;
  const bool skip_triangles = (p.flags & kPipelineSkipTriangles) || (*v.flags & kRaySkipTriangles);
  const bool skip_aabbs = (p.flags & kPipelineSkipAabbs) || (*v.flags & kRaySkipAabbs);
  for (size_t i = 0; i < c.scene.instances.size(); ++i) {
    const Instance& inst = c.scene.instances[i];
    if (!inst.blas || *inst.blas >= c.scene.blases.size()) continue;  // inactive
    if ((inst.mask & *v.cull_mask & kVisibilityMask) == 0) continue;  // R-MASK: never reached
    const Blas& blas = c.scene.blases[*inst.blas];
    for (size_t g = 0; g < blas.geometries.size(); ++g) {
      const Geometry& geom = blas.geometries[g];
      if (geom.primitiveCount() == 0) continue;
      if (geom.kind == Geometry::Kind::Triangles ? skip_triangles : skip_aabbs) continue;
      // R-SBT-HIT: only the low 4 bits of the trace's offset and stride count.
      const uint64_t index = (inst.sbt_offset & kInstanceFieldMask) +
                             static_cast<uint64_t>(g) * (*v.sbt_stride & kTraceSbtFieldMask) +
                             (*v.sbt_offset & kTraceSbtFieldMask);
      if (index < p.sbt_hit.size()) continue;
      std::ostringstream s;
      s << "hit record " << index << " is out of range: scene.instances[" << i << "] (blas "
        << blas.name << ", sbt_offset " << inst.sbt_offset << ") geometry " << g
        << " with sbt_offset " << *v.sbt_offset << ", sbt_stride " << *v.sbt_stride
        << " reaches it; " << regionSize(p.sbt_hit.size(), "hit", "hit group");
      return s.str();
    }
  }
  return {};
}

class TraceChecker {
 public:
  TraceChecker(YamlReader& r, const Case& c) : r_(r), c_(c), launch_(launchParameters(c.rays)) {}

  void program(const Program& p, Stage stage) {
    walkStatements(p, [&](const Stmt& s) {
      if (s.kind == Stmt::Kind::Trace) trace(s, stage);
      if (s.kind == Stmt::Kind::RayQuery || s.kind == Stmt::Kind::RestartQuery) topLevel(s.trace);
      if (s.kind == Stmt::Kind::Call) call(s);
    });
  }

 private:
  void note(const SourceLoc& loc, UndefinedReason reason, const std::string& message) {
    SourceLoc l = loc;
    if (l.file.empty()) l.file = r_.file();
    r_.undefinedBehaviour(l, reason, message + ": undefined behaviour (R-UB)");
  }

  // A constant top level the scene has (a trace's, a ray query's).
  void topLevel(const TraceArgs& t) {
    if (t.tlas >= c_.scene.tlasCount())
      r_.error(t.tlas_loc, "top level " + std::to_string(t.tlas) + ", but the scene has " +
                               std::to_string(c_.scene.tlasCount()) + " (scene.instances[].tlas)");
  }

  void trace(const Stmt& s, Stage stage) {
    const TraceArgs& t = s.trace;
    topLevel(t);
    // In raygen a missing argument comes from each launch ray; elsewhere from the defaults.
    std::vector<LaunchParameters> bases = {{c_.rays.defaults, c_.rays.defaults_loc}};
    if (stage == Stage::Raygen && !launch_.empty()) bases = launch_;
    bool hit_noted = false;
    for (const LaunchParameters& base : bases) {
      const TraceValues v = traceValues(t, base.ray);
      // Values a launch ray gave (not the trace itself) are named by the ray they come from.
      auto from = [&](std::initializer_list<const std::vector<Expr>*> args) {
        bool launch = false;
        for (const auto* a : args) launch = launch || a->empty();
        return launch && base.from.field != "rays" ? " (values of " + base.from.field + ")"
                                                   : std::string();
      };
      // The default raygen (no pipeline written) has no place of its own: the ray's.
      const SourceLoc& at = s.loc.line ? s.loc : base.from;
      if (const std::string hit = hitOutOfRange(c_, v); !hit.empty() && !hit_noted) {
        note(at, UndefinedReason::HitRecordOutOfRange,
             hit + from({&t.flags, &t.cull_mask, &t.sbt_offset, &t.sbt_stride}));
        hit_noted = true;
      }
    }
    // The trace's own interval (the launch rays' and the defaults' are checked where they are
    // written).
    auto value = [](const std::vector<Expr>& e) {
      return e.empty() ? std::nullopt : constantFloat(e.front());
    };
    const std::optional<double> tmin = value(t.tmin), tmax = value(t.tmax);
    const bool bad_tmin = tmin && !(*tmin >= 0), bad_tmax = tmax && !(*tmax >= 0);
    if (bad_tmin)
      note(t.tmin.front().loc, UndefinedReason::RayParameters, "trace tmin is negative or NaN");
    if (bad_tmax)
      note(t.tmax.front().loc, UndefinedReason::RayParameters, "trace tmax is negative or NaN");
    if (bad_tmin || bad_tmax || !(tmin || tmax)) return;
    for (const LaunchParameters& base : bases) {
      const TraceValues v = traceValues(t, base.ray);
      if (v.tmin && v.tmax && *v.tmin > *v.tmax) {
        note(tmax ? t.tmax.front().loc : t.tmin.front().loc, UndefinedReason::RayParameters,
             "trace tmax is below tmin");
        return;
      }
    }
  }

  void call(const Stmt& s) {
    const std::optional<uint32_t> index = constantUint(s.call_index);
    if (!index || *index < c_.pipeline.sbt_callable.size()) return;
    note(s.call_index.loc, UndefinedReason::CallableOutOfRange,
         "callable index " + std::to_string(*index) + " is out of range: " +
             regionSize(c_.pipeline.sbt_callable.size(), "callable", "callable"));
  }

  YamlReader& r_;
  const Case& c_;
  std::vector<LaunchParameters> launch_;
};

}  // namespace

void checkTraceConstants(YamlReader& r, const Case& c) {
  TraceChecker check(r, c);
  const Pipeline& p = c.pipeline;
  check.program(p.raygen, Stage::Raygen);
  for (const Program& g : p.other_raygens) check.program(g, Stage::Raygen);
  for (const Program& m : p.miss) check.program(m, Stage::Miss);
  for (const HitGroup& g : p.hit_groups) {
    if (g.closest_hit) check.program(*g.closest_hit, Stage::ClosestHit);
    if (g.any_hit) check.program(*g.any_hit, Stage::AnyHit);
    if (g.intersection) check.program(*g.intersection, Stage::Intersection);
  }
  for (const Program& k : p.callables) check.program(k, Stage::Callable);
}

}  // namespace rayspec
