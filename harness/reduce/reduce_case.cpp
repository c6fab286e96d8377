#include "reduce/reduce_case.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/output_folder.h"
#include "base/shell_word.h"
#include "base/visible_text.h"
#include "base/whole_file.h"
#include "export/export_c.h"
#include "library/case_discovery.h"
#include "model/model_engine.h"
#include "plan/plan.h"
#include "reduce/case_size.h"
#include "reduce/reduce_document.h"
#include "reduce/reduce_report.h"
#include "reduce/variant_judge.h"
#include "reduce/yaml_sites.h"
#include "report/rule_catalog.h"
#include "run/cache_dir.h"
#include "run/fault_seam.h"
#include "run/interrupt.h"
#include "run/run_setup.h"
#include "vulkan/icd_environment.h"

namespace rayspec {
namespace fs = std::filesystem;
namespace {

int badInput(const std::string& why) {
  std::fprintf(stderr, "rayspec reduce: %s\n", visibleLine(why).c_str());
  return kReduceBadInput;
}

// The case asked for: a file (a sweep file only with one variant), else a
// case name under the cases folder.
Result<CaseFile> chosenCase(const ReduceOptions& opt) {
  std::error_code ec;
  if (fs::is_regular_file(opt.case_path, ec)) {
    std::vector<CaseFile> files = caseFilesFor(opt.case_path, opt.run.cases_dir);
    if (files.size() != 1)
      return errorMessage(opt.case_path + " is a sweep file with " + std::to_string(files.size()) +
                          " variants: name one, e.g. " +
                          (files.empty() ? std::string("its variant") : files.front().name));
    return files.front();
  }
  if (std::optional<CaseFile> f = findCase(opt.case_path, "", opt.run.cases_dir)) return *f;
  return errorMessage(opt.case_path + ": no such case file, nor a case of that name in " +
                      opt.run.cases_dir);
}

Result<std::string> caseText(const CaseFile& f) {
  if (f.generated) return f.text;
  const Result<std::string> text = readWholeFile(f.path, kMaxCaseFileBytes);
  if (!text) return inOneMessage(text.error());
  return *text;
}

Result<YAML::Node> loadDocument(const std::string& text, const std::string& path) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    return errorMessage(path + ": not YAML: " + e.what());
  }
}

// The command line that shows the failure, every word quoted for sh
// (base/shell_word.h): a path or name holding a quote, `$(...)` or a
// newline is text there, never shell code.
std::string reproduction(const ReduceOptions& opt, const std::string& name) {
  if (!opt.device_command.empty())  // the device is the command's: it runs OUT/cases, judged here
    return "RAYSPEC_VARIANT_CASES=" + shellWord(opt.out + "/" + kReductionCasesFolder) +
           " RAYSPEC_VARIANT_NAME=" + shellWord(name) +
           " RAYSPEC_VARIANT_OUT=" + shellWord(opt.out + "/device") + " sh -c " +
           shellWord(opt.device_command) + " && rayspec run --cases " +
           shellWord(opt.out + "/" + kReductionCasesFolder) + " --device-results " +
           shellWord(opt.out + "/device");
  std::string c = "rayspec run --case " + shellWord(opt.out + "/" + kReducedCaseFile);
  if (!opt.run.device.empty()) c += " --device " + shellWord(opt.run.device);
  for (const std::string& icd : opt.run.icd_files) c += " --icd " + shellWord(icd);
  if (!opt.run.plant_fault.empty()) c += " --plant-fault " + shellWord(opt.run.plant_fault);
  if (opt.run.model_tier != "exact") c += " --model " + shellWord(opt.run.model_tier);
  return c;
}

// Text as YAML comment lines: a line break in it (a path's) starts another
// comment, never a line of YAML.
std::string commentLines(const std::string& text) {
  std::string out = "# ";
  for (char ch : text) out += ch == '\n' ? std::string("\n# ") : std::string(1, ch);
  return out + "\n";
}

// The titles of a finding's rules ("R-A/R-B": each), from the catalog.
std::string ruleTitle(const std::vector<Rule>& catalog, const std::string& labels) {
  std::string out;
  std::stringstream parts(labels);
  for (std::string label; std::getline(parts, label, '/');)
    for (const Rule& r : catalog)
      if (r.label == label) out += (out.empty() ? "" : "; ") + label + ": " + r.title;
  return out;
}

