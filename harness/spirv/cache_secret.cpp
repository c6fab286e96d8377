#include "spirv/cache_secret.h"

#include <fcntl.h>
#include <openssl/rand.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "base/whole_file.h"

namespace rayspec {
namespace fs = std::filesystem;
namespace {

constexpr char kSecretName[] = "spirv-cache.key";

Error secretError(const std::string& file, const std::string& what) {
  return errorMessage(file + ": " + what);
}

// The secret in `file` when it is usable (see the header), else why not. The
// file is opened without following a link and without blocking on a FIFO,
// and judged by what was opened.
Result<std::string> readSecret(const std::string& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return secretError(file, std::strerror(errno));
  struct stat st {};
  const char* problem = ::fstat(fd, &st) != 0      ? "cannot read its status"
                        : !S_ISREG(st.st_mode)     ? "not a regular file"
                        : st.st_uid != ::geteuid() ? "not this user's"
                        : (st.st_mode & 077) != 0  ? "open to group or others"
                                                   : nullptr;
  std::string bytes(kCacheSecretBytes + 1, '\0');  // one more: a longer file is seen
  const ssize_t n = problem ? 0 : ::read(fd, bytes.data(), bytes.size());
  ::close(fd);
  if (problem) return secretError(file, problem);
  if (n != static_cast<ssize_t>(kCacheSecretBytes))
    return secretError(file, "not " + std::to_string(kCacheSecretBytes) + " bytes");
  bytes.resize(kCacheSecretBytes);
  return bytes;
}

// The folder of the secret; made 0700 when missing (its parents as usual).
Result<void> makePrivateFolder(const fs::path& dir) {
  std::error_code ec;
  if (dir.empty() || fs::is_directory(dir, ec)) return {};
  if (dir.has_parent_path()) fs::create_directories(dir.parent_path(), ec);
  if (::mkdir(dir.c_str(), 0700) != 0 && errno != EEXIST)
    return secretError(dir.string(),
                       std::string("cannot make the folder: ") + std::strerror(errno));
  return {};
}

Result<std::string> randomSecret() {
  std::string bytes(kCacheSecretBytes, '\0');
  if (RAND_bytes(reinterpret_cast<unsigned char*>(bytes.data()), static_cast<int>(bytes.size())) !=
      1)
    return errorMessage("libcrypto: no random bytes for the SPIR-V cache's key");
  return bytes;
}

// `bytes` into a new file at `path`, mode 0600 from the start.
Result<void> writePrivateFile(const std::string& path, const std::string& bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd < 0) return secretError(path, std::string("cannot write: ") + std::strerror(errno));
  const bool whole = ::write(fd, bytes.data(), bytes.size()) == static_cast<ssize_t>(bytes.size());
  if (::close(fd) == 0 && whole) return {};
  ::unlink(path.c_str());
  return secretError(path, "cannot write");
}

// The new secret, written to `part`, put in place at `file`. A missing file
// is made with link(), which never replaces one: of processes starting at
// once, the first one's secret stays and the others read it. An unusable
// file is replaced.
Result<std::string> placeSecret(const std::string& part, const std::string& file,
                                const std::string& secret) {
  std::error_code ec;
  const bool missing = fs::symlink_status(file, ec).type() == fs::file_type::not_found;
  const int rc =
      missing ? ::link(part.c_str(), file.c_str()) : ::rename(part.c_str(), file.c_str());
  const int err = errno;
  ::unlink(part.c_str());  // after link(); gone already after rename()
  if (rc == 0) return secret;
  if (missing && err == EEXIST) return readSecret(file);
  return secretError(file, std::string("cannot write: ") + std::strerror(err));
}

}  // namespace

std::string cacheSecretFile() {
  if (const char* d = std::getenv("RAYSPEC_CONFIG_DIR"); d && *d)
    return std::string(d) + "/" + kSecretName;
  if (const char* d = std::getenv("XDG_CONFIG_HOME"); d && *d)
    return std::string(d) + "/rayspec/" + kSecretName;
  if (const char* d = std::getenv("HOME"); d && *d)
    return std::string(d) + "/.config/rayspec/" + kSecretName;
  return {};
}

Result<std::string> loadCacheSecret(const std::string& file) {
  if (file.empty())
    return errorMessage(
        "no folder for the SPIR-V cache's key: none of RAYSPEC_CONFIG_DIR, XDG_CONFIG_HOME and "
        "HOME is set");
  if (Result<std::string> held = readSecret(file)) return held;
  RAYSPEC_TRY_VOID(makePrivateFolder(fs::path(file).parent_path()));
  RAYSPEC_TRY(const std::string secret, randomSecret());
  const std::string part = partFileName(file);
  RAYSPEC_TRY_VOID(writePrivateFile(part, secret));
  return placeSecret(part, file, secret);
}

}  // namespace rayspec
