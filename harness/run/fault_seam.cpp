#include "run/fault_seam.h"

#include <fnmatch.h>

#include <optional>

#include "fault/planted_fault.h"
#include "model/model_engine.h"
#include "vulkan/build_layout.h"
#include "vulkan/device_errors.h"
#include "vulkan/vk_fault_hook.h"

namespace rayspec {
namespace {

// A Vulkan call fails on purpose for this case only.
void armVulkanError(Side& s, const std::string& fault, const InjectedVkError& e) {
  s.before = [e] {
    injectVkError(e);
  };
  s.after = [fault, e](const Case&, const Plan&, Results&) -> std::string {
    injectVkError({});
    return "planted fault " + fault + ": " + e.call + " returns " + vkResultName(e.result);
  };
}

// Whether query fault f changes an answer of this case's scene.build.queries,
// and if not, why; "-": f is no query fault.
std::string queryFaultMisses(const Case& c, LayoutFault f) {
  const StructureQueries& q = c.scene.build.queries;
  const auto needs = [&q](bool asked, const char* what) {
    return asked ? std::string() : std::string("the case asks for no ") + what + " query";
  };
  switch (f) {
    case LayoutFault::CompactedTooLarge:
      return needs(q.asks(StructureQuery::CompactedSize), "compacted_size");
    case LayoutFault::SizeTooLarge:
      return needs(q.asks(StructureQuery::Size), "size");
    case LayoutFault::AvailabilityLost:
      return needs(!q.queries.empty() && q.command == QueryCommand::Device, "device-form");
    case LayoutFault::UuidWrong:
      return needs(
          q.asks(StructureQuery::SerializationSize) || q.asks(StructureQuery::BottomLevelPointers),
          "serialization_size or bottom_level_pointers");
    case LayoutFault::PointerCountOff:
      return needs(q.asks(StructureQuery::BottomLevelPointers), "bottom_level_pointers");
    default:
      return "-";
  }
}

// Whether layout fault f changes what this case's builds read, and if not,
// why.
std::string layoutFaultMisses(const Case& c, LayoutFault f) {
  const AsBuild& b = c.scene.build;
  if (f == LayoutFault::FormatMisread) {
    for (const Blas& blas : c.scene.blases)
      for (const Geometry& g : blas.geometries)
        if (g.kind == Geometry::Kind::Triangles && vertexFormatMisread(g.vertex_format)) return "";
    return "no triangles in a format it misreads (triangles.vertex_format)";
  }
  if (f == LayoutFault::WritesPastSize)
    return c.scene.instances.empty() ? "the case builds no structure" : "";
  if (f == LayoutFault::CreationClears)
    return b.storage == StructureStorage::Reused ? ""
                                                 : "the case does not reuse memory "
                                                   "(scene.build.storage reused)";
  if (f == LayoutFault::DeferredHandleEarly)
    return c.pipeline.deferred_threads ? ""
                                       : "the case creates no pipeline through a deferred "
                                         "operation (pipeline.deferred, --through deferred)";
  if (f == LayoutFault::SparsePageLost)
    return b.sparse.geometry || b.sparse.instances
               ? ""
               : "no input buffer of the case is sparse (scene.build.sparse geometry, instances)";
  if (const std::string query = queryFaultMisses(c, f); query != "-") return query;
  const bool applies = f == LayoutFault::StrideIgnored    ? b.vertex_stride || b.aabb_stride
                       : f == LayoutFault::OffsetsIgnored ? b.data_offsets || b.first_vertex
                                                          : b.instances_as_pointers;
  return applies ? "" : "the case asks for no such layout (scene.build)";
}

// The builds lay their inputs out wrong for this case only. Where the case
// asks for no layout the fault would change, it says so.
void armLayoutFault(Side& s, const std::string& fault, LayoutFault f) {
  s.before = [f] {
    injectLayoutFault(f);
  };
  s.after = [fault, f](const Case& c, const Plan&, Results&) -> std::string {
    injectLayoutFault(LayoutFault::None);
    const std::string misses = layoutFaultMisses(c, f);
    const char* what = f == LayoutFault::WritesPastSize ? "a build wrote past the size the device "
                                                          "reported"
                       : f == LayoutFault::CreationClears
                           ? "creating a structure over a built one zeroed its memory"
                       : f == LayoutFault::DeferredHandleEarly
                           ? "a deferred pipeline's handle was taken before the operation "
                             "completed"
                       : f == LayoutFault::SparsePageLost
                           ? "a page of each sparse input buffer lost its binding (zeros there)"
                       : queryFaultMisses(c, f) != "-" ? "a structure query answered wrong"
                                                       : "the builds misread the input layout";
    return misses.empty() ? "planted fault " + fault + ": " + what
                          : "planted fault not applicable: " + fault + ": " + misses;
  };
}

// A crash or hang in the device's process (only in a child: the run loop
// refuses them in process), or the results a faulty device gives.
void armResultsFault(Side& s, const std::string& fault, std::shared_ptr<const Results> model,
                     const std::string& run_dir) {
  s.after = [fault, model, run_dir](const Case& c, const Plan& plan,
                                    Results& device) -> std::string {
    raiseProcessFault(fault, c.name, run_dir);
    if (isProcessFault(fault)) return {};
    const FaultResult f = plantFault(fault, c, plan, device, *model);
    return (f.applied ? "planted fault " : "planted fault not applicable: ") + fault + ": " +
           f.what;
  };
}

}  // namespace

Result<void> plantedFaultError(const RunOptions& opt) {
  const std::string& name = opt.plant_fault;
  if (name.empty()) return {};
  const bool vulkan_error = deviceErrorFault(name).has_value() || layoutFault(name).has_value();
  if (!isFaultName(name) && !vulkan_error)
    return errorMessage("unknown fault '" + name + "' (one of " + plantableFaultNames() +
                        "; `rayspec faults` says what each breaks)");
  if (isProcessFault(name) && opt.no_isolation)
    return errorMessage("the fault '" + name +
                        "' needs the device in a child process (no --no-isolation)");
  if (!modelInThisBuild() && !vulkan_error && !isProcessFault(name))
    return errorMessage(
        "the fault '" + name +
        "' is made from the model's results, which this run-only build lacks (crash, hang and "
        "the Vulkan error faults work here; plant it when judging, with --device-results)");
  if (vulkan_error && !opt.device_results.empty())
    return errorMessage("the fault '" + name +
                        "' makes a Vulkan call fail: it needs a live device, not --device-results");
  return {};
}

std::string plantableFaultNames() {
  std::string list;
  // The fault table holds the Vulkan faults too (FaultKind::Vulkan).
  for (const std::string& name : faultNames()) list += (list.empty() ? "" : ", ") + name;
  return list;
}

std::string plantedFaultIn(const RunOptions& opt, const std::string& case_name) {
  return fnmatch(opt.plant_fault_in.c_str(), case_name.c_str(), 0) == 0 ? opt.plant_fault
                                                                        : std::string();
}

bool faultReadsModel(const std::string& fault) {
  return !fault.empty() && !deviceErrorFault(fault) && !layoutFault(fault);
}

Result<LayoutFault> exportedLayoutFault(const std::string& fault) {
  if (fault.empty()) return LayoutFault::None;
  const std::optional<LayoutFault> layout = layoutFault(fault);
  if (layout == LayoutFault::StrideIgnored || layout == LayoutFault::OffsetsIgnored ||
      layout == LayoutFault::FormatMisread)
    return *layout;
  const FaultInfo* info = findFault(fault);
  const std::string where = layout ? std::string("in a step of the builds the file does not take")
                            : info ? std::string("in ") + faultKindText(info->kind)
                                   : std::string("nowhere a C file holds");
  return errorMessage("the planted fault " + fault + " is made " + where +
                      ", not in the inputs a device is given: a C file cannot carry it");
}

void armDeviceSide(Side& s, const std::string& fault, std::shared_ptr<const Results> model,
                   const std::string& run_dir) {
  if (fault.empty()) return;
  if (const std::optional<InjectedVkError> injected = deviceErrorFault(fault))
    armVulkanError(s, fault, *injected);
  else if (const std::optional<LayoutFault> layout = layoutFault(fault))
    armLayoutFault(s, fault, *layout);
  else
    armResultsFault(s, fault, std::move(model), run_dir);
}

}  // namespace rayspec
