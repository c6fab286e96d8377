// A fresh, empty folder under GoogleTest's temporary folder, for tests that
// write runs and bundles.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace rayspec {

// <TempDir>/<path>, emptied and made.
inline std::string freshTempDir(const std::string& path) {
  const std::string dir = ::testing::TempDir() + "/" + path;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A file of `bytes` zero bytes that takes no disk (sparse): to show that a
// reader refuses a file over its size limit before reading it.
inline std::string sparseFile(const std::string& path, uint64_t bytes) {
  { std::ofstream(path, std::ios::binary | std::ios::trunc); }
  std::filesystem::resize_file(path, bytes);
  return path;
}

}  // namespace rayspec
