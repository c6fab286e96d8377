// What `rayspec run` was asked to do (the command line fills it, cli/main.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "metamorphic/feature_path.h"
#include "metamorphic/transform_case.h"
#include "model/model_engine.h"
#include "run/cache_dir.h"

namespace rayspec {

#ifndef RAYSPEC_SOURCE_DIR
#define RAYSPEC_SOURCE_DIR "."
#endif

// Memory a case's model or device child process may hold (run/child_process.h,
// RLIMIT_DATA). 8 GiB leaves room on a 24 GiB, 2-core machine for the parent,
// another run and the page cache, and fits the largest launch a case may
// declare (2^24 rays of records and images). Measured here (2 cores): every
// case of the suite runs under 512 MiB on both sides but the device side of
// the 1M-ray model/mixed-scene-1024 (768 MiB); a small case runs on lavapipe
// with the validation layer under 256 MiB; Embree's rtcNewDevice fails under
// 256 MiB and lavapipe under 128 MiB.
inline constexpr uint64_t kDefaultMemoryLimit = uint64_t(8) << 30;

struct RunOptions {
  std::string device;
  std::vector<std::string>
      icd_files;  // --icd: the loader reads only these driver manifests (vulkan/icd_environment.h)
  std::string filter = "*";
  std::vector<std::string>
      filters;  // when not empty, instead of filter: every case matching one of these globs
  std::string out = "rayspec-results";
  std::string cases_dir = RAYSPEC_SOURCE_DIR "/cases";
  std::vector<std::string> case_files;
  std::string model_tier = "exact";
  bool no_model = false;
  bool no_device = false;
  bool no_validation = false;
  bool strict_validation = false;
  unsigned threads = 0;
  bool brief = false;        // print only the cases that fail the run (ctest), not a line per case
  bool records_csv = false;  // records.csv in every bundle, not only where the case did not pass
  std::string cache_dir =
      defaultCacheDir();   // SPIR-V kept across processes and runs (run/cache_dir.h); "" off
  double timeout = 120.0;  // seconds per case side (model, device) in its worker process
  uint64_t memory_limit =
      kDefaultMemoryLimit;    // bytes of memory per child (RLIMIT_DATA); 0: no limit
  bool no_isolation = false;  // run both sides in this process (one VkDevice for all cases)
  unsigned jobs = 0;  // cases at once, each side in long-lived worker processes; 0: one per core
  std::string device_per_case = "auto";  // yes, no, auto (vulkan/vulkan_engine.h devicePerCase)
  bool process_per_case =
      false;  // each side of each case in a process of its own (no workers; the slowest way)
  std::vector<std::string> process_per_case_for;  // globs: only these cases so, the rest in workers
  std::string plant_fault;                        // test only: fault/planted_fault.h
  std::string plant_fault_in = "*";               // only in cases whose name matches this glob
  std::string rules_file = RAYSPEC_SOURCE_DIR "/references/spec-rules.yaml";
  std::string baseline;       // expected results of this driver (report/baseline.h)
  std::string flakes, skips;  // its flakes and skips files ("": the baseline's siblings, if any)
  std::string shard;          // "I/N": every N-th case from the I-th (run/shard.h)
  bool resume = false;        // keep the cases `out` already has, run the rest
  std::optional<uint64_t>
      permute;  // run each case with primitives and instances permuted (metamorphic/)
  std::optional<RigidMotion>
      move;  // run each case moved by this exact rigid motion (metamorphic/transform_case.h)
  std::optional<FeaturePath>
      through;  // run each case through this feature path (metamorphic/feature_path.h)
  std::string device_results;  // judge device bundles saved in this run folder instead of running a
                               // device (run/device_results.h)
  std::optional<bool> check_case;  // --check-case / --no-check-case; none: the cases outside the
                                   // library folder are checked (run/case_check.h)
};

// What the run does to every case (--through, --permute, --move), as the run
// folder records it (RunInfo::variant): "" for the cases as written, else
// e.g. "through update; permute 7; move -y,x,z".
std::string runVariant(const RunOptions& opt);

// --model as a tier: the name optionError (run/run_setup.h) has checked,
// so Exact only stands in for a name no run gets past that check with.
ModelTier checkedModelTier(const RunOptions& opt);

}  // namespace rayspec
