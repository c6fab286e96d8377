// writePlots: the script beside the image, and gnuplot run on it.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "base/whole_file.h"
#include "plot/line_plot.h"

extern char** environ;

namespace rayspec {
namespace {

// Runs `gnuplot script` with its output into `log`; the exit status, or -1
// with errno set where it could not start.
int runGnuplot(const std::string& script, const std::string& log) {
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_adddup2(&files, STDOUT_FILENO, STDERR_FILENO);
  const char* argv[] = {"gnuplot", script.c_str(), nullptr};
  pid_t pid = 0;
  const int started =
      posix_spawnp(&pid, "gnuplot", &files, nullptr, const_cast<char* const*>(argv), environ);
  posix_spawn_file_actions_destroy(&files);
  if (started != 0) {
    errno = started;
    return -1;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

Result<void> writePlots(const std::string& path, const std::vector<PlotPanel>& panels,
                        const PlotLayout& layout) {
  if (panels.empty()) return errorMessage("nothing to plot: no panel");
  const std::string script = path + ".gp", log = path + ".gnuplot-log";
  if (Result<void> r = writeWholeFile(script, gnuplotScript(path, panels, layout)); !r) return r;
  std::error_code ec;
  std::filesystem::remove(path, ec);  // an old image must not pass for a new one
  const int rc = runGnuplot(script, log);
  // What gnuplot printed, for the error (its first 64 KiB).
  const Result<std::string> printed_text = readWholeFile(log, 64u << 10);
  const std::string printed = printed_text ? *printed_text : printed_text.error().format();
  std::filesystem::remove(log, ec);
  if (rc < 0)
    return errorMessage("cannot run gnuplot for " + path + ": " + std::strerror(errno) +
                        " (tools/setup.sh installs gnuplot-nox)");
  if (rc != 0 || !std::filesystem::exists(path))
    return errorMessage("gnuplot " + script + " failed (exit " + std::to_string(rc) +
                        "): " + printed);
  return {};
}

}  // namespace rayspec
