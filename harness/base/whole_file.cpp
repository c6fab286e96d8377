#include "base/whole_file.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
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
