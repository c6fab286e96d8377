// The model against a bare loop of rtcIntersect1, in one process: the same
// scene (a TLAS with one instance of a triangle grid BLAS, opaque, no any-hit)
// and the same rays (generated once, by the same code). Both sides include
// building the Embree scene (device, BLAS, TLAS) in every iteration; the model
// also interprets raygen / closest-hit / miss, which count hits and misses
// (counters only: no per-ray records). The bare loop counts them as well, and
// both sides' counts are checked against one single-threaded bare run.
// Counter "rays_per_second" for both; single thread (/1) and all cores (/0).
// "setup_ms" is the serial part before any ray is traced (the bare loop: the
// Embree device and scene; the model: its model_scene step, the programs and
// the scene) and "trace_ms" the rest (threads, rays, results), both averages
// per iteration: the setup does not shrink with more cores.
// The machine is shared: run with --benchmark_repetitions=5
// --benchmark_enable_random_interleaving=true and compare medians.
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "model/model_engine.h"
#include "plan/plan.h"
#include "results/record_layout.h"

namespace rayspec {
namespace {

constexpr int kCells = 128;       // 2 * 128 * 128 triangles
constexpr uint32_t kSize = 1024;  // 1024 x 1024 rays

Case benchCase() {
  Case c;
  c.name = "bench/grid";
  Geometry g;
  g.flags = kGeometryOpaque;
  const int n = kCells;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      g.vertices.push_back(
          {-1 + 2.0f * i / n, -1 + 2.0f * j / n, 0.1f * std::sin(i * 0.3f) * std::cos(j * 0.2f)});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      uint32_t a = j * (n + 1) + i, b = a + 1, cc = a + n + 2, d = a + n + 1;
      g.indices.insert(g.indices.end(), {a, b, cc, a, cc, d});
    }
  Blas blas;
  blas.name = "grid";
  blas.geometries.push_back(g);
  c.scene.blases.push_back(blas);
  Instance inst;
  inst.blas = 0;
  c.scene.instances.push_back(inst);
  c.rays.width = c.rays.height = kSize;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) {
      Ray r;
      r.origin = {0, 0, 3};
      r.direction = {-1.2f + 2.4f * (x + 0.5f) / kSize, -1.2f + 2.4f * (y + 0.5f) / kSize, -3};
      r.tmin = 0.001f;
      r.tmax = 100;
      c.rays.rays.push_back(r);
    }
  Stmt trace;
  trace.kind = Stmt::Kind::Trace;
  c.pipeline.raygen = {trace};
  // Counters only (no per-ray fields, no images): the plan keeps no records,
  // so the model simulates none; the bare loop counts hits and misses too.
  auto count = [](const char* name) {
    Stmt s;
    s.kind = Stmt::Kind::Count;
    s.counter = name;
    return s;
  };
  c.pipeline.miss = {{count("miss")}};
  HitGroup hg;
  hg.closest_hit = Program{count("hit")};
  c.pipeline.hit_groups = {hg};
  c.outputs.counters = {"hit", "miss"};
  return c;
}

const Case& theCase() {
  static const Case c = benchCase();
  return c;
}

unsigned threadsOf(const benchmark::State& s) {
  return s.range(0) ? static_cast<unsigned>(s.range(0))
                    : std::max(1u, std::thread::hardware_concurrency());
}

