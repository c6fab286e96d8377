#include "results/whole_file.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>

namespace rayspec {

bool writeFileWhole(const std::string& path, const void* data, size_t size) {
  const std::string part = path + ".part." + std::to_string(::getpid()) + "-" +
                           std::to_string(std::hash<std::thread::id>()(std::this_thread::get_id()));
  std::error_code ec;
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) {
      out.close();
      std::filesystem::remove(part, ec);
      return false;
    }
  }
  std::filesystem::rename(part, path, ec);
  if (ec) std::filesystem::remove(part, ec);
  return !ec;
}

}  // namespace rayspec
