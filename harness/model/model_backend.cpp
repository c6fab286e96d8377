#include "model/model_backend.h"

#include <bit>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <stdexcept>
#include <thread>

#include "model/model_machine.h"
#include "model/model_program.h"
#include "model/model_scene.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

// Does a trace statement set its own SBT offset or stride?
bool setsSbtArguments(const Program& p) {
  for (const Stmt& s : p)
    if ((s.kind == Stmt::Kind::Trace && (!s.trace.sbt_offset.empty() || !s.trace.sbt_stride.empty())) ||
        setsSbtArguments(s.then_) || setsSbtArguments(s.else_))
      return true;
  return false;
}
bool setsSbtArguments(const Pipeline& p) {
  if (setsSbtArguments(p.raygen)) return true;
  for (const Program& m : p.miss)
    if (setsSbtArguments(m)) return true;
  for (const HitGroup& g : p.hit_groups)
    if (g.closest_hit && setsSbtArguments(*g.closest_hit)) return true;
  return false;
}

// Could a hit record lie beyond the hit region (R-UB, Machine::checkCandidates)?
// The largest index any instance and geometry can reach with the rays' SBT
// offset and stride (a trace that sets them: any 4-bit value); `nonOpaque`:
// only through a geometry of triangles that may be non-opaque (a device reads
// their records whatever the order, not only the closest hit's).
bool hitRecordMayBeOutOfRange(const Case& c, bool nonOpaque) {
  uint32_t offset = c.rays.defaults.sbt_offset & 0xF, stride = c.rays.defaults.sbt_stride & 0xF;
  for (const Ray& r : c.rays.rays) {
    offset = std::max(offset, r.sbt_offset & 0xF);
    stride = std::max(stride, r.sbt_stride & 0xF);
  }
  if (setsSbtArguments(c.pipeline)) offset = stride = 0xF;
  const size_t region = c.pipeline.sbt_hit.empty() ? c.pipeline.hit_groups.size() : c.pipeline.sbt_hit.size();
  uint64_t top = 0;
  for (const Instance& inst : c.scene.instances) {
    if (!inst.blas || *inst.blas >= c.scene.blases.size()) continue;
    const Blas& b = c.scene.blases[*inst.blas];
    for (uint64_t g = 0; g < b.geometries.size(); ++g) {
      const Geometry& geom = b.geometries[g];
      if (nonOpaque && (geom.kind != Geometry::Kind::Triangles || (geom.flags & kGeometryOpaque))) continue;
      top = std::max<uint64_t>(top, uint64_t{inst.sbt_offset & 0xFFFFFF} + stride * g + offset + 1);
    }
  }
  return top > region;
}

bool hasNanTriangles(const ModelScene& s) {
  for (const ModelBlas& b : s.blases)
    for (const ModelGeometry& g : b.geometries)
      if (!g.nan_regions.empty()) return true;
  return false;
}

// Does any trace need the model to see every candidate (rather than Embree's
// own closest hit)?
bool needsCandidates(const Case& c, const Plan& plan, ModelTier tier) {
  if (tier == ModelTier::Exact) return true;
  if (plan.any_hit || plan.aabbs || plan.intersection) return true;
  if (plan.facing_culls || plan.opacity_flags) return true;  // culls decided per candidate
  for (const Blas& b : c.scene.blases)
    for (const Geometry& g : b.geometries)
      if (g.kind == Geometry::Kind::Aabbs) return true;
  return hitRecordMayBeOutOfRange(c, true);
}

bool hasOwnTriangles(const ModelScene& s) {
  for (const ModelBlas& b : s.blases)
    for (const ModelGeometry& g : b.geometries)
      if (g.own_triangles) return true;
  return false;
}

void fillImages(Results& r, const Plan& plan) {
  const uint32_t words = recordWords();
  const size_t n = static_cast<size_t>(r.width) * r.height;
  for (const ImageOutput& io : plan.images) {
    const RecordField* f = findRecordField(io.field);
    Image img;
    img.name = io.name;
    img.field = io.field;
    img.width = r.width;
    img.height = r.height;
    if (!f) continue;
    img.is_float = f->type == FieldType::Float;
    img.channels = img.is_float ? 4 : 1;
    img.texels.assign(n * img.channels, 0);
    const uint32_t oneBits = std::bit_cast<uint32_t>(1.0f);
    for (size_t i = 0; i < n; ++i) {
      const uint32_t* rec = r.records.data() + i * words;
      if (!img.is_float) {
        img.texels[i] = rec[f->offset];
        continue;
      }
      for (uint32_t k = 0; k < 4; ++k)
        img.texels[i * 4 + k] = k < f->words ? rec[f->offset + k] : (k == 3 ? oneBits : 0u);
    }
    r.images.push_back(std::move(img));
  }
}

}  // namespace

bool modelInThisBuild() { return true; }

