// The steps the export's tests share (tests/export_*_test.cpp): a library
// case loaded and run on the model, its C export built with the C compiler
// (C99, every warning an error) and run on lavapipe.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "export/export_c.h"
#include "library/case_discovery.h"
#include "model/model_engine.h"
#include "temp_dir.h"

namespace rayspec {

inline const std::string kExportCasesDir = RAYSPEC_SOURCE_DIR "/cases";

struct ExportCase {
  Case c;
  Plan plan;
};

inline ExportCase loadExportCase(const std::string& name) {
  const std::optional<CaseFile> f = findCase(name, "", kExportCasesDir);
  EXPECT_TRUE(f) << name;
  ParseResult parsed = loadCase(*f, kExportCasesDir);
  EXPECT_TRUE(parsed.value) << name;
  ExportCase out{*parsed.value, {}};
  out.plan = derivePlan(out.c);
  return out;
}

inline Results exportModelOf(const ExportCase& l, const ModelFaults& faults = {}) {
  ModelOptions opt;
  opt.faults = faults;
  return runOnModel(l.c, l.plan, opt);
}

struct Played {
  int status = -1;  // the player's exit status; -1: it did not build
  std::string output;
};

inline std::string slurpExportFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The exported text built (C99, every warning an error) and run on lavapipe.
inline Played playExport(const std::string& text, const std::string& dir_name) {
  const std::string dir = freshTempDir("export/" + dir_name);
  std::ofstream(dir + "/repro.c") << text;
  const std::string build = std::string(RAYSPEC_C_COMPILER) +
                            " -std=c99 -Wall -Wextra -Wno-missing-field-initializers -Werror " +
                            dir + "/repro.c -lvulkan -o " + dir + "/repro > " + dir +
                            "/build.txt 2>&1";
  Played p;
  if (std::system(build.c_str()) != 0) {
    p.output = slurpExportFile(dir + "/build.txt");
    return p;
  }
  const int s = std::system((dir + "/repro llvmpipe > " + dir + "/out.txt 2>&1").c_str());
  p.status = WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  p.output = slurpExportFile(dir + "/out.txt");
  return p;
}

// The case exported with `model`'s expectations, built and run; a failed
// expectation where it is refused, does not build, or finds no lavapipe.
inline Played exportAndPlay(const ExportCase& l, const Results& model,
                            const std::string& dir_name) {
  const Result<std::string> text = exportCaseAsC(l.c, l.plan, model);
  EXPECT_TRUE(text) << l.c.name << ": " << (text ? "" : text.error().format());
  if (!text) return {};
  Played p = playExport(*text, dir_name);
  EXPECT_NE(p.status, -1) << "did not build:\n" << p.output;
  if (p.status == 77 && p.output.find("llvmpipe") == std::string::npos)
    ADD_FAILURE() << "no lavapipe device to run on:\n" << p.output;
  return p;
}

}  // namespace rayspec
