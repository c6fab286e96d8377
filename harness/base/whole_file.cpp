#include "base/whole_file.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
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
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return fail("cannot read");
  return text.str();
}

Result<void> writeWholeFile(const std::string& path, const void* data, size_t size) {
  const std::string part = path + ".part." + std::to_string(::getpid()) + "-" +
                           std::to_string(std::hash<std::thread::id>()(std::this_thread::get_id()));
  std::error_code ec;
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) {
      out.close();
      std::filesystem::remove(part, ec);
      return errorMessage(path + ": cannot write");
    }
  }
  std::filesystem::rename(part, path, ec);
  if (!ec) return {};
  const std::string why = ec.message();
  std::filesystem::remove(part, ec);
  return errorMessage(path + ": cannot write: " + why);
}

Result<void> writeWholeFile(const std::string& path, std::string_view text) {
  return writeWholeFile(path, text.data(), text.size());
}

}  // namespace rayspec