Results runOnModel(const Case& c, const Plan& plan, const ModelOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  Results r;
  r.case_name = c.name;
  r.backend = "model";
  r.device = std::string("embree-") + modelTierName(opt.tier);
  r.width = c.rays.width;
  r.height = c.rays.height;
  for (const std::string& name : plan.counters) r.counters[name] = 0;
  const size_t n = static_cast<size_t>(c.rays.width) * c.rays.height;
  if (c.rays.rays.size() != n) {
    r.setStatus(RunStatus::Crash, "the case has " + std::to_string(c.rays.rays.size()) + " rays for a " +
               std::to_string(c.rays.width) + "x" + std::to_string(c.rays.height) + " launch");
    return r;
  }
  try {
    StepTimer scene_time(r.cost, CostStep::ModelScene);
    const CPipeline programs = compilePipeline(c, plan);
    ModelScene scene;
    // Per-primitive triangles are read by candidates, own tests, or the
    // facing of a direct hit when a program reads hit_kind.
    buildModelScene(scene, c, opt.tier, needsCandidates(c, plan, opt.tier), programs.reads(kBiHitKind));
    ModelShared shared;
    shared.c = &c;
    shared.plan = &plan;
    shared.scene = &scene;
    shared.programs = &programs;
    shared.direct = !scene.filters && !hasOwnTriangles(scene) && opt.order == CandidateOrder::Distance;
    shared.order = opt.order;
    shared.need_facing = programs.reads(kBiHitKind);
    shared.deviation = opt.deviation;
    shared.check_candidates = hitRecordMayBeOutOfRange(c, false) || hasNanTriangles(scene);
    shared.raygen_traces_launch_ray =
        programs.raygen.size() == 1 && programs.raygen[0].kind == Stmt::Kind::Trace &&
        std::none_of(programs.raygen[0].has.begin(), programs.raygen[0].has.end(), [](bool b) { return b; });
    shared.need_object_ray =
        programs.reads(kBiObjectOrigin) || programs.reads(kBiObjectDirection) || programs.reads_sphere;
    scene_time.stop();
    StepTimer trace_time(r.cost, CostStep::ModelTrace);
    if (plan.records) r.records.assign(n * recordWords(), 0);
    uint32_t* records = plan.records ? r.records.data() : nullptr;

    unsigned threads = opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<size_t>(threads, std::max<size_t>(1, n / 64)));
    std::vector<std::unique_ptr<Machine>> machines;
    for (unsigned t = 0; t < threads; ++t) machines.push_back(std::make_unique<Machine>(shared, records));
    std::atomic<size_t> next{0};
    constexpr size_t kBlock = 256;
    auto work = [&](Machine& m) {
      for (;;) {
        const size_t begin = next.fetch_add(kBlock);
        if (begin >= n) break;
        const size_t end = std::min(n, begin + kBlock);
        m.runRays(static_cast<uint32_t>(begin), static_cast<uint32_t>(end));
      }
    };
    if (threads == 1) {
      work(*machines[0]);
    } else {
      std::vector<std::thread> pool;
      for (unsigned t = 0; t < threads; ++t) pool.emplace_back(work, std::ref(*machines[t]));
      for (std::thread& t : pool) t.join();
    }
    for (auto& m : machines) {
      for (size_t k = 0; k < plan.counters.size(); ++k) r.counters[plan.counters[k]] += m->counters[k];
      r.ambiguous.insert(r.ambiguous.end(), m->ambiguous.begin(), m->ambiguous.end());
      r.t_bounds.insert(r.t_bounds.end(), m->t_bounds.begin(), m->t_bounds.end());
      r.undefined.insert(r.undefined.end(), m->undefined.begin(), m->undefined.end());
      if (!m->error.empty() && r.ok()) r.setStatus(RunStatus::Crash, m->error);
    }
    std::sort(r.ambiguous.begin(), r.ambiguous.end(),
              [](const RayAmbiguity& a, const RayAmbiguity& b) { return a.ray < b.ray; });
    std::sort(r.undefined.begin(), r.undefined.end(),
              [](const UndefinedRay& a, const UndefinedRay& b) { return a.ray < b.ray; });
    // One bound per ray (the widest of its traces), in ray order.
    std::sort(r.t_bounds.begin(), r.t_bounds.end(),
              [](const TBound& a, const TBound& b) { return a.ray < b.ray || (a.ray == b.ray && a.bound > b.bound); });
    r.t_bounds.erase(std::unique(r.t_bounds.begin(), r.t_bounds.end(),
                                 [](const TBound& a, const TBound& b) { return a.ray == b.ray; }),
                     r.t_bounds.end());
    if (plan.records) fillImages(r, plan);
  } catch (const std::exception& e) {
    r.setStatus(RunStatus::Crash, std::string("model: ") + e.what());
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace rayspec