// The SPIR-V cache of the variants' runs; without one (no key for it) they
// compile every stage, and the user is told.
void useCacheDirOrSay(const std::string& dir) {
  if (const Result<void> cached = useCacheDir(dir); !cached)
    std::fprintf(stderr, "rayspec reduce: %s\n", visibleLine(cached.error().format()).c_str());
}

// The setup a reduction needs before its first variant: the options, the
// driver manifests, the device.
Result<void> reductionSetup(ReduceOptions& opt, const CaseFile& f, RunInfo& info) {
  if (!modelInThisBuild())
    return errorMessage("this run-only build has no model to judge variants by");
  RAYSPEC_TRY_VOID(plantedFaultError(opt.run));
  const IcdSelection icd = useIcdFiles(opt.run.icd_files);
  for (const std::string& note : icd.notes)
    std::fprintf(stderr, "rayspec reduce: %s\n", note.c_str());
  if (!icd.error.empty()) return errorMessage(icd.error);
  if (!opt.device_command.empty()) {  // no device here: the command runs each variant's
    info.device = "the device `" + opt.device_command + "` runs";
    useCacheDirOrSay(opt.run.cache_dir);
    // The command runs in a process group of its own, which the terminal's
    // Ctrl-C does not reach: the signal is caught here and the group killed.
    catchInterrupts();
    return {};
  }
  RAYSPEC_TRY_VOID(chooseDevice(opt.run, {f}, icd, info));
  useCacheDirOrSay(opt.run.cache_dir);
  return {};
}

// With a planted fault: whether the case fails without it too (then the
// failure is not the fault's, and there is nothing of it to reduce).
bool failsWithoutTheFault(const VariantJudge& probe, const Case& c, const std::string& fault,
                          bool* interrupted) {
  const std::string why = probe.failureWithoutTheFault(c, interrupted);
  if (*interrupted || why.empty()) return *interrupted;
  std::printf("%s (the fault: %s) %s\n", c.name.c_str(), fault.c_str(), visibleLine(why).c_str());
  return true;
}

// The device and driver manifest the report names: this process's, or what
// the device command's runs said they ran on.
void nameTheDevice(ReductionRecord& r, const RunInfo& info, const VariantJudge& judge,
                   const std::string& device_command) {
  r.device = info.device;
  r.icd = info.icd;
  if (const VariantJudge::CommandDevice ran = judge.commandDevice(); !ran.device.empty()) {
    r.device = ran.device + ", run by `" + device_command + "`";
    r.icd = ran.icd;
  }
}

// The reduced case as a standalone C file and as an Amber script
// (export/export_c.h, export/export_amber.h: their expectations from the
// model's exact tier), the C file carrying the planted fault where it can
// (a script cannot: none with a fault); or why there is none.
void exportReduced(ReductionRecord& r, const ParseResult& reduced, const std::string& fault) {
  const Result<LayoutFault> layout = exportedLayoutFault(fault);
  if (!layout) r.reproducer_refused = layout.error().format();
  if (!fault.empty()) r.amber_refused = "an Amber script cannot carry the planted fault " + fault;
  if (!reduced.value) {
    r.reproducer_refused = r.amber_refused = "the reduced case does not parse";
    return;
  }
  const Case& c = *reduced.value;
  const Plan plan = derivePlan(c);
  const Results model = runOnModel(c, plan, {});
  if (layout) {
    const Result<std::string> text = exportCaseAsC(c, plan, model, *layout);
    if (text)
      r.reproducer = *text;
    else
      r.reproducer_refused = text.error().format();
  }
  if (!fault.empty()) return;
  const Result<std::string> script = exportCaseAsAmber(c, plan, model);
  if (script)
    r.amber = *script;
  else
    r.amber_refused = script.error().format();
}

}  // namespace

