#include "run/isolation.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <utility>

#include "bundle/image_files.h"
#include "bundle/results_io.h"
#include "plan/plan.h"

namespace rayspec {
namespace {

// A child writes neither pictures nor records.csv (the parent does: pictures
// always, records.csv where the case does not pass, run/case_steps.h).
constexpr BundleFiles kChildBundle{false, false};

// A Harness error (the case becomes a CaseError).
Error harnessError(std::string message) {
  return errorOf(ErrorKind::Harness, std::move(message));
}

// The part both ways share: run, name the results, let `after` see them.
Result<Results> runSide(const Side& side, Backend& backend, const Case& c, const Plan& plan,
                        std::string* note) {
  if (side.before) side.before();
  RAYSPEC_TRY(Results r, backend.run(c, plan));
  r.case_name = c.name;
  r.case_file = c.file;
  r.case_hash = c.source_hash;
  if (side.after) *note = side.after(c, plan, r);
  return r;
}

Results failed(const std::string& backend_name, const Case& c, SideStatus status,
               const std::string& detail, double seconds) {
  Results r;
  r.backend = backend_name;
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
SideResult ended(const std::string& backend_name, const Case& c, const Plan& plan,
                 SideStatus status, const std::string& detail, double seconds,
                 const std::string& dir) {
  SideResult out;
  out.results = failed(backend_name, c, status, detail, seconds);
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  (void)writeResults(out.results, dir, plan.record_fields, kChildBundle);  // best effort
  return out;
}

// The parent's half of a side run in another process: how the process ended
// made into Results (Crash, Timeout), or the bundle it wrote read back and its
// pictures written; or the Harness error of a child that could not report.
Result<SideResult> collect(const std::string& label, const std::string& backend_name, const Case& c,
                           const Plan& plan, const ChildEnd& end, const ChildLimits& limits,
                           const std::string& dir) {
  const std::string who = "the " + label + " process";
  SideResult out;
  switch (end.how) {
    case ChildEnd::How::Interrupted:
      out.interrupted = true;
      out.results = failed(backend_name, c, SideStatus::Crash, describeChildEnd(end, who, limits),
                           end.seconds);
      return out;
    case ChildEnd::How::TimedOut:
      return ended(backend_name, c, plan, SideStatus::Timeout, describeChildEnd(end, who, limits),
                   end.seconds, dir);
    case ChildEnd::How::Signaled:
      return ended(backend_name, c, plan, SideStatus::Crash, describeChildEnd(end, who, limits),
                   end.seconds, dir);
    case ChildEnd::How::NotStarted:
      return harnessError(describeChildEnd(end, who, limits));
    case ChildEnd::How::Exited:
      if (end.code == kChildException) return harnessError(label + " side: " + end.message);
      if (end.code != 0)
        return ended(backend_name, c, plan, SideStatus::Crash, describeChildEnd(end, who, limits),
                     end.seconds, dir);
  }
  StepCosts parent;  // the parent's own steps for this side
  StepTimer read_time(parent, CostStep::ReadBundle);
  Result<Results> read = readResults(dir);
  read_time.stop();
  if (!read) return harnessError(label + " side: " + read.error().format());
  out.results = std::move(*read);
  out.note = end.message;
  StepTimer image_time(parent, CostStep::ImageFiles);
  for (const Image& im : out.results.images)
    if (const Result<void> written = writeImageFiles(im, dir); !written)
      return harnessError(label + " side: " + written.error().format());
  image_time.stop();
  // What the child did not account for: fork, exit, the loader, waiting.
  parent.add(CostStep::Process, std::max(0.0, end.seconds - out.results.cost.total()));
  out.results.cost += parent;
  return out;
}

// The child's work under runIsolated: makes the backend, runs the case,
// closes the backend and writes the bundle (not the pictures: the parent
// writes them). `note`: what `after` said.
Result<void> runAndWrite(const Side& side, const Case& c, const Plan& plan, const std::string& dir,
                         std::string& note) {
  StepCosts setup;
  StepTimer setup_time(setup, CostStep::BackendSetup);
  std::unique_ptr<Backend> backend = side.make();
  setup_time.stop();
  RAYSPEC_TRY(Results r, runSide(side, *backend, c, plan, &note));
  r.cost += setup;
  StepTimer teardown_time(r.cost, CostStep::BackendTeardown);
  for (const std::string& m : backend->close())
    r.validation_messages.push_back("at device teardown: " + m);
  backend.reset();
  teardown_time.stop();
  return writeResults(r, dir, plan.record_fields, kChildBundle);
}

}  // namespace

Result<SideResult> runIsolated(const Side& side, const Case& c, const Plan& plan,
                               const ChildLimits& limits, const std::string& dir) {
  const ChildEnd end = runChild(
      [&](std::string& message) {
        // An error reaches the parent as the message of a kChildException end.
        const Result<void> ran = runAndWrite(side, c, plan, dir, message);
        if (!ran) message = ran.error().format();
        return ran ? 0 : kChildException;
      },
      limits);
  return collect(side.label, side.backend_name, c, plan, end, limits, dir);
}

namespace {

// The worker's side of SideWorker: each request is "INDEX\nDIR"; the backend
// is made by the first case's side and kept.
struct ServedSide {
  const std::vector<Case>* cases;
  SideFor side_for;
  std::unique_ptr<Backend> backend;

