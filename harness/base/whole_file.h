// Whole files. Read: at most a given size (every file rayspec reads is input,
// and a huge one is refused before it is read). Written whole or not at all:
// into a temporary name beside it (unique per process and thread), then
// renamed over it, so that a reader (another worker, another run) never
// sees half a file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "base/result.h"

namespace rayspec {

// The file's bytes; an error about the file (Error::loc.file) when it is no
// file, cannot be read or holds more than max_bytes.
Result<std::string> readWholeFile(const std::string& path, uint64_t max_bytes);

// readWholeFile's error as one message, "PATH: WHAT", for readers whose
// callers pass Error::message on.
Error inOneMessage(const Error& e);

// The name of a file written beside `path` before it is renamed to it: one
// of this process and thread's own (path.part.PID-THREAD).
std::string partFileName(const std::string& path);

// The error: ErrorKind::Harness, "PATH: cannot write: WHY" (a full disk, a
// folder in the way ...); nothing is left behind then, and a file that was at
// path stays as it was.
Result<void> writeWholeFile(const std::string& path, const void* data, size_t size);
Result<void> writeWholeFile(const std::string& path, std::string_view text);

}  // namespace rayspec
