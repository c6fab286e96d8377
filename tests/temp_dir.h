// A fresh, empty folder under GoogleTest's temporary folder, for tests that
// write runs and bundles.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace rayspec {

// <TempDir>/<path>, emptied and made.
inline std::string freshTempDir(const std::string& path) {
  const std::string dir = ::testing::TempDir() + "/" + path;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace rayspec
