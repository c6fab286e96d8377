#include "base/whole_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <functional>
#include <system_error>
#include <thread>

namespace rayspec {

Result<std::string> readWholeFile(const std::string& path, uint64_t max_bytes) {
  const auto fail = [&path](std::string message) {
    return Error{{path, 0, 0, ""}, message};
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return fail("no such file");
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return fail("cannot read its size: " + ec.message());
  if (size > max_bytes)
    return fail(std::to_string(size) + " bytes, more than the " + std::to_string(max_bytes) +
                " such a file may hold");
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail("cannot open");
  // At most one byte more than allowed, whatever the size said: a file that
  // grew since, or one whose size says nothing (/proc), is refused too.
  std::string text(static_cast<size_t>(std::min<uint64_t>(size, max_bytes)) + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) return fail("cannot read");
  text.resize(static_cast<size_t>(in.gcount()));
  while (text.size() <= max_bytes && in) {  // grew past its size, within the limit
    char more[4096];
    in.read(more, sizeof more);
    text.append(more, static_cast<size_t>(in.gcount()));
  }
  if (in.bad()) return fail("cannot read");
  if (text.size() > max_bytes)
    return fail("more than the " + std::to_string(max_bytes) + " bytes such a file may hold");
  return text;
}

Error inOneMessage(const Error& e) {
  return e.loc.file.empty() ? e : errorMessage(e.loc.file + ": " + e.message);
}

namespace {

// errno's words for an error number.
std::string errorWords(int error) {
  return std::error_code(error, std::generic_category()).message();
}

// All of data into fd (write(2) may take less than asked); 0, or errno.
int writeAll(int fd, const char* data, size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : EIO;
    data += n;
    size -= static_cast<size_t>(n);
  }
  return 0;
}

}  // namespace

std::string partFileName(const std::string& path) {
  return path + ".part." + std::to_string(::getpid()) + "-" +
         std::to_string(std::hash<std::thread::id>()(std::this_thread::get_id()));
}

Result<void> writeWholeFile(const std::string& path, const void* data, size_t size) {
  const std::string part = partFileName(path);
  const auto failed = [&path](int error) {
    return errorOf(ErrorKind::Harness, path + ": cannot write: " + errorWords(error));
  };
  // O_NOFOLLOW: a link planted at the temporary name is not written through.
  const int fd = ::open(part.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) return failed(errno);
  int error = writeAll(fd, static_cast<const char*>(data), size);
  // A file system that says it is full only when the file is closed (NFS) says it here.
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error == 0 && ::rename(part.c_str(), path.c_str()) != 0) error = errno;
  if (error == 0) return {};
  ::unlink(part.c_str());
  return failed(error);
}

Result<void> writeWholeFile(const std::string& path, std::string_view text) {
  return writeWholeFile(path, text.data(), text.size());
}

}  // namespace rayspec
