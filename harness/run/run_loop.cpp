#include "run/run_loop.h"

#include <fnmatch.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

#include "base/output_folder.h"
#include "base/visible_text.h"
#include "metamorphic/feature_path.h"
#include "metamorphic/motion_spec.h"
#include "report/baseline_gate.h"
#include "report/case_journal.h"
#include "report/outcome_json.h"
#include "report/rule_catalog.h"
#include "report/run_folder_writes.h"
#include "run/cache_dir.h"
#include "run/case_as_run.h"
#include "run/case_order.h"
#include "run/case_steps.h"
#include "run/device_probe.h"
#include "run/device_results.h"
#include "run/interrupt.h"
#include "run/model_adapter.h"
#include "run/run_only.h"
#include "run/run_setup.h"
#include "run/shard.h"
#include "run/vulkan_adapter.h"
#include "vulkan/device_errors.h"
#include "vulkan/icd_environment.h"

namespace rayspec {
namespace {

// What becomes of each selected case file, decided before any case runs (the
// workers are forks of this process and see the cases as they are then).
struct PlannedCase {
  std::string name;
  std::optional<CaseOutcome>
      ready;  // no run: resumed (as judged then), skipped, a case-file error, not moved
  bool resumed = false;
  std::string not_checked;  // the portability check did not finish (run/case_check.h)
  size_t index = 0;         // into PreparedRun::cases when it runs
  StepCosts parse_cost;
};

struct PreparedRun {
  std::vector<PlannedCase> planned;  // in the cases' own order
  std::vector<Case> cases;           // those that run
};

PreparedRun prepareCases(const std::vector<CaseFile>& files, const RunOptions& opt,
                         const Baseline& baseline, const std::vector<std::string>& labels,
                         std::map<std::string, CaseOutcome>& earlier, const CaseCheck& check) {
  PreparedRun run;
  for (const CaseFile& f : files) {
    PlannedCase p;
    p.name = f.name;
    if (auto it = earlier.find(f.name); it != earlier.end()) {
      p.ready = std::move(it->second);
      p.resumed = true;
    } else if (const NamePattern* skip = findPattern(baseline.skips, f.name)) {
      p.ready = skippedOutcome(f.name, *skip);
    } else {
      StepTimer parse_time(p.parse_cost, CostStep::Parse);
      const ParseResult parsed = loadCase(f, opt.cases_dir, labels.empty() ? nullptr : &labels);
      parse_time.stop();
      if (std::optional<CaseOutcome> error = caseFileError(f, parsed)) {
        applyBaseline(baseline, *error);
        p.ready = std::move(error);
      } else {
        // --permute, --move, --through: the case as it runs, or why it does not.
        CaseAsRun as_run = caseAsRun(*parsed.value, opt);
        if (!as_run.not_run && check && checksCase(opt, f)) {
          CheckedCase checked = checkedCase(check, *as_run.runs, opt);
          if (checked.refused) applyBaseline(baseline, *checked.refused);
          as_run.not_run = std::move(checked.refused);
          p.not_checked = checked.not_checked;
        }
        if (as_run.not_run) {
          p.ready = std::move(as_run.not_run);
        } else {
          p.index = run.cases.size();
          run.cases.push_back(std::move(*as_run.runs));
        }
      }
    }
    run.planned.push_back(std::move(p));
  }
  return run;
}

// How many cases run at once: --jobs, or one per core (at most 16) where the
// device's work is this machine's (lavapipe, saved results), 4 on a GPU (an
// H100 with 16 cores, warm: 8.1 s for the suite with -j 4, 9.5 s with 8,
// 11.8 s with 16, each worker's instance and validation layer costing about
// 3 s of CPU); one without isolation (one backend in this process).
unsigned jobCount(const RunOptions& opt, size_t cases, bool gpu) {
  if (opt.no_isolation) return 1;
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  unsigned jobs = opt.jobs ? opt.jobs : std::min(gpu ? 4u : 16u, cores);
  return static_cast<unsigned>(std::max<size_t>(1, std::min<size_t>(jobs, cases)));
}

// What the threads of a run share; every member function takes the lock.
class RunBook {
 public:
  RunBook(const PreparedRun& prepared, const Baseline& baseline, RunInfo& info,
          const std::string& out, bool brief)
      : outcomes_(prepared.planned.size()),
        baseline_(baseline),
        info_(info),
        out_(out),
        progress_(prepared.planned.size(),
                  brief ? RunSummary::Progress::Brief : RunSummary::Progress::Every) {}

