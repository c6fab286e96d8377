// A long-lived child process that serves requests one at a time (deqp-runner's
// answer to a process per test): the parent sends a request, the child runs
// `serve` on it and sends back the reply. The child is set up as a child of
// run/child_process.h is (dies with the thread that started it, default
// SIGINT / SIGTERM, the memory limit, out of memory ends it with
// kChildOutOfMemory) and closes every file descriptor of the parent but its
// own socket, so that closing one worker is seen by that worker alone.
//
// When the child ends without replying (crash, out of memory, timeout: the
// parent kills it, interrupt: likewise), call() says how, as runChild's
// ChildEnd does, and the next call() starts a new child: whatever the request
// did costs only that request. An error `serve` returns (or an exception of
// the standard library escaping it) is a reply of its own kind
// (Reply::failed) and the child goes on.
#pragma once

#include "base/result.h"

#include <sys/types.h>

#include <functional>
#include <string>
#include <utility>

#include "run/child_process.h"

namespace rayspec {

class Worker {
 public:
  // Runs in the child, once per request: the reply, or the error.
  using Serve = std::function<Result<std::string>(const std::string& request)>;
  // Runs in the child when the parent closes it: the last reply.
  using Finish = std::function<std::string()>;

  struct Reply {
    bool replied = false;  // the child answered; otherwise `end` says how it ended
    bool failed = false;   // the answer is the message of the error `serve` returned
    std::string text;
    ChildEnd end;        // replied: how = Exited, code 0
    double seconds = 0;  // from the request sent to the reply (or the end)
  };

  Worker(Serve serve, Finish finish, ChildLimits limits);
  Worker(std::pair<Serve, Finish> both, ChildLimits limits)
      : Worker(std::move(both.first), std::move(both.second), limits) {}
  ~Worker();  // kills a child still running
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;

  // Sends the request to the child (starting one first when none runs) and
  // waits for its reply, at most the limits' timeout.
  Reply call(const std::string& request);
  // Ends the child: Finish's reply, or "" when no child runs or it did not
  // answer within the timeout (then it is killed).
  std::string close();

  bool running() const { return pid_ > 0; }
  int started() const { return started_; }  // children started so far

 private:
  Result<void> start();
  // Waits for the child (at most grace_seconds), then kills it if it is
  // still alive (`how_if_alive`: why) and closes the socket.
  ChildEnd reap(ChildEnd::How how_if_alive, double grace_seconds = 0);
  bool await(Reply& reply, double timeout_seconds);

  Serve serve_;
  Finish finish_;
  ChildLimits limits_;
  pid_t pid_ = -1;
  int fd_ = -1;
  int started_ = 0;
};

}  // namespace rayspec