int runReduce(const ReduceOptions& requested) {
  ReduceOptions opt = requested;
  const auto start = std::chrono::steady_clock::now();
  Result<CaseFile> f = chosenCase(opt);
  if (!f) return badInput(f.error().format());
  if (!f->errors.empty()) return badInput(f->errors.front().format());
  Result<std::string> text = caseText(*f);
  if (!text) return badInput(text.error().format());
  Result<YAML::Node> doc = loadDocument(*text, f->path);
  if (!doc) return badInput(doc.error().format());
  Result<std::vector<Rule>> catalog = loadRuleCatalog(opt.run.rules_file);
  if (!catalog) return badInput(catalog.error().format());
  const std::vector<std::string> labels = ruleLabels(*catalog);
  const ParseResult parsed = parseCaseText(*text, f->path, f->name, &labels);
  if (!parsed.value || !parsed.errors.empty())
    return badInput(parsed.errors.empty() ? f->path + ": cannot read the case"
                                          : parsed.errors.front().format());
  const Result<OutputFolder> held =
      claimOutputFolder(opt.out, {kReductionWrites.begin(), kReductionWrites.end()}, "reduce");
  if (!held) return badInput(held.error().format());
  RunInfo info;
  opt.run.out = opt.out + "/" + kReductionRunsFolder;
  if (Result<void> setup = reductionSetup(opt, *f, info); !setup)
    return badInput(setup.error().format());

  VariantJudge probe(opt.run, f->name, labels, {}, 1, opt.device_command);
  bool interrupted = false;
  const CaseOutcome original = probe.judge(*text, &interrupted);
  if (interrupted) return badInput("interrupted");
  if (!probe.commandFailure().empty()) return badInput(probe.commandFailure());
  std::optional<FailureSignature> signature = failureToKeep(original, opt.keep);
  if (signature && failsWithoutTheFault(probe, *parsed.value, opt.run.plant_fault, &interrupted))
    return interrupted ? badInput("interrupted") : kReduceNotFailing;
  if (!signature) {
    std::printf("%s\n", notFailingText(f->name, opt.keep, original).c_str());
    return kReduceNotFailing;
  }
  std::printf("Reducing %s: keeps %s: %s%s\n", f->name.c_str(), statusName(signature->status),
              signature->rule.empty() ? "" : (signature->rule + ": ").c_str(),
              visibleLine(signature->message).c_str());
  VariantJudge judge(opt.run, f->name, labels, *signature, opt.max_attempts, opt.device_command);
  judge.keepPortable(*parsed.value);
  YAML::Node reduced =
      reduceDocument(*doc, *parsed.value, failingRays(original, *signature), judge);
  if (!judge.commandFailure().empty()) return badInput(judge.commandFailure());

  ReductionRecord r;
  r.case_name = f->name;
  r.case_path = f->path;
  r.signature = *signature;
  const CaseOutcome* kept = judge.keptOutcome(emitYaml(reduced));
  r.outcome = kept ? *kept : original;
  r.before = caseSize(*parsed.value);
  const ParseResult after = parseCaseText(emitYaml(reduced), "reduced.yaml", f->name, &labels);
  r.after = after.value ? caseSize(*after.value) : r.before;
  nameTheDevice(r, info, judge, opt.device_command);
  r.fault = opt.run.plant_fault;
  r.rule_title = ruleTitle(*catalog, signature->rule);
  r.command = reproduction(opt, f->name);
  r.attempts = judge.attempts();
  reduced["description"] = reducedDescription(r);
  r.reduced_text =
      commentLines("Made by rayspec reduce; shown by: " + r.command) + emitYaml(reduced);
  exportReduced(r, after, opt.run.plant_fault);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (std::string e = writeReduction(r, opt.out); !e.empty()) return badInput(e);
  if (!opt.device_command.empty()) {  // where the reproduction's command reads it
    std::error_code ec;
    const std::string at = opt.out + "/" + kReductionCasesFolder + "/" + f->name + ".yaml";
    std::filesystem::create_directories(std::filesystem::path(at).parent_path(), ec);
    if (Result<void> w = writeWholeFile(at, r.reduced_text); !w)
      return badInput(w.error().format());
  }
  std::printf("%s", reductionSummary(r, opt.out).c_str());
  return kReduceDone;
}

}  // namespace rayspec
