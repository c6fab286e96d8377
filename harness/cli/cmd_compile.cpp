// `rayspec compile`: the SPIR-V of every generated stage of every case, into
// the cache folder, with no device and nothing run: what a run-only pack
// carries (tools/pack-device.sh), made in seconds instead of by a run of the
// suite on lavapipe.
#include <cstdio>

#include "cli/commands.h"
#include "glsl/generate_glsl.h"
#include "library/case_discovery.h"
#include "plan/plan.h"
#include "spirv/compile_glsl.h"

namespace rayspec {
namespace {

struct CompileCounts {
  int cases = 0, stages = 0, compiled = 0, failed = 0, bad_cases = 0;
};

// Each stage of one case compiled (or found in the cache); a stage rayspec
// generated that does not compile is rayspec's error, printed with its case.
void compileCase(const Case& c, CompileCounts& n) {
  if (!c.expected_rejections.empty()) return;  // compiled to be refused, on the device side
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  ++n.cases;
  for (const GeneratedShader* s : everyStage(g)) {
    const SpirvResult r = compileGlsl(s->glsl, s->stage, s->compute);
    ++n.stages;
    if (!r.from_cache && !r.words.empty()) ++n.compiled;
    if (r.words.empty()) {
      ++n.failed;
      std::fprintf(stderr, "rayspec compile: %s: %s: %s\n", c.name.c_str(), s->name.c_str(),
                   r.error.c_str());
    }
  }
}

}  // namespace

int runCompile(const CompileOptions& opt) {
  const std::vector<CaseFile> files = findCases(opt.cases_dir, opt.filter);
  if (files.empty()) {
    std::fprintf(stderr, "rayspec compile: no case matches '%s' in %s\n", opt.filter.c_str(),
                 opt.cases_dir.c_str());
    return 2;
  }
  // What it compiles is for the cache on disk: without the cache's key, nothing would be kept.
  if (const Result<void> cached = useCacheDir(opt.cache_dir); !cached) {
    std::fprintf(stderr, "rayspec compile: %s\n", cached.error().format().c_str());
    return 2;
  }
  CompileCounts n;
  for (const CaseFile& f : files) {
    const ParseResult parsed = loadCase(f, opt.cases_dir, nullptr);
    for (const Error& e : parsed.errors) std::fprintf(stderr, "%s\n", e.format().c_str());
    if (parsed.value)
      compileCase(*parsed.value, n);
    else
      ++n.bad_cases;
  }
  std::printf(
      "%d cases, %d stages: %d compiled, %d from the cache, %d failed; %d cases do not "
      "parse\n",
      n.cases, n.stages, n.compiled, n.stages - n.compiled - n.failed, n.failed, n.bad_cases);
  return n.failed || n.bad_cases ? 1 : 0;
}

}  // namespace rayspec