struct Counts {
  uint64_t hits = 0, misses = 0;
  double setup_s = 0, trace_s = 0;  // wall time: scene set-up, tracing
};

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The bare loop: build the same two-level scene, rtcIntersect1 every ray,
// count hits and misses.
Counts bareRun(const Case& c, unsigned threads) {
  const auto start = std::chrono::steady_clock::now();
  const Geometry& g = c.scene.blases[0].geometries[0];
  RTCDevice dev = rtcNewDevice(nullptr);
  RTCScene blas = rtcNewScene(dev);
  RTCGeometry geom = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, g.vertices.data(),
                             0, sizeof(Vec3), g.vertices.size());
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, g.indices.data(), 0,
                             3 * sizeof(uint32_t), g.indices.size() / 3);
  rtcCommitGeometry(geom);
  rtcAttachGeometry(blas, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(blas);
  RTCScene top = rtcNewScene(dev);
  RTCGeometry ig = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(ig, blas);
  rtcSetGeometryTransform(ig, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR,
                          c.scene.instances[0].transform.data());
  rtcCommitGeometry(ig);
  rtcAttachGeometry(top, ig);
  rtcReleaseGeometry(ig);
  rtcCommitScene(top);
  const double setup = secondsSince(start);
  const auto trace_start = std::chrono::steady_clock::now();
  std::atomic<size_t> next{0};
  std::atomic<uint64_t> hit_sum{0}, miss_sum{0};
  const size_t n = c.rays.rays.size();
  auto work = [&] {
    uint64_t h = 0, m = 0;
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    for (;;) {
      const size_t b = next.fetch_add(256);
      if (b >= n) break;
      for (size_t i = b; i < std::min(n, b + 256); ++i) {
        const Ray& r = c.rays.rays[i];
        RTCRayHit rh;
        rh.ray.org_x = r.origin[0];
        rh.ray.org_y = r.origin[1];
        rh.ray.org_z = r.origin[2];
        rh.ray.dir_x = r.direction[0];
        rh.ray.dir_y = r.direction[1];
        rh.ray.dir_z = r.direction[2];
        rh.ray.tnear = r.tmin;
        rh.ray.tfar = r.tmax;
        rh.ray.time = 0;
        rh.ray.mask = 0xFFFFFFFF;
        rh.ray.id = 0;
        rh.ray.flags = 0;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(top, &ctx, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
          ++m;
        else
          ++h;
      }
    }
    hit_sum += h;
    miss_sum += m;
  };
  if (threads == 1)
    work();
  else {
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(work);
    for (auto& t : pool) t.join();
  }
  const double traced = secondsSince(trace_start);
  rtcReleaseScene(top);
  rtcReleaseScene(blas);
  rtcReleaseDevice(dev);
  return {hit_sum.load(), miss_sum.load(), setup, traced};
}

// The bare loop's answer, once (single thread), for both sides to check against.
const Counts& reference() {
  static const Counts k = bareRun(theCase(), 1);
  return k;
}

void BM_BareEmbree(benchmark::State& state) {
  const Case& c = theCase();
  const unsigned threads = threadsOf(state);
  Counts k;
  double setup = 0, trace = 0;
  reference();  // computed before timing starts
  for (auto _ : state) {
    k = bareRun(c, threads);
    benchmark::DoNotOptimize(k);
    setup += k.setup_s;
    trace += k.trace_s;
  }
  if (k.hits != reference().hits || k.misses != reference().misses)
    state.SkipWithError(
        "the bare loop's hit/miss counts differ from the single-threaded reference");
  state.counters["rays_per_second"] = benchmark::Counter(
      double(c.rays.rays.size()) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["threads"] = threads;
  state.counters["setup_ms"] = benchmark::Counter(1e3 * setup, benchmark::Counter::kAvgIterations);
  state.counters["trace_ms"] = benchmark::Counter(1e3 * trace, benchmark::Counter::kAvgIterations);
  state.counters["hits"] = static_cast<double>(k.hits);
  state.counters["misses"] = static_cast<double>(k.misses);
}

void BM_Model(benchmark::State& state, ModelTier tier) {
  const Case& c = theCase();
  const Plan plan = derivePlan(c);
  ModelOptions o;
  o.tier = tier;
  o.threads = threadsOf(state);
  if (plan.records) state.SkipWithError("the benchmark case must be counters-only");
  Results r;
  double setup = 0, trace = 0;
  reference();  // computed before timing starts
  for (auto _ : state) {
    r = runOnModel(c, plan, o);
    if (!r.ok()) state.SkipWithError(r.statusText().c_str());
    benchmark::DoNotOptimize(r.counters);
    setup += r.cost[CostStep::ModelScene];
    trace += r.cost[CostStep::ModelTrace];
  }
  // Same rays, same scene: the model must find exactly the bare loop's hits.
  if (r.counters["hit"] != reference().hits || r.counters["miss"] != reference().misses)
    state.SkipWithError("the model's hit/miss counts differ from the bare loop's");
  state.counters["rays_per_second"] = benchmark::Counter(
      double(c.rays.rays.size()) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["threads"] = o.threads;
  state.counters["setup_ms"] = benchmark::Counter(1e3 * setup, benchmark::Counter::kAvgIterations);
  state.counters["trace_ms"] = benchmark::Counter(1e3 * trace, benchmark::Counter::kAvgIterations);
  state.counters["hits"] = static_cast<double>(r.counters["hit"]);
  state.counters["misses"] = static_cast<double>(r.counters["miss"]);
}

// The model's fast tier with one per-ray field (closest-hit records
// primitive_id): every ray's record (recordWords() words, 176 MB for the 1M
// rays) written and returned, as a case with per_ray outputs needs. No bare
// counterpart; "setup_ms" / "trace_ms" show what stays serial.
void BM_Records(benchmark::State& state) {
  Case c = theCase();
  Stmt rec;
  rec.kind = Stmt::Kind::Record;
  Expr prim;
  prim.kind = Expr::Kind::Builtin;
  prim.name = "primitive_id";
  rec.assigns.push_back({"primitive_id", prim});
  c.pipeline.hit_groups[0].closest_hit->push_back(rec);
  c.outputs.per_ray = {"primitive_id"};
  const Plan plan = derivePlan(c);
  ModelOptions o;
  o.tier = ModelTier::Fast;
  o.threads = threadsOf(state);
  if (!plan.records) state.SkipWithError("the records benchmark's plan keeps no records");
  double setup = 0, trace = 0;
  size_t records = 0;
  for (auto _ : state) {
    Results r = runOnModel(c, plan, o);
    if (!r.ok()) state.SkipWithError(r.statusText().c_str());
    records = r.records.size();
    benchmark::DoNotOptimize(r.records.data());
    setup += r.cost[CostStep::ModelScene];
    trace += r.cost[CostStep::ModelTrace];
  }
  if (records != c.rays.rays.size() * recordWords()) state.SkipWithError("not one record per ray");
  state.counters["rays_per_second"] = benchmark::Counter(
      double(c.rays.rays.size()) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["threads"] = o.threads;
  state.counters["setup_ms"] = benchmark::Counter(1e3 * setup, benchmark::Counter::kAvgIterations);
  state.counters["trace_ms"] = benchmark::Counter(1e3 * trace, benchmark::Counter::kAvgIterations);
}

BENCHMARK(BM_BareEmbree)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Model, fast, ModelTier::Fast)
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Model, robust, ModelTier::Robust)
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Model, exact, ModelTier::Exact)
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Records)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace rayspec

BENCHMARK_MAIN();