  // The case at `position` ended (or was ready): journal, progress line, and
  // the reports in full now and then.
  void finish(size_t position, CaseOutcome outcome, bool journal = true) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (journal) journalCase(outcome, baseline_, out_);
    progress_.add(outcome);
    outcomes_[position] = std::move(outcome);
    const auto now = std::chrono::steady_clock::now();
    if (reported_ && now - last_reports_ < std::chrono::seconds(2)) return;
    reported_ = true;
    last_reports_ = now;
    if (const Result<void> written = writeReportsLocked(); !written)
      std::fprintf(stderr, "%s\n", visibleLine(written.error().format()).c_str());
  }
  // On a terminal: a live line naming the case that started last.
  void starting(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    progress_.starting(name);
  }
  void teardownErrors(const std::vector<std::string>& messages) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const std::string& m : messages) teardown_.push_back(m);
  }
  // Every case that ended, in the cases' own order.
  std::vector<CaseOutcome> ended() {
    std::lock_guard<std::mutex> lock(mutex_);
    return endedLocked();
  }
  // The reports of what ended. The error: a report not written (the copy
  // that was there stays), naming it and why.
  Result<void> writeAll() {
    std::lock_guard<std::mutex> lock(mutex_);
    return writeReportsLocked();
  }
  std::vector<std::string> teardown() {
    std::lock_guard<std::mutex> lock(mutex_);
    return teardown_;
  }
  void stop() { stopped_ = true; }
  bool stopped() const { return stopped_ || interruptSignal() != 0; }

 private:
  std::vector<CaseOutcome> endedLocked() const {
    std::vector<CaseOutcome> out;
    for (const std::optional<CaseOutcome>& o : outcomes_)
      if (o) out.push_back(*o);
    return out;
  }
  Result<void> writeReportsLocked() {
    std::vector<CaseOutcome> all = endedLocked();
    info_.teardown_errors = teardown_;
    const Result<void> written = writeRunReports(all, baseline_, info_, out_);
    // A case the reports could not show stays the CaseError it became.
    size_t i = 0;
    for (std::optional<CaseOutcome>& o : outcomes_)
      if (o) *o = std::move(all[i++]);
    return written;
  }

  std::mutex mutex_;
  std::vector<std::optional<CaseOutcome>> outcomes_;
  const Baseline& baseline_;
  RunInfo& info_;
  std::string out_;
  RunSummary progress_;
  std::vector<std::string> teardown_;
  bool reported_ = false;
  std::chrono::steady_clock::time_point last_reports_;
  std::atomic<bool> stopped_{false};
};

// A crash in a worker that ran other cases before is not charged to this
// case until it crashes alone: the case runs again, each side in a process of
// its own (into the same folder). If it does not crash there it is judged by
// that run, and the crash becomes a finding of its own ("crashes only in a
// reused process": the driver trips over what an earlier case left). False:
// a signal stopped it.
bool judgeCrashAlone(const CaseRunner& runner, const Case& c, const CaseSlot* slot,
                     CaseOutcome& outcome, bool& interrupted) {
  if (outcome.status != Status::Crash || !slot || (!slot->model && !slot->device)) return true;
  std::printf("        %s: crashed in a reused worker: running it alone\n", c.name.c_str());
  const CaseSlot alone{slot->index, nullptr, nullptr};
  CaseOutcome fresh =
      guardCase(c.name, c.rules, [&] { return runner.run(c, &interrupted, "", &alone); });
  if (interrupted) return false;
  if (fresh.status == Status::Crash) return true;
  fresh.verdict.add({Status::QualityWarning,
                     "reused-process",
                     "crashes only in a reused process: " + outcome.headline +
                         " in a long-lived worker; alone, in processes of its own, it ran and "
                         "was judged (a driver that trips over what earlier cases left, or a "
                         "flake)",
                     {},
                     0});
  fresh.deriveFromVerdict();
  fresh.cost += outcome.cost;
  outcome = std::move(fresh);
  return true;
}

