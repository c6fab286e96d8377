#include "run/isolation.h"

#include "plan/plan.h"
#include "results/image_files.h"
#include "results/results_io.h"

namespace rayspec {
namespace {

// The part both ways share: run, name the results, let `after` see them.
Results runSide(const Side& side, Backend& backend, const Case& c, const Plan& plan, std::string* note) {
  if (side.before) side.before();
  Results r = backend.run(c, plan);
  r.case_name = c.name;
  r.case_file = c.file;
  if (side.after) *note = side.after(c, plan, r);
  return r;
}

Results failed(const Side& side, const Case& c, RunStatus status, const std::string& detail, double seconds) {
  Results r;
  r.backend = side.backend_name;
  r.case_name = c.name;
  r.case_file = c.file;
  r.setStatus(status, detail);
  r.seconds = seconds;
  return r;
}

}  // namespace

SideResult runIsolated(const Side& side, const Case& c, const Plan& plan, const ChildLimits& limits,
                       const std::string& dir) {
  const std::string who = "the " + side.label + " process";
  const ChildEnd end = runChild(
      [&](std::string& message) {
        std::unique_ptr<Backend> backend = side.make();
        Results r = runSide(side, *backend, c, plan, &message);
        for (const std::string& m : backend->close()) r.validation_messages.push_back("at device teardown: " + m);
        backend.reset();
        const std::string err = writeResults(r, dir, plan.record_fields, false);  // the parent writes the pictures
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
      out.results = failed(side, c, RunStatus::Timeout, describeChildEnd(end, who, limits), end.seconds);
      return out;
    case ChildEnd::How::Signaled:
      out.results = failed(side, c, RunStatus::Crash, describeChildEnd(end, who, limits), end.seconds);
      return out;
    case ChildEnd::How::NotStarted: throw HarnessError(describeChildEnd(end, who, limits));
    case ChildEnd::How::Exited:
      if (end.code == kChildException) throw HarnessError(side.label + " side: " + end.message);
      if (end.code != 0) {
        out.results = failed(side, c, RunStatus::Crash, describeChildEnd(end, who, limits), end.seconds);
        return out;
      }
  }
  std::string error;
  out.results = readResults(dir, &error);
  if (!error.empty()) throw HarnessError(side.label + " side: " + error);
  out.note = end.message;
  for (const Image& im : out.results.images) {
    const std::string err = writeImageFiles(im, dir);
    if (!err.empty()) throw HarnessError(side.label + " side: " + err);
  }
  return out;
}

SideResult runInProcess(const Side& side, Backend& backend, const Case& c, const Plan& plan, const std::string& dir) {
  SideResult out;
  out.results = runSide(side, backend, c, plan, &out.note);
  const std::string err = writeResults(out.results, dir, plan.record_fields, true);
  if (!err.empty()) throw HarnessError(side.label + " side: " + err);
  return out;
}

}  // namespace rayspec
