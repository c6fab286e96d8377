#include "run/worker.h"

#include <poll.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <thread>

#include "run/interrupt.h"

namespace rayspec {
namespace {

// The child keeps its socket at this descriptor and closes every other one
// above stderr.
constexpr int kWorkerFd = 3;

// A message on the socket: kind ('Q' request, 'R' reply, 'E' exception),
// 8 bytes of length (little endian), the text.
constexpr size_t kHeader = 9;

bool sendAll(int fd, const char* data, size_t size) {
  while (size) {
    const ssize_t n = send(fd, data, size, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<size_t>(n);
  }
  return true;
}

bool sendMessage(int fd, char kind, const std::string& text) {
  char header[kHeader];
  header[0] = kind;
  uint64_t size = text.size();
  for (size_t i = 1; i < kHeader; ++i, size >>= 8) header[i] = static_cast<char>(size & 0xff);
  return sendAll(fd, header, kHeader) && sendAll(fd, text.data(), text.size());
}

// Whether `buffer` holds a whole message; then its kind and text.
bool wholeMessage(const std::string& buffer, char* kind, std::string* text) {
  if (buffer.size() < kHeader) return false;
  uint64_t size = 0;
  for (size_t i = kHeader - 1; i >= 1; --i)
    size = (size << 8) | static_cast<unsigned char>(buffer[i]);
  if (buffer.size() - kHeader < size) return false;
  *kind = buffer[0];
  *text = buffer.substr(kHeader, size);
  return true;
}

// The child's side: blocking reads of one request at a time. False at the
// end of the stream (the parent closed it or is gone).
bool receiveRequest(int fd, std::string* request) {
  std::string buffer;
  char kind = 0;
  char chunk[65536];
  while (!wholeMessage(buffer, &kind, request)) {
    const ssize_t n = recv(fd, chunk, sizeof chunk, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    buffer.append(chunk, static_cast<size_t>(n));
  }
  return kind == 'Q';
}

[[noreturn]] void serveForever(pid_t parent, int fd, const Worker::Serve& serve,
                               const Worker::Finish& finish, const ChildLimits& limits) {
  prepareChild(parent, limits);
  if (fd != kWorkerFd) {
    dup2(fd, kWorkerFd);
    close(fd);
  }
  close_range(kWorkerFd + 1, ~0U, 0);  // the other workers' sockets, the parent's files
  std::string request;
  while (receiveRequest(kWorkerFd, &request)) {
    char kind = 'R';
    std::string reply;
    try {
      Result<std::string> served = serve(request);
      if (served) {
        reply = std::move(*served);
      } else {
        kind = 'E';
        reply = served.error().format();
      }
    } catch (const std::exception& e) {  // the standard library's (std::bad_alloc ...)
      kind = 'E';
      reply = e.what();
    }
    if (!sendMessage(kWorkerFd, kind, reply)) _exit(0);  // the parent is gone
  }
  char kind = 'R';
  std::string last;
  try {
    last = finish();
  } catch (const std::exception& e) {
    kind = 'E';
    last = e.what();
  }
  const int code = kAddressSanitizer && childLeaked() ? kChildLeaked : 0;
  sendMessage(kWorkerFd, kind, last);
  close(kWorkerFd);
  std::fflush(nullptr);
  _exit(code);
}

double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Worker::Worker(Serve serve, Finish finish, ChildLimits limits)
    : serve_(std::move(serve)), finish_(std::move(finish)), limits_(limits) {}

Worker::~Worker() {
  if (pid_ > 0) reap(ChildEnd::How::Interrupted);
}

Result<void> Worker::start() {
  int fds[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0)
    return errorMessage(std::string("socketpair failed: ") + std::strerror(errno));
  std::fflush(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    const int fork_errno = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    return errorMessage(std::string("fork failed: ") + std::strerror(fork_errno));
  }
  if (pid == 0) {
    ::close(fds[0]);
    serveForever(parent, fds[1], serve_, finish_, limits_);
  }
  ::close(fds[1]);
  pid_ = pid;
  fd_ = fds[0];
  ++started_;
  return {};
}

ChildEnd Worker::reap(ChildEnd::How how_if_alive, double grace_seconds) {
  ChildEnd end;
  int wstatus = 0;
  pid_t done = waitpid(pid_, &wstatus, WNOHANG);
  // A child that closed its socket is ending: it gets a moment to be gone.
  for (const auto start = std::chrono::steady_clock::now();
       done == 0 && since(start) < grace_seconds;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    done = waitpid(pid_, &wstatus, WNOHANG);
  }
  if (done == 0) {  // still alive: the parent ends it
    kill(pid_, SIGKILL);
    while ((done = waitpid(pid_, &wstatus, 0)) < 0 && errno == EINTR) {
    }
    end.how = how_if_alive;
    if (how_if_alive == ChildEnd::How::NotStarted)
      end.error = "the worker process stopped answering and did not end";
  } else if (done == pid_ && WIFSIGNALED(wstatus)) {
    end.how = ChildEnd::How::Signaled;
    end.code = WTERMSIG(wstatus);
  } else if (done == pid_) {
    end.how = ChildEnd::How::Exited;
    end.code = WEXITSTATUS(wstatus);
  } else {
    end.how = ChildEnd::How::NotStarted;
    end.error = "lost the worker process";
  }
  ::close(fd_);
  fd_ = -1;
  pid_ = -1;
  return end;
}

// Waits for a whole reply; false when the child ended, timed out or the run
// was interrupted first (reply.end says which; the child is gone then).
bool Worker::await(Reply& reply, double timeout_seconds) {
  const auto start = std::chrono::steady_clock::now();
  std::string buffer;
  char kind = 0;
  char chunk[65536];
  MemoryWatch memory(pid_, limits_.memory_limit);
  for (;;) {
    if (wholeMessage(buffer, &kind, &reply.text)) {
      reply.replied = true;
      reply.failed = kind == 'E';
      reply.end.how = ChildEnd::How::Exited;
      reply.end.code = 0;
      return true;
    }
    pollfd p{fd_, POLLIN, 0};
    const int ready = poll(&p, 1, 20);
    if (ready > 0) {
      const ssize_t n = recv(fd_, chunk, sizeof chunk, 0);
      if (n > 0) {
        buffer.append(chunk, static_cast<size_t>(n));
        continue;
      }
      if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
      // The child closed its end: it has ended, or is ending.
      reply.end = reap(ChildEnd::How::NotStarted, 5);
      break;
    }
    if (interruptSignal() != 0) {
      reply.end = reap(ChildEnd::How::Interrupted);
      break;
    }
    if (timeout_seconds > 0 && since(start) > timeout_seconds) {
      reply.end = reap(ChildEnd::How::TimedOut);
      break;
    }
    if (memory.over()) {  // the resident set, shared mappings included
      reply.end = reap(ChildEnd::How::Exited);
      reply.end.how = ChildEnd::How::Exited;
      reply.end.code = kChildOutOfMemory;
      break;
    }
  }
  // A child killed by the terminal's SIGINT with the rest of the process group.
  if (interruptSignal() != 0) reply.end.how = ChildEnd::How::Interrupted;
  reply.end.seconds = since(start);
  return false;
}

Worker::Reply Worker::call(const std::string& request) {
  Reply reply;
  const auto began = std::chrono::steady_clock::now();
  // A child that died while idle (nothing of this request ran) is replaced once.
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (Result<void> started = pid_ > 0 ? Result<void>() : start(); !started) {
      reply.end.how = ChildEnd::How::NotStarted;
      reply.end.error = started.error().format();
      return reply;
    }
    if (sendMessage(fd_, 'Q', request)) break;
    reap(ChildEnd::How::NotStarted, 5);
    if (attempt == 1) {
      reply.end.how = ChildEnd::How::NotStarted;
      reply.end.error = "the worker process took no request";
      return reply;
    }
  }
  await(reply, limits_.timeout_seconds);
  reply.seconds = since(began);
  reply.end.seconds = reply.seconds;
  return reply;
}

std::string Worker::close() {
  if (pid_ <= 0) return {};
  shutdown(fd_, SHUT_WR);  // the child sees the end of its requests and finishes
  Reply reply;
  if (!await(reply, limits_.timeout_seconds)) return {};
  int wstatus = 0;
  while (waitpid(pid_, &wstatus, 0) < 0 && errno == EINTR) {
  }
  ::close(fd_);
  fd_ = -1;
  pid_ = -1;
  return reply.text;
}

}  // namespace rayspec
