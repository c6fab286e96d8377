// The run loop's own cost per case, side by side in one process: the same
// generated sweep of N copies of one small case (results/miss-xor-closest-hit:
// 5 rays, a triangle, miss and closest hit) run by `rayspec run` with
// long-lived workers (the default) and with a process per case side
// (--process-per-case, the way runs went before workers), both with the
// validation layer on, the exact model tier and the jobs given in
// RAYSPEC_BENCH_JOBS (default: one per core). Reported: cases per second and
// seconds per case; with workers the cost per case stays flat from 100 to
// 5,000 cases (2 cores, lavapipe: 48.6, 53.4 and 48.3 cases/s at 100, 1,000
// and 5,000; a process per case: 7.0 and 7.2 at 100 and 500). The per-process reference stops at
// 500 cases (about 10 s a hundred on 2 cores). Run it on lavapipe (MESA_SHADER_CACHE_DIR warm) or
// on any device with RAYSPEC_BENCH_DEVICE.
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "run/run_loop.h"

namespace rayspec {
namespace {
namespace fs = std::filesystem;

// A folder of cases holding one sweep of n variants of one case.
std::string generatedSuite(int n) {
  const std::string root =
      fs::temp_directory_path().string() + "/rayspec-bench-run-loop/" + std::to_string(n);
  fs::remove_all(root);
  fs::create_directories(root + "/cases/bench");
  std::ifstream in(RAYSPEC_SOURCE_DIR "/cases/results/miss-xor-closest-hit.yaml");
  std::stringstream original;
  original << in.rdbuf();
  std::ofstream out(root + "/cases/bench/loop.sweep.yaml");
  out << "sweep:\n  name: \"copy-${i}\"\n  product:\n    i: [";
  for (int i = 0; i < n; ++i) out << (i ? ", " : "") << i;
  out << "]\n" << original.str();
  return root;
}

// stdout and stderr to /dev/null while the run prints its progress.
class Quiet {
 public:
  Quiet() : out_(dup(STDOUT_FILENO)), err_(dup(STDERR_FILENO)) {
    std::fflush(nullptr);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
    close(null);
  }
  ~Quiet() {
    std::fflush(nullptr);
    dup2(out_, STDOUT_FILENO);
    dup2(err_, STDERR_FILENO);
    close(out_);
    close(err_);
  }

 private:
  int out_, err_;
};

void runLoop(benchmark::State& state, bool process_per_case) {
  const int n = static_cast<int>(state.range(0));
  const std::string root = generatedSuite(n);
  RunOptions opt;
  opt.cases_dir = root + "/cases";
  opt.out = root + "/out";
  opt.cache_dir =
      root + "/cache";  // no timings from other runs; SPIR-V compiled once, by the first case
  opt.process_per_case = process_per_case;
  if (const char* d = std::getenv("RAYSPEC_BENCH_DEVICE")) opt.device = d;
  if (const char* j = std::getenv("RAYSPEC_BENCH_JOBS"))
    opt.jobs = static_cast<unsigned>(std::atoi(j));
  int status = 0;
  for (auto _ : state) {
    Quiet quiet;
    status = runCases(opt);
  }
  if (status != kExitPass)
    state.SkipWithError(("the run did not pass: see " + opt.out + "/summary.txt").c_str());
  state.counters["cases_per_s"] =
      benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["s_per_case"] = benchmark::Counter(
      n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  fs::remove_all(root);
}

void workers(benchmark::State& state) {
  runLoop(state, false);
}
void processPerCase(benchmark::State& state) {
  runLoop(state, true);
}

BENCHMARK(workers)->Arg(100)->Arg(1000)->Arg(5000)->Iterations(1)->UseRealTime()->Unit(
    benchmark::kSecond);
BENCHMARK(processPerCase)
    ->Arg(100)
    ->Arg(500)
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

}  // namespace
}  // namespace rayspec

BENCHMARK_MAIN();
