// rayspec export CASE [--format c|amber] [--out DIR]: the case as a standalone
// reproducer, DIR/repro.c (export/export_c.h) or DIR/repro.amber (export/export_amber.h).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "cli/commands.h"
#include "cli/subcommands.h"
#include "export/export_amber.h"
#include "export/export_c.h"
#include "model/model_engine.h"
#include "parse/parse_case.h"
#include "plan/plan.h"

namespace rayspec {
namespace {

struct ExportOptions {
  std::string case_file;
  std::string format = "c";
  std::string out = "export";
  std::string cases_dir = RAYSPEC_SOURCE_DIR "/cases";
};

// Writes text to DIR/repro.c or DIR/repro.amber; false (said on stderr) where it cannot.
bool writeReproducer(const std::string& dir, const std::string& format, const std::string& text) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const bool amber = format == "amber";
  const std::string path =
      (std::filesystem::path(dir) / (amber ? kAmberScriptFile : kReproducerFile)).string();
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) {
    std::fprintf(stderr, "rayspec export: cannot write %s\n", path.c_str());
    return false;
  }
  if (amber)
    std::printf("wrote %s (run: amber -v 1.2 %s)\n", path.c_str(), path.c_str());
  else
    std::printf("wrote %s (build: cc %s -lvulkan -o repro)\n", path.c_str(), path.c_str());
  return true;
}

// 0 written, 77 refused (the feature named), 1 a case or compile error, 2 usage.
int runExport(const ExportOptions& opt) {
  if (!modelInThisBuild()) {
    std::fprintf(stderr,
                 "rayspec export: this run-only build has no model to take the "
                 "expectations from\n");
    return 2;
  }
  const std::optional<CaseFile> file = caseToShow(opt.case_file, opt.cases_dir, "exporting");
  if (!file) {
    std::fprintf(stderr,
                 "rayspec export: no such case file: '%s' (neither a file nor a case "
                 "name under %s)\n",
                 opt.case_file.c_str(), opt.cases_dir.c_str());
    return 2;
  }
  ParseResult parsed = loadCase(*file, opt.cases_dir, nullptr);
  for (const Error& e : parsed.errors) std::fprintf(stderr, "%s\n", e.format().c_str());
  if (!parsed.value) return 1;
  const Case& c = *parsed.value;
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, ModelOptions{});
  const Result<std::string> text =
      opt.format == "amber" ? exportCaseAsAmber(c, plan, model) : exportCaseAsC(c, plan, model);
  if (!text) {
    std::fprintf(stderr, "%s\n", text.error().format().c_str());
    return text.error().kind == ErrorKind::NotSupported ? 77 : 1;
  }
  return writeReproducer(opt.out, opt.format, *text) ? 0 : 1;
}

}  // namespace

Subcommand addExportCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "export",
      "Write a case as a standalone reproducer, DIR/repro.c: one C file that builds with "
      "`cc repro.c -lvulkan`, traces the case on a device and compares with the model's "
      "expectations (exit 0 PASS, 1 FAIL, 77 NotSupported); or with --format amber "
      "DIR/repro.amber, an Amber script of the CTS's ray tracing subset; exits 77 naming the "
      "feature a case uses that the export does not handle");
  auto opt = std::make_shared<ExportOptions>();
  cmd->add_option("case", opt->case_file, "Case file (or case name under cases/)")->required();
  cmd->add_option("--format", opt->format, "c (a C file) or amber (an Amber script)")
      ->check(CLI::IsMember({"c", "amber"}))
      ->capture_default_str();
  cmd->add_option("--out", opt->out, "Folder to write repro.c or repro.amber into")
      ->capture_default_str();
  cmd->add_option("--cases", opt->cases_dir, "Folder of case files")->capture_default_str();
  return {cmd, [opt] {
            return runExport(*opt);
          }};
}

}  // namespace rayspec
