#include "model/model_engine.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <exception>
#include <memory>
#include <stdexcept>
#include <thread>
#include <tuple>

#ifdef __linux__
#include <sys/mman.h>
#endif

#include "case/flag_names.h"
#include "model/any_hit_repeat.h"
#include "model/model_machine.h"
#include "model/model_program.h"
#include "model/model_scene.h"
#include "model/uniform_launch.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

// Does a trace statement set its own SBT offset or stride?
bool setsSbtArguments(const Program& p) {
  for (const Stmt& s : p)
    if ((s.kind == Stmt::Kind::Trace &&
         (!s.trace.sbt_offset.empty() || !s.trace.sbt_stride.empty())) ||
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

// The largest hit record index any instance and geometry can reach, plus one,
// for a trace's SBT offset and stride (4 bits each); `non_opaque`: only
// through a geometry of triangles that may be non-opaque (a device reads
// their records whatever the order, not only the closest hit's).
uint64_t hitRecordReach(const Case& c, bool non_opaque, uint32_t offset, uint32_t stride) {
  uint64_t top = 0;
  for (const Instance& inst : c.scene.instances) {
    if (!inst.blas || *inst.blas >= c.scene.blases.size()) continue;
    const Blas& b = c.scene.blases[*inst.blas];
    for (uint64_t g = 0; g < b.geometries.size(); ++g) {
      const Geometry& geom = b.geometries[g];
      if (non_opaque && (geom.kind != Geometry::Kind::Triangles || (geom.flags & kGeometryOpaque)))
        continue;
      top = std::max<uint64_t>(
          top, uint64_t{inst.sbt_offset & kInstanceFieldMask} + stride * g + offset + 1);
    }
  }
  return top;
}

// Could a hit record lie beyond the hit region (R-UB, ModelTracer::checkCandidates)?
// The reach with the rays' largest SBT offset and stride (a trace that sets
// them: any 4-bit value). The rays are read only when the largest 4-bit
// values could reach beyond the region: a scan of every launch ray is a
// serial pass over the whole ray list before any thread starts.
bool hitRecordMayBeOutOfRange(const Case& c, bool non_opaque) {
  const size_t region =
      c.pipeline.sbt_hit.empty() ? c.pipeline.hit_groups.size() : c.pipeline.sbt_hit.size();
  if (hitRecordReach(c, non_opaque, kTraceSbtFieldMask, kTraceSbtFieldMask) <= region) return false;
  if (setsSbtArguments(c.pipeline)) return true;
  uint32_t offset = c.rays.defaults.sbt_offset & kTraceSbtFieldMask,
           stride = c.rays.defaults.sbt_stride & kTraceSbtFieldMask;
  for (const Ray& r : c.rays.rays) {
    offset = std::max(offset, r.sbt_offset & kTraceSbtFieldMask);
    stride = std::max(stride, r.sbt_stride & kTraceSbtFieldMask);
  }
  return hitRecordReach(c, non_opaque, offset, stride) > region;
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
  if (tier == ModelTier::Exact || plan.ray_queries) return true;
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

// The plan's images, sized but not written (every texel is written by
// writeTexels, chunk by chunk in the workers), with the record field each
// shows (an image of an unknown field is left out).
std::vector<const RecordField*> prepareImages(Results& r, const Plan& plan) {
  const size_t n = static_cast<size_t>(r.width) * r.height;
  std::vector<const RecordField*> fields;
  for (const ImageOutput& io : plan.images) {
    const RecordField* f = findRecordField(io.field);
    if (!f) continue;
    Image img;
    img.name = io.name;
    img.field = io.field;
    img.width = r.width;
    img.height = r.height;
    img.is_float = f->type == FieldType::Float;
    img.channels = img.is_float ? 4 : 1;
    img.texels.resize(n * img.channels);
    r.images.push_back(std::move(img));
    fields.push_back(f);
  }
  return fields;
}

// The texels of launch indices [begin, end) from their records: a uint
// field's word, or a float field's words as rgba (missing channels 0, alpha 1).
void writeTexels(Image& img, const RecordField& f, const uint32_t* records, size_t begin,
                 size_t end) {
  const uint32_t words = recordWords();
  const uint32_t one_bits = std::bit_cast<uint32_t>(1.0f);
  uint32_t* texels = img.texels.data();
  for (size_t i = begin; i < end; ++i) {
    const uint32_t* rec = records + i * words;
    if (!img.is_float) {
      texels[i] = rec[f.offset];
      continue;
    }
    for (uint32_t k = 0; k < 4; ++k)
      texels[i * 4 + k] = k < f.words ? rec[f.offset + k] : (k == 3 ? one_bits : 0u);
  }
}

// Large, untouched records: asks Linux for 2 MB pages (transparent huge
// pages in "madvise" mode), about 90 page faults instead of 45,000 for a
// million rays' records. A hint only: nothing changes where it is refused.
void adviseHugePages(void* p, size_t bytes) {
#ifdef __linux__
  constexpr uintptr_t kHuge = uintptr_t{2} << 20;
  if (bytes < 4 * kHuge) return;
  const uintptr_t begin = (reinterpret_cast<uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
  const uintptr_t end = (reinterpret_cast<uintptr_t>(p) + bytes) & ~(kHuge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

// What every Machine of the run shares: the case, its plan, the scene, the
// compiled programs, and the paths the run may take.
ModelShared sharedState(const Case& c, const Plan& plan, const ModelOptions& opt,
                        const ModelScene& scene, const CPipeline& programs) {
  ModelShared shared;
  shared.c = &c;
  shared.plan = &plan;
  shared.scene = &scene;
  shared.programs = &programs;
  // A NO_NULL any-hit or intersection promise is checked on every candidate
  // (ModelTracer::checkCandidates), which a direct run does not see.
  const bool no_null_candidates =
      (c.pipeline.flags & (kPipelineNoNullAnyHit | kPipelineNoNullIntersection)) != 0;
  shared.fault_seam = ModelFaultSeam(opt, &c.pipeline);
  shared.direct = !scene.filters && !hasOwnTriangles(scene) && shared.fault_seam.distanceOrder() &&
                  !shared.fault_seam.inlinedQueryFaulty() && !no_null_candidates;
  shared.any_hit_repeat = opt.any_hit_repeat;
  shared.replays = opt.tier == ModelTier::Exact && opt.any_hit_repeat == AnyHitRepeat::None &&
                   !shared.fault_seam.answersOtherwise();
  shared.need_facing = programs.needs & builtin_needs::Facing;
  // Read by the candidate path only (ModelTracer::checkCandidates): a direct
  // run sees no candidates, so it is not worked out there.
  shared.check_candidates = !shared.direct && (hitRecordMayBeOutOfRange(c, false) ||
                                               hasNanTriangles(scene) || no_null_candidates);
  shared.raygen_traces_launch_ray =
      programs.raygen.size() == 1 && programs.raygen[0].kind == Stmt::Kind::Trace &&
      programs.raygen[0].assigns.empty() && programs.raygen[0].src->trace.tlas == 0 &&
      !programs.raygen[0].src->trace.hit_object && c.pipeline.payload_words.size() == 1 &&
      std::none_of(programs.raygen[0].has.begin(), programs.raygen[0].has.end(),
                   [](bool b) { return b; });
  shared.payload_types = c.pipeline.payload_words.size() > 1;
  shared.need_object_ray = (programs.needs & builtin_needs::ObjectRay) || programs.reads_sphere;
  shared.alike_rays = !opt.trace_each_ray && !launchIdRead(programs);
  return shared;
}

// The launch's n rays traced by `threads` workers. Each builds its own
// Machine in its own thread (its counters and vectors come from that
// thread's malloc arena, never a cache line another worker writes) and takes
// chunks of launch rays from one shared index: about 32 chunks per thread,
// each 256 to 4096 rays (few atomic steps on the shared index, little
// imbalance at the end). Records are zeroed, and image texels written, chunk
// by chunk by the worker that traced it. Rethrows a worker's exception.
std::vector<std::unique_ptr<Machine>> traceInThreads(
    const ModelShared& shared, size_t n, unsigned threads, uint32_t* records, Results& r,
    const std::vector<const RecordField*>& image_fields) {
  const size_t words = recordWords();
  std::vector<std::unique_ptr<Machine>> machines(threads);
  std::vector<std::exception_ptr> failures(threads);
  const size_t chunk = std::clamp<size_t>(n / (size_t{threads} * 32), 256, 4096);
  std::atomic<size_t> next{0};
  auto work = [&](unsigned t) {
    try {
      machines[t] = std::make_unique<Machine>(shared, records);
      Machine& m = *machines[t];
      for (;;) {
        const size_t begin = next.fetch_add(chunk, std::memory_order_relaxed);
        if (begin >= n) break;
        const size_t end = std::min(n, begin + chunk);
        if (records) std::fill(records + begin * words, records + end * words, 0u);
        m.runRays(static_cast<uint32_t>(begin), static_cast<uint32_t>(end));
        for (size_t k = 0; k < image_fields.size(); ++k)
          writeTexels(r.images[k], *image_fields[k], records, begin, end);
      }
    } catch (...) {
      failures[t] = std::current_exception();  // rethrown below, after the join
      next.store(n);                           // the others stop at their next chunk
    }
  };
  if (threads == 1) {
    work(0);
  } else {
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(work, t);
    for (std::thread& t : pool) t.join();
  }
  for (const std::exception_ptr& f : failures)
    if (f) std::rethrow_exception(f);
  return machines;
}

// The workers' counters, ambiguous, bounded and undefined rays into r, in
// ray order (one t bound per ray: the widest of its traces).
// Sorted by ray, one bound a ray: its widest.
void keepWidestPerRay(std::vector<TBound>& bounds) {
  std::sort(bounds.begin(), bounds.end(), [](const TBound& a, const TBound& b) {
    return a.ray < b.ray || (a.ray == b.ray && a.bound > b.bound);
  });
  bounds.erase(std::unique(bounds.begin(), bounds.end(),
                           [](const TBound& a, const TBound& b) { return a.ray == b.ray; }),
               bounds.end());
}

// Each place once, in the order of the case file (whichever thread met it first).
void keepOnceInFileOrder(std::vector<SourceLoc>& at) {
  const auto key = [](const SourceLoc& l) {
    return std::tie(l.file, l.line, l.column, l.field);
  };
  std::sort(at.begin(), at.end(),
            [&](const SourceLoc& a, const SourceLoc& b) { return key(a) < key(b); });
  at.erase(std::unique(at.begin(), at.end(),
                       [&](const SourceLoc& a, const SourceLoc& b) { return key(a) == key(b); }),
           at.end());
}

void gatherMachines(const std::vector<std::unique_ptr<Machine>>& machines, const Plan& plan,
                    Results& r) {
  for (auto& m : machines) {
    if (!m) continue;
    for (size_t k = 0; k < plan.counters.size(); ++k)
      r.counters[plan.counters[k]] += m->state().counters[k];
    for (size_t k = 0; k < plan.counters.size(); ++k)
      if (m->state().floors[k]) r.counter_floors[plan.counters[k]] += m->state().floors[k];
    r.ambiguous.insert(r.ambiguous.end(), m->state().ambiguous.begin(), m->state().ambiguous.end());
    r.t_bounds.insert(r.t_bounds.end(), m->state().t_bounds.begin(), m->state().t_bounds.end());
    r.object_origin_bounds.insert(r.object_origin_bounds.end(),
                                  m->state().object_origin_bounds.begin(),
                                  m->state().object_origin_bounds.end());
    r.position_bounds.insert(r.position_bounds.end(), m->state().position_bounds.begin(),
                             m->state().position_bounds.end());
    r.undefined.insert(r.undefined.end(), m->state().undefined.begin(), m->state().undefined.end());
    for (const std::string& o : m->state().order_dependent)
      if (std::find(r.order_dependent.begin(), r.order_dependent.end(), o) ==
          r.order_dependent.end())
        r.order_dependent.push_back(o);
    for (const SourceLoc& at : m->state().missed_box_reports) r.missed_box_reports.push_back(at);
    for (const std::string& o : m->state().endless_restarts)
      if (std::find(r.endless_restarts.begin(), r.endless_restarts.end(), o) ==
          r.endless_restarts.end())
        r.endless_restarts.push_back(o);
    if (!m->state().error.empty() && r.ok()) r.setStatus(SideStatus::Crash, m->state().error);
  }
  std::sort(r.ambiguous.begin(), r.ambiguous.end(),
            [](const RayAmbiguity& a, const RayAmbiguity& b) { return a.ray < b.ray; });
  std::sort(r.undefined.begin(), r.undefined.end(),
            [](const UndefinedRay& a, const UndefinedRay& b) { return a.ray < b.ray; });
  keepWidestPerRay(r.t_bounds);
  keepWidestPerRay(r.object_origin_bounds);
  keepWidestPerRay(r.position_bounds);
  keepOnceInFileOrder(r.missed_box_reports);
}

// The empty results of the model's run of c: names, size, counters at 0.
Results emptyResults(const Case& c, const Plan& plan, const ModelOptions& opt) {
  Results r;
  r.case_name = c.name;
  r.backend = "model";
  r.device = std::string("embree-") + modelTierName(opt.tier);
  r.width = c.rays.width;
  r.height = c.rays.height;
  for (const std::string& name : plan.counters) r.counters[name] = 0;
  return r;
}

// Every id of the launch traced, into r cleared first of what a one-id run
// of a uniform launch gathered that could not stand for all (its ray is
// ambiguous or undefined, which the judge reads per ray).
void traceWholeLaunch(const ModelShared& shared, size_t n, const ModelOptions& opt,
                      uint32_t* records, Results& r,
                      const std::vector<const RecordField*>& image_fields) {
  if (n > kMaxTracedLaunchIds) {
    r.setStatus(SideStatus::Crash,
                "model: a launch of " + std::to_string(n) +
                    " ids: above 2^24 the model traces one id for all, which needs every id "
                    "alike and its ray neither ambiguous nor undefined (model/uniform_launch.h)");
    return;
  }
  for (auto& [name, count] : r.counters) count = 0;
  r.counter_floors.clear();
  r.ambiguous.clear();
  r.t_bounds.clear();
  r.object_origin_bounds.clear();
  r.position_bounds.clear();
  r.undefined.clear();
  unsigned threads = opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::min<size_t>(threads, std::max<size_t>(1, n / 64)));
  gatherMachines(traceInThreads(shared, n, threads, records, r, image_fields), *shared.plan, r);
}

}  // namespace

bool modelInThisBuild() {
  return true;
}

Results runOnModel(const Case& c, const Plan& plan, const ModelOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  Results r = emptyResults(c, plan, opt);
  // A case that expects its compiler to reject shaders launches nothing; the
  // reference is the checker's (program/stage_interface.h): every one is.
  for (const ExpectedRejection& e : c.expected_rejections) r.rejected.push_back(e.shader);
  if (!c.expected_rejections.empty()) return r;
  const size_t n = static_cast<size_t>(c.rays.width) * c.rays.height;
  if (c.rays.launchRays() != n) {
    r.setStatus(SideStatus::Crash, "the case has " + std::to_string(c.rays.launchRays()) +
                                       " rays for a " + std::to_string(c.rays.width) + "x" +
                                       std::to_string(c.rays.height) + " launch");
    return r;
  }
  try {
    StepTimer scene_time(r.cost, CostStep::ModelScene);
    const CPipeline programs = compilePipeline(c, plan);
    ModelScene scene;
    scene.aabbs_grown = ModelFaultSeam(opt).aabbNeighboursRun();
    // Per-primitive triangles are read by candidates, own tests, and the
    // built-ins that need them (the facing of a direct hit, vertex_position<i>).
    const bool keep_triangles = (programs.needs & builtin_needs::Triangles) || plan.position_fetch;
    if (Result<void> built =
            buildModelScene(scene, c, opt.tier, needsCandidates(c, plan, opt.tier), keep_triangles);
        !built) {
      r.setStatus(SideStatus::Crash, "model: " + built.error().message);
      return r;
    }
    const ModelShared shared = sharedState(c, plan, opt, scene, programs);
    scene_time.stop();
    StepTimer trace_time(r.cost, CostStep::ModelTrace);
    // Left unwritten here (BulkWords): each worker zeroes the records of its
    // own chunks just before tracing them, so the pages are first touched,
    // and cleared, by the threads that write them.
    const size_t words = recordWords();
    if (plan.records) r.records.resize(n * words);
    uint32_t* records = plan.records ? r.records.data() : nullptr;
    if (records) adviseHugePages(records, n * words * sizeof(uint32_t));
    const std::vector<const RecordField*> image_fields =
        plan.records ? prepareImages(r, plan) : std::vector<const RecordField*>{};
    for (Image& img : r.images)
      adviseHugePages(img.texels.data(), img.texels.size() * sizeof(uint32_t));
    // Every id alike: one traced for all where its rays stand for every id's.
    const bool uniform = n > 1 && launchUniform(c, plan, programs);
    if (uniform) gatherMachines(traceInThreads(shared, 1, 1, records, r, image_fields), plan, r);
    if (!uniform || (r.ok() && !oneIdStandsForAll(r)))
      traceWholeLaunch(shared, n, opt, records, r, image_fields);
    else if (r.ok())
      scaleToLaunch(r, n);
  } catch (const std::exception& e) {
    r.setStatus(SideStatus::Crash, std::string("model: ") + e.what());
    r.records.clear();  // chunks no worker reached were never zeroed
    r.images.clear();
  }
  if (r.ok() && opt.tier == ModelTier::Exact && opt.any_hit_repeat == AnyHitRepeat::None) {
    StepTimer repeat_time(r.cost, CostStep::ModelTrace);
    findAnyHitRepeatDependence(c, plan, opt, r);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace rayspec
