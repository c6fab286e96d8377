// `rayspec devices`: every driver manifest the loader would read, each probed
// alone in a child process (run/icd_probe.h), with its devices, whether each
// can run the cases and why not, the ray tracing limits of the usable ones,
// and the options that select one.
#include <cstdio>

#include "cli/commands.h"
#include "run/icd_probe.h"
#include "vulkan/device_usability.h"
#include "vulkan/icd_environment.h"

namespace rayspec {
namespace {

// A word for the shell: quoted when it holds anything but [A-Za-z0-9._/-].
std::string shellWord(const std::string& s) {
  bool plain = !s.empty();
  for (char c : s)
    plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' ||
                      c == '/' || c == '-');
  if (plain) return s;
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

void printLimits(const DeviceInfo& d) {
  std::printf("        shaderGroupHandleSize          %u\n", d.shader_group_handle_size);
  std::printf("        shaderGroupHandleAlignment     %u\n", d.shader_group_handle_alignment);
  std::printf("        shaderGroupBaseAlignment       %u\n", d.shader_group_base_alignment);
  std::printf("        maxRayRecursionDepth           %u\n", d.max_ray_recursion_depth);
  std::printf("        maxRayHitAttributeSize         %u\n", d.max_ray_hit_attribute_size);
  std::printf("        maxShaderGroupStride           %u\n", d.max_shader_group_stride);
  std::printf("        maxRayDispatchInvocationCount  %u\n", d.max_ray_dispatch_invocation_count);
  std::printf("        accelerationStructureHostCommands %s\n",
              d.acceleration_structure_host_commands ? "yes" : "no");
  std::printf("        VK_KHR_pipeline_library        %s\n", d.pipeline_library ? "yes" : "no");
  std::printf("        VK_EXT_opacity_micromap        %s\n", d.opacity_micromap ? "yes" : "no");
  std::printf("        VK_KHR_ray_tracing_maintenance1 %s\n",
              d.ray_tracing_maintenance1 ? "yes" : "no");
  std::printf("        vkCmdTraceRaysIndirectKHR      %s\n", d.trace_rays_indirect ? "yes" : "no");
  std::printf("        vkCmdTraceRaysIndirect2KHR     %s\n", d.trace_rays_indirect2 ? "yes" : "no");
  std::printf("        VK_KHR_ray_tracing_position_fetch %s\n", d.position_fetch ? "yes" : "no");
  std::printf("        VK_EXT_pipeline_library_group_handles %s\n",
              d.library_group_handles ? "yes" : "no");
  std::string formats;
  for (const std::string& f : d.vertex_formats) formats += " " + f;
  std::printf("        vertex formats (AS build)     %s\n",
              formats.empty() ? " none" : formats.c_str());
}

// One manifest's devices; returns how many are usable.
int printProbe(const IcdProbe& p) {
  std::printf("ICD %s (library %s%s%s)\n", p.manifest.path.c_str(), p.manifest.library_path.c_str(),
              p.manifest.api_version.empty() ? "" : ", Vulkan ", p.manifest.api_version.c_str());
  if (p.devices.empty())
    std::printf("    NOT USABLE: %s\n",
                p.failure.empty() ? "no physical device" : p.failure.c_str());
  int usable = 0;
  for (const DeviceInfo& d : p.devices) {
    const DeviceUsability u = deviceUsability(d);
    std::printf("    [%u] %s: %s%s\n", d.index, d.name.c_str(),
                u == DeviceUsability::Usable ? "USABLE" : "NOT USABLE: ",
                u == DeviceUsability::Usable ? "" : usabilityReason(u, d).c_str());
    std::printf("        driver %s (%s), Vulkan %s\n",
                d.driver_name.empty() ? "?" : d.driver_name.c_str(), d.driver_info.c_str(),
                d.api_version.c_str());
    if (u != DeviceUsability::Usable) continue;
    ++usable;
    std::printf("        select: --icd %s --device %s\n", shellWord(p.manifest.path).c_str(),
                shellWord(d.name).c_str());
    printLimits(d);
  }
  return usable;
}

}  // namespace

int runDevices(const DevicesOptions& opt) {
  const IcdSelection selection = useIcdFiles(opt.icd_files);
  for (const std::string& note : selection.notes)
    std::fprintf(stderr, "rayspec devices: %s\n", note.c_str());
  if (!selection.error.empty()) {
    std::fprintf(stderr, "rayspec devices: %s\n", selection.error.c_str());
    return 2;
  }
  const IcdSearch search = findIcdManifests();
  std::string places;
  for (const std::string& p : search.places) places += (places.empty() ? "" : ", ") + p;
  std::printf("Driver manifests from %s%s: %s\n\n", icdSourceName(search.source).c_str(),
              opt.icd_files.empty() ? "" : " (--icd)", places.c_str());
  int usable = 0;
  for (const IcdManifest& m : search.manifests)
    usable += printProbe(probeIcd(m, ChildLimits{kProbeSeconds, 0}));
  for (const std::string& e : search.errors) std::printf("NOT USABLE: %s\n", e.c_str());
  const size_t manifests = search.manifests.size() + search.errors.size();
  if (usable == 0) {
    std::printf(
        "\nNo usable device (Vulkan 1.2 with ray tracing pipelines and acceleration structures) "
        "through %zu driver manifest%s.\n",
        manifests, manifests == 1 ? "" : "s");
    return 1;
  }
  std::printf("\n%d usable device%s through %zu driver manifest%s.\n", usable,
              usable == 1 ? "" : "s", manifests, manifests == 1 ? "" : "s");
  return 0;
}

}  // namespace rayspec
