// A temporary folder of the running test alone: ctest runs each test in its
// own process, in parallel, so files named alike by two tests must not meet.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace rayspec::testing_support {

inline std::string testDir() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "no-test";
  name += "-" + std::to_string(::getpid());
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / ("rayspec-" + name);
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace rayspec::testing_support
