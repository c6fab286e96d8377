#include "run/isolation.h"

#include <algorithm>
#include <filesystem>

#include "plan/plan.h"
#include "results/image_files.h"
#include "results/results_io.h"

namespace rayspec {
namespace {

// A child writes neither pictures nor records.csv (the parent does: pictures
// always, records.csv where the case does not pass, run/case_steps.h).
constexpr BundleFiles kChildBundle{false, false};

// The part both ways share: run, name the results, let `after` see them.
Results runSide(const Side& side, Backend& backend, const Case& c, const Plan& plan, std::string* note) {
  if (side.before) side.before();
  Results r = backend.run(c, plan);
  r.case_name = c.name;
  r.case_file = c.file;
  r.case_hash = c.source_hash;
  if (side.after) *note = side.after(c, plan, r);
  return r;
}

Results failed(const Side& side, const Case& c, RunStatus status, const std::string& detail, double seconds) {
  Results r;
  r.backend = side.backend_name;
  r.case_name = c.name;
  r.case_file = c.file;
  r.case_hash = c.source_hash;
  r.setStatus(status, detail);
  r.seconds = seconds;
  return r;
}

// A side whose process died leaves a bundle that says so (status Crash or
// Timeout), in place of whatever the child had half written: a saved run
// judged elsewhere (--device-results) then shows the crash. Best effort: the
// case is that Crash or Timeout whether or not the bundle could be written.
SideResult ended(const Side& side, const Case& c, const Plan& plan, RunStatus status, const std::string& detail,
                 double seconds, const std::string& dir) {
  SideResult out;
  out.results = failed(side, c, status, detail, seconds);
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  writeResults(out.results, dir, plan.record_fields, kChildBundle);
  return out;
}

}  // namespace

SideResult runIsolated(const Side& side, const Case& c, const Plan& plan, const ChildLimits& limits,
                       const std::string& dir) {
  const std::string who = "the " + side.label + " process";
  const ChildEnd end = runChild(
      [&](std::string& message) {
        StepCosts setup;
        StepTimer setup_time(setup, CostStep::BackendSetup);
        std::unique_ptr<Backend> backend = side.make();
        setup_time.stop();
        Results r = runSide(side, *backend, c, plan, &message);
        r.cost += setup;
        StepTimer teardown_time(r.cost, CostStep::BackendTeardown);
        for (const std::string& m : backend->close()) r.validation_messages.push_back("at device teardown: " + m);
        backend.reset();
        teardown_time.stop();
        const std::string err = writeResults(r, dir, plan.record_fields, kChildBundle);  // the parent writes the pictures
        if (!err.empty()) throw HarnessError(err);
        return 0;
      },
      limits);
  SideResult out;
  switch (end.how) {
    case ChildEnd::How::Interrupted:
      out.interrupted = true;
      out.results = failed(side, c, RunStatus::Crash, describeChildEnd(end, who, limits), end.seconds);
      return out;
    case ChildEnd::How::TimedOut:
      return ended(side, c, plan, RunStatus::Timeout, describeChildEnd(end, who, limits), end.seconds, dir);
    case ChildEnd::How::Signaled:
      return ended(side, c, plan, RunStatus::Crash, describeChildEnd(end, who, limits), end.seconds, dir);
    case ChildEnd::How::NotStarted: throw HarnessError(describeChildEnd(end, who, limits));
    case ChildEnd::How::Exited:
      if (end.code == kChildException) throw HarnessError(side.label + " side: " + end.message);
      if (end.code != 0)
        return ended(side, c, plan, RunStatus::Crash, describeChildEnd(end, who, limits), end.seconds, dir);
  }
  std::string error;
  StepCosts parent;  // the parent's own steps for this side
  StepTimer read_time(parent, CostStep::ReadBundle);
  out.results = readResults(dir, &error);
  read_time.stop();
  if (!error.empty()) throw HarnessError(side.label + " side: " + error);
  out.note = end.message;
  StepTimer image_time(parent, CostStep::ImageFiles);
  for (const Image& im : out.results.images) {
    const std::string err = writeImageFiles(im, dir);
    if (!err.empty()) throw HarnessError(side.label + " side: " + err);
  }
  image_time.stop();
  // What the child did not account for: fork, exit, the loader, waiting.
  parent.add(CostStep::Process, std::max(0.0, end.seconds - out.results.cost.total()));
  out.results.cost += parent;
  return out;
}

SideResult runInProcess(const Side& side, Backend& backend, const Case& c, const Plan& plan, const std::string& dir) {
  SideResult out;
  out.results = runSide(side, backend, c, plan, &out.note);
  StepTimer write_time(out.results.cost, CostStep::WriteBundle);
  const std::string err = writeResults(out.results, dir, plan.record_fields, BundleFiles{true, false});
  write_time.stop();
  if (!err.empty()) throw HarnessError(side.label + " side: " + err);
  return out;
}

}  // namespace rayspec