  Result<std::string> serve(const std::string& request) {
    const size_t newline = request.find('\n');
    const size_t index = std::stoul(request.substr(0, newline));
    const std::string dir = request.substr(newline + 1);
    const Case& c = cases->at(index);
    const Plan plan = derivePlan(c);
    RAYSPEC_TRY(const Side side, side_for(c, dir));
    StepCosts setup;
    if (!backend) {
      StepTimer setup_time(setup, CostStep::BackendSetup);
      backend = side.make();
    }
    std::string note;
    RAYSPEC_TRY(Results r, runSide(side, *backend, c, plan, &note));
    r.cost += setup;
    // The parent writes the pictures.
    RAYSPEC_TRY_VOID(writeResults(r, dir, plan.record_fields, kChildBundle));
    return note;
  }

  std::string finish() {
    std::string out;
    if (backend)
      for (const std::string& m : backend->close()) out += m + '\n';
    backend.reset();
    return out;
  }
};

// serve and finish of one ServedSide (in the worker, they share its backend).
std::pair<Worker::Serve, Worker::Finish> servedSide(const std::vector<Case>& cases,
                                                    SideFor side_for) {
  auto served = std::make_shared<ServedSide>(ServedSide{&cases, std::move(side_for), nullptr});
  return {[served](const std::string& request) { return served->serve(request); },
          [served] {
            return served->finish();
          }};
}

}  // namespace

SideWorker::SideWorker(std::string label, std::string backend_name, const std::vector<Case>& cases,
                       SideFor side_for, const ChildLimits& limits)
    : label_(std::move(label)),
      backend_name_(std::move(backend_name)),
      cases_(cases),
      limits_(limits),
      worker_(servedSide(cases, std::move(side_for)), limits) {}

Result<SideResult> SideWorker::run(size_t index, const Plan& plan, const std::string& dir) {
  const Worker::Reply reply = worker_.call(std::to_string(index) + "\n" + dir);
  if (reply.failed) return harnessError(label_ + " side: " + reply.text);
  ChildEnd end = reply.end;
  end.seconds = reply.seconds;
  end.message = reply.text;
  return collect(label_, backend_name_, cases_.at(index), plan, end, limits_, dir);
}

std::vector<std::string> SideWorker::close() {
  std::vector<std::string> out;
  const std::string text = worker_.close();
  for (size_t at = 0; at < text.size();) {
    const size_t end = text.find('\n', at);
    out.push_back(text.substr(at, end - at));
    at = end == std::string::npos ? text.size() : end + 1;
  }
  return out;
}

Result<SideResult> runInProcess(const Side& side, Backend& backend, const Case& c, const Plan& plan,
                                const std::string& dir) {
  SideResult out;
  RAYSPEC_TRY(out.results, runSide(side, backend, c, plan, &out.note));
  StepTimer write_time(out.results.cost, CostStep::WriteBundle);
  const Result<void> written =
      writeResults(out.results, dir, plan.record_fields, BundleFiles{true, false});
  write_time.stop();
  if (!written) return harnessError(side.label + " side: " + written.error().format());
  return out;
}

}  // namespace rayspec
