// The cases of cases/ as the run finds them (sweeps expanded), for tests that
// go over the whole suite.
#pragma once

#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "library/case_discovery.h"
#include "parse/parse_case.h"

namespace rayspec {

// RAYSPEC_CASES_DIR overrides the folder (to check cases being written elsewhere).
inline const std::string kSuiteCases = std::getenv("RAYSPEC_CASES_DIR")
                                           ? std::getenv("RAYSPEC_CASES_DIR")
                                           : RAYSPEC_SOURCE_DIR "/cases";

// Every case; with one_per_file, a sweep gives only its first variant.
inline std::vector<CaseFile> suiteCases(bool one_per_file = false) {
  std::vector<CaseFile> all = findCases(kSuiteCases, "*");
  if (!one_per_file) return all;
  std::vector<CaseFile> out;
  std::set<std::string> files;
  for (CaseFile& f : all)
    if (files.insert(f.path).second) out.push_back(std::move(f));
  return out;
}

// One case by name, from one scan of the folder per process (findCase scans
// and expands every sweep each time it is asked).
inline std::optional<CaseFile> suiteCase(const std::string& name) {
  static const std::map<std::string, CaseFile> by_name = [] {
    std::map<std::string, CaseFile> m;
    for (CaseFile& f : suiteCases()) m.emplace(f.name, std::move(f));
    return m;
  }();
  const auto it = by_name.find(name);
  if (it == by_name.end()) return std::nullopt;
  return it->second;
}

inline ParseResult loadSuiteCase(const CaseFile& f) {
  return loadCase(f, kSuiteCases);
}

// The case of the suite's file NAME.yaml (not a sweep), parsed; an empty
// case, and a failed expectation, when it does not parse.
inline Case suiteCaseFile(const std::string& name) {
  ParseResult p = parseCaseFile(kSuiteCases + "/" + name + ".yaml", kSuiteCases);
  EXPECT_TRUE(p.value) << (p.errors.empty() ? "" : p.errors[0].format());
  return p.value ? *p.value : Case{};
}

}  // namespace rayspec