// One case: run, judged by the baseline, run again when the baseline did not
// expect the result (into <case>/rerun, to tell a flake). nullopt: a signal
// stopped it (nothing measured, nothing said).
std::optional<CaseOutcome> runOneCase(const CaseRunner& runner, const Case& c, const PlannedCase& p,
                                      const Baseline& baseline, const CaseSlot* slot) {
  const auto start = std::chrono::steady_clock::now();
  bool interrupted = false;
  CaseOutcome outcome =
      guardCase(c.name, c.rules, [&] { return runner.run(c, &interrupted, "", slot); });
  if (interrupted) return std::nullopt;
  if (!judgeCrashAlone(runner, c, slot, outcome, interrupted)) return std::nullopt;
  outcome.cost[CostSide::Parent] += p.parse_cost;
  if (!p.not_checked.empty()) {
    outcome.verdict.add({Status::Pass, "not-portable", p.not_checked, {}, 0});
    outcome.deriveFromVerdict();
  }
  if (applyBaseline(baseline, outcome)) {
    std::printf("        %s: unexpected %s: running it again\n", c.name.c_str(),
                statusName(outcome.status));
    const CaseOutcome again =
        guardCase(c.name, c.rules, [&] { return runner.run(c, &interrupted, "/rerun", slot); });
    if (interrupted) return std::nullopt;
    applyRerun(outcome, again);
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

bool matchesAnyGlob(const std::vector<std::string>& globs, const std::string& name) {
  for (const std::string& g : globs)
    if (fnmatch(g.c_str(), name.c_str(), 0) == 0) return true;
  return false;
}

// One job slot: takes the next case (longest first) until none is left, each
// side in this slot's long-lived workers (none without isolation).
void runSlot(const CaseRunner& runner, const RunOptions& opt, const PreparedRun& prepared,
             const std::vector<size_t>& order, std::atomic<size_t>& next, const Baseline& baseline,
             RunBook& book) {
  const ChildLimits limits{opt.timeout, opt.memory_limit};
  std::unique_ptr<SideWorker> model, device;
  const bool workers = !opt.no_isolation && !opt.process_per_case;
  if (workers && !opt.no_model)
    model =
        std::make_unique<SideWorker>("model", "model", prepared.cases, modelSideFor(opt), limits);
  if (workers && !opt.no_device)
    device = std::make_unique<SideWorker>("device", "vulkan", prepared.cases, deviceSideFor(opt),
                                          limits);
  for (size_t n; !book.stopped() && (n = next++) < order.size();) {
    const size_t position = order[n];
    const PlannedCase& p = prepared.planned[position];
    const bool own_process = matchesAnyGlob(opt.process_per_case_for, p.name);
    const CaseSlot slot{p.index, own_process ? nullptr : model.get(),
                        own_process ? nullptr : device.get()};
    book.starting(p.name);
    std::optional<CaseOutcome> outcome = runOneCase(runner, prepared.cases[p.index], p, baseline,
                                                    opt.no_isolation ? nullptr : &slot);
    if (!outcome) {
      book.stop();
      break;
    }
    book.finish(position, std::move(*outcome));
  }
  // Each worker ends in the thread that started it (it dies with that thread).
  if (model) book.teardownErrors(model->close());
  if (device) book.teardownErrors(device->close());
}

// The lines that say how the run goes: motions, jobs and limits, baseline.
void announceRun(const RunOptions& opt, unsigned jobs, const Baseline& baseline) {
  if (opt.permute)
    std::printf("Permuted: primitives and instances, seed %llu\n",
                (unsigned long long)*opt.permute);
  if (opt.through)
    std::printf("Through: every case by %s (a case that takes its own way there is NotSupported)\n",
                featurePathName(*opt.through));
  if (opt.move)
    std::printf(
        "Moved: every case by the rigid motion %s (a case it cannot move exactly is "
        "NotSupported)\n",
        motionSpecText(*opt.move).c_str());
  if (!opt.no_isolation)
    std::printf("%u case%s at once, each side in %s: timeout %g s, memory limit %s\n", jobs,
                jobs == 1 ? "" : "s",
                opt.process_per_case ? "a process of its own per case"
                : opt.process_per_case_for.empty()
                    ? "a long-lived worker process (a new one after a crash)"
                    : "a long-lived worker process (a new one after a crash; a process of its own "
                      "for the cases --process-per-case-for names)",
                opt.timeout, opt.memory_limit ? formatBytes(opt.memory_limit).c_str() : "none");
  if (!baseline.file.empty()) {
    std::printf("Baseline: %s (%zu known results)\n", baseline.file.c_str(),
                baseline.expected.size());
    if (!baseline.through_file.empty())
      std::printf("  with what --through changes: %s\n", baseline.through_file.c_str());
    std::vector<std::string> library;
    for (const CaseFile& f : findCases(opt.cases_dir, "*")) library.push_back(f.name);
    for (const std::string& w : unknownEntries(baseline, library))
      std::printf("Baseline warning: %s\n", w.c_str());
  }
  if (!baseline.flakes_file.empty())
    std::printf("Flakes: %s (%zu patterns)\n", baseline.flakes_file.c_str(),
                baseline.flakes.size());
  if (!baseline.skips_file.empty())
    std::printf("Skips: %s (%zu patterns)\n", baseline.skips_file.c_str(), baseline.skips.size());
}

// Takes the cases that need no run (kept as judged, skipped, case-file
// errors, not moved) into the book; the others' positions in the order they
// are dealt: longest first, or their own order with one job (what ran before
// a case in its worker is then the same in every run).
std::vector<size_t> dealOrder(const PreparedRun& prepared, const RunOptions& opt, unsigned jobs,
                              RunBook& book) {
  std::vector<std::string> names;
  std::vector<size_t> positions;
  for (size_t i = 0; i < prepared.planned.size(); ++i) {
    const PlannedCase& p = prepared.planned[i];
    if (p.ready) {
      book.finish(i, *p.ready, !p.resumed);
    } else {
      names.push_back(p.name);
      positions.push_back(i);
    }
  }
  const std::map<std::string, double> seconds =
      jobs > 1 ? loadCaseSeconds(opt.cache_dir) : std::map<std::string, double>{};
  std::vector<size_t> order;
  for (size_t k : longestFirst(names, seconds)) order.push_back(positions[k]);
  return order;
}

// `jobs` slots at once, each a thread with its own workers, until every case
// has been dealt (or a signal stopped the run).
void runSlots(unsigned jobs, const CaseRunner& runner, const RunOptions& opt,
              const PreparedRun& prepared, const std::vector<size_t>& order,
              const Baseline& baseline, RunBook& book) {
  std::atomic<size_t> next{0};
  std::vector<std::thread> slots;
  for (unsigned j = 0; j < jobs; ++j)
    slots.emplace_back([&] { runSlot(runner, opt, prepared, order, next, baseline, book); });
  for (std::thread& t : slots) t.join();
}

// The run's end: timings kept for the next run's order, coverage, the
// reports in full, the summary printed; the exit status.
int finishRun(RunBook& book, RunInfo& info, const RunOptions& opt, size_t planned,
              bool device_found) {
  const std::vector<CaseOutcome> ended = book.ended();
  std::vector<std::pair<std::string, std::vector<std::string>>> case_rules;
  std::map<std::string, double> seconds;
  for (const CaseOutcome& o : ended) {
    case_rules.push_back({o.name, o.rules});
    if (o.status != Status::CaseError && o.seconds > 0) seconds[o.name] = o.seconds;
  }
  saveCaseSeconds(opt.cache_dir, seconds);
  info.coverage = ruleCoverage(info.catalog, case_rules);
  info.interrupted = ended.size() < planned;
  const Result<void> reported = book.writeAll();
  RunSummary summary(planned, RunSummary::Progress::Quiet);
  for (const CaseOutcome& o : book.ended()) summary.add(o);
  for (const std::string& m : book.teardown()) summary.addTeardownError(m);
  summary.print(opt.brief, info.baseline);
  if (info.interrupted) std::printf("INTERRUPTED: %zu of %zu cases ran\n", ended.size(), planned);
  if (!reported) {
    std::fprintf(stderr, "rayspec run: the reports are not complete: %s\n",
                 visibleLine(reported.error().format()).c_str());
    return kExitReports;
  }
  std::printf("Reports: %s/report.html, results.csv, junit.xml, summary.json\n", opt.out.c_str());
  const int status = runExitStatus(summary, planned, device_found, interruptSignal());
  if (status == kExitNothingCompared)
    std::fprintf(stderr, "rayspec run: nothing was compared: every case is NotSupported\n");
  return status;
}

// Without isolation the model runs in this process; with it, in workers.
std::unique_ptr<ModelAdapter> inProcessModel(const RunOptions& opt) {
  if (opt.no_model || !opt.no_isolation) return nullptr;
  return std::make_unique<ModelAdapter>(ModelOptions{checkedModelTier(opt), opt.threads});
}

// The cases in files, dealt to `jobs` slots, judged and reported.
int runPreparedCases(const RunOptions& opt, const std::vector<CaseFile>& files,
                     const Baseline& baseline, RunInfo& info, ChosenDevice& device, unsigned jobs,
                     std::map<std::string, CaseOutcome>& earlier, const CaseCheck& check) {
  std::unique_ptr<ModelAdapter> model = inProcessModel(opt);
  // Before the first fork: every case process inherits it.
  if (const Result<void> cached = useCacheDir(opt.cache_dir); !cached)
    std::fprintf(stderr, "rayspec run: %s\n", cached.error().format().c_str());
  // Unknown rule labels are case-file errors at their line:col (the parser checks them).
  const PreparedRun prepared =
      prepareCases(files, opt, baseline, ruleLabels(info.catalog), earlier, check);
  std::error_code ec;
  std::filesystem::create_directories(opt.out, ec);
  if (!opt.resume)
    if (const Result<void> started = startJournal(opt.out); !started)
      std::fprintf(stderr, "rayspec run: %s\n", visibleLine(started.error().format()).c_str());
  RunBook book(prepared, baseline, info, opt.out, opt.brief);
  // Empty and marked interrupted until the run ends.
  if (const Result<void> written = book.writeAll(); !written)
    std::fprintf(stderr, "rayspec run: %s\n", visibleLine(written.error().format()).c_str());
  const std::vector<size_t> order = dealOrder(prepared, opt, jobs, book);
  catchInterrupts();
  const CaseRunner runner(opt, device.adapter.get(), model.get(), device.probed);
  runSlots(jobs, runner, opt, prepared, order, baseline, book);
  if (device.adapter) book.teardownErrors(device.adapter->close());
  return finishRun(book, info, opt, files.size(), device.found);
}

// The run folder, held until the run ends; nothing in it is written through
// a link.
Result<OutputFolder> claimRunFolder(const RunOptions& opt, const std::vector<CaseFile>& files) {
  std::vector<std::string> names;
  for (const CaseFile& f : files) names.push_back(f.name);
  return claimOutputFolder(opt.out, runFolderWrites(names), "run");
}

}  // namespace

// The steps of a run; a step that fails ends it before any case runs
// (kExitSetup), naming why.
int runCases(const RunOptions& requested, const CaseCheck& check) {
  RunOptions opt = optionsForThisBuild(requested);
  Result<std::vector<CaseFile>> files = selectedCaseFiles(opt);
  if (!files) return setupFailed(files.error());
  const IcdSelection icd =
      useIcdFiles(opt.icd_files);  // before any Vulkan call; children inherit it
  for (const std::string& note : icd.notes) std::fprintf(stderr, "rayspec run: %s\n", note.c_str());
  if (!icd.error.empty()) return setupFailed(errorMessage(icd.error));
  files = thisShard(opt, std::move(*files));
  if (!files) return setupFailed(files.error());
  RunInfo info = startRunInfo(opt, files->size());
  const Result<Baseline> baseline = loadRunBaseline(opt);
  if (!baseline) return setupFailed(baseline.error());
  info.baseline = baseline->file;
  const Result<OutputFolder> out = claimRunFolder(opt, *files);
  if (!out) return setupFailed(out.error());
  Result<ChosenDevice> device = chooseDevice(opt, *files, icd, info);
  if (!device) return setupFailed(device.error());
  const unsigned jobs = jobCount(opt, files->size(), device->gpu);
  // The model's threads shared among the cases that run at once.
  if (opt.threads == 0 && jobs > 1)
    opt.threads = std::max(1u, std::thread::hardware_concurrency() / jobs);
  if (!opt.no_model) std::printf("Model: embree, %s tier\n", opt.model_tier.c_str());
  announceRun(opt, jobs, *baseline);
  Result<std::map<std::string, CaseOutcome>> earlier = resumedCases(opt, info, *files);
  if (!earlier) return setupFailed(earlier.error());
  return runPreparedCases(opt, *files, *baseline, info, *device, jobs, *earlier, check);
}

int runExitStatus(const RunSummary& summary, size_t planned, bool device_found, int signal) {
  if (signal) return 128 + signal;
  if (summary.failed()) return kExitFailing;
  if (summary.allNotSupported() || summary.outcomes().empty())
    return planned == 1 && device_found && !summary.outcomes().empty() ? kExitNotSupported
                                                                       : kExitNothingCompared;
  return kExitPass;
}

}  // namespace rayspec
