#include "cli/device_child.h"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include "fault/planted_fault.h"
#include "results/image_files.h"
#include "results/results_io.h"

namespace rayspec {
namespace {

const char* kFaultNote = "planted_fault.txt";

std::string plant(const std::string& fault, const Case& c, const Plan& plan, Results& device, const Results& model) {
  if (fault.empty() || isProcessFault(fault)) return {};
  const FaultResult f = plantFault(fault, c, plan, device, model);
  return (f.applied ? "planted fault " : "planted fault not applicable: ") + fault + ": " + f.what;
}

void save(const Results& device, const Plan& plan, const std::string& dir, const std::string& note,
          bool image_files) {
  const std::string err = writeResults(device, dir, plan.record_fields, image_files);
  if (!err.empty()) std::fprintf(stderr, "%s\n", err.c_str());
  if (!note.empty()) std::ofstream(dir + "/" + kFaultNote) << note << '\n';
}

[[noreturn]] void childMain(const Case& c, const Plan& plan, const Results& model, const DeviceRun& run,
                            const std::string& dir) {
  Results device;
  std::string error;
  {
    std::unique_ptr<VulkanBackend> backend = VulkanBackend::create(run.vulkan, &error);
    if (backend) {
      device = backend->run(c, plan);
      for (const std::string& m : backend->close())
        device.validation_messages.push_back("at device teardown: " + m);
    } else {
      device.backend = "vulkan";
      device.setStatus(RunStatus::NotSupported, error);
    }
  }
  device.case_name = c.name;
  device.case_file = c.file;
  if (run.fault == "crash" || run.fault == "hang") raiseProcessFault(run.fault);
  const std::string note = plant(run.fault, c, plan, device, model);
  save(device, plan, dir, note, false);  // the parent writes the pictures
  std::fflush(nullptr);
  _exit(0);
}

Results failed(const Case& c, RunStatus status, const std::string& detail, double seconds) {
  Results r;
  r.backend = "vulkan";
  r.case_name = c.name;
  r.case_file = c.file;
  r.setStatus(status, detail);
  r.seconds = seconds;
  return r;
}

std::string readNote(const std::string& dir) {
  std::ifstream in(dir + "/" + kFaultNote);
  std::string line;
  std::getline(in, line);
  return line;
}

}  // namespace

Results runDeviceIsolated(const Case& c, const Plan& plan, const Results& model, const DeviceRun& run,
                          const std::string& dir, std::string* fault_note) {
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return failed(c, RunStatus::Crash, std::string("fork failed: ") + std::strerror(errno), 0.0);
  if (pid == 0) childMain(c, plan, model, run, dir);

  int wstatus = 0;
  for (;;) {
    const pid_t done = waitpid(pid, &wstatus, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) return failed(c, RunStatus::Crash, "lost the device process", elapsed());
    if (elapsed() > run.timeout_seconds) {
      kill(pid, SIGKILL);
      waitpid(pid, &wstatus, 0);
      std::ostringstream s;
      s << "the device side ran longer than " << run.timeout_seconds << " s (killed)";
      return failed(c, RunStatus::Timeout, s.str(), elapsed());
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (WIFSIGNALED(wstatus)) {
    const int sig = WTERMSIG(wstatus);
    return failed(c, RunStatus::Crash, "the device process died of signal " + std::to_string(sig) + " (" + strsignal(sig) + ")",
                  elapsed());
  }
  if (!WIFEXITED(wstatus) || WEXITSTATUS(wstatus) != 0)
    return failed(c, RunStatus::Crash, "the device process exited with status " + std::to_string(WEXITSTATUS(wstatus)),
                  elapsed());
  std::string error;
  Results device = readResults(dir, &error);
  if (!error.empty()) return failed(c, RunStatus::Crash, "no results from the device process: " + error, elapsed());
  *fault_note = readNote(dir);
  for (const Image& im : device.images) {
    const std::string err = writeImageFiles(im, dir);
    if (!err.empty()) std::fprintf(stderr, "%s\n", err.c_str());
  }
  return device;
}

Results runDeviceInProcess(const Case& c, const Plan& plan, const Results& model, VulkanBackend* backend,
                           const std::string& backend_error, const std::string& fault, const std::string& dir,
                           std::string* fault_note) {
  Results device;
  if (backend) {
    device = backend->run(c, plan);
  } else {
    device.backend = "vulkan";
    device.setStatus(RunStatus::NotSupported, backend_error);
  }
  device.case_name = c.name;
  device.case_file = c.file;
  *fault_note = plant(fault, c, plan, device, model);
  save(device, plan, dir, *fault_note, true);
  return device;
}

}  // namespace rayspec
