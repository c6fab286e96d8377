#include <cstdio>

#include "base/visible_text.h"
#include "cli/commands.h"
#include "cli/option_checks.h"
#include "report/merge_runs.h"
#include "report/rule_catalog.h"
#include "report/run_summary.h"
#include "run/run_loop.h"
#include "run/saved_case.h"

namespace rayspec {

int runMerge(const MergeOptions& opt) {
  if (const std::string overlap = outputOverlapsInputs(opt.out, opt.dirs); !overlap.empty()) {
    std::fprintf(stderr, "rayspec merge: %s: the merged run would replace what is merged\n",
                 overlap.c_str());
    return kExitSetup;
  }
  const Result<Baseline> loaded = loadBaselineSet(opt.baseline, opt.flakes, opt.skips);
  if (!loaded) {
    std::fprintf(stderr, "rayspec merge: %s\n", visibleLine(loaded.error().format()).c_str());
    return kExitSetup;
  }
  const Baseline& baseline = *loaded;
  Result<std::vector<Rule>> catalog = loadRuleCatalog(opt.rules_file);
  if (!catalog)
    std::fprintf(stderr, "rayspec merge: %s\n", visibleLine(catalog.error().format()).c_str());
  // Every case judged anew from its bundles, never a shard's summary.json on its word.
  const Result<SavedRun> run =
      mergeRuns(opt.dirs, opt.out, baseline, catalog ? *catalog : std::vector<Rule>{},
                shardCaseJudge(opt.cases_dir));
  if (!run) {
    std::fprintf(stderr, "rayspec merge: %s\n", visibleLine(run.error().format()).c_str());
    // Harness: the shards were read, but the merged folder not written.
    return run.error().kind == ErrorKind::Harness ? kExitReports : kExitSetup;
  }
  const SavedRun& merged = *run;
  RunSummary summary(merged.outcomes.size(), RunSummary::Progress::Quiet);
  for (const CaseOutcome& o : merged.outcomes) summary.add(o);
  for (const std::string& m : merged.info.teardown_errors) summary.addTeardownError(m);
  std::printf("Merged %zu folders: %zu cases on %s\n", opt.dirs.size(), merged.outcomes.size(),
              visibleLine(merged.info.device).c_str());
  summary.print(opt.brief, merged.info.baseline);
  if (merged.info.interrupted)
    std::printf("INTERRUPTED: %zu of %zu planned cases ran\n", merged.outcomes.size(),
                merged.info.planned_cases);
  std::printf("Reports: %s/report.html, results.csv, failures.csv, junit.xml, summary.json\n",
              opt.out.c_str());
  const int status = runExitStatus(summary, merged.info.planned_cases, true, 0);
  // A shard that stopped early: the cases it did not run are no pass.
  return merged.info.interrupted && status == kExitPass ? kExitFailing : status;
}

}  // namespace rayspec
