// What the library's cases need of a device and it lacks (`rayspec devices`,
// issue 61): how many of them it cannot run (NotSupported), and for each
// feature or extension it lacks, how many that one alone keeps from running.
// Decided by the check VulkanEngine runs before each case
// (vulkan/case_support.h), over the features of vulkan/device_info_fields.h
// (its labelled yes/no rows): no second list of what a case needs.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "case/case.h"
#include "plan/plan.h"
#include "vulkan/vulkan_engine.h"

namespace rayspec {

// A yes/no row of vulkan/device_info_fields.h that `rayspec devices` prints
// (what a case may need and a device may lack): its label
// (rayTraversalPrimitiveCulling, VK_KHR_ray_query, ...) and its member.
using FeatureRow = std::pair<const char*, bool DeviceInfo::*>;
std::vector<FeatureRow> featureRows();

// A library case as a plain run runs it, with its plan.
struct LibraryCase {
  Case c;
  Plan plan;
};

// The cases under cases_dir that parse and run as written (a case that does
// not parse, or is not run plainly, is left out: run reports those itself).
std::vector<LibraryCase> libraryCases(const std::string& cases_dir);

struct FeatureSkips {
  std::string feature;  // the row's label (rayTraversalPrimitiveCulling, VK_KHR_ray_query, ...)
                        // or the validation layer's version (1.3.239)
  int cases = 0;        // cases it alone makes NotSupported
  bool validation_layer = false;  // the layer on, not a feature missing
};

struct LibrarySupport {
  int cases = 0;          // library cases looked at
  int not_supported = 0;  // NotSupported on the device as it is
  // Each feature the device lacks, in the rows' order, then the validation
  // layer when one on makes cases NotSupported: the cases that run once the
  // device has every feature it lacks and that fail with this one taken away
  // again (a case needing two missing features counts under both).
  std::vector<FeatureSkips> missing;
};

// validation_layer: the layer's specVersion as a run would have it on (0: off
// or not installed).
LibrarySupport librarySupport(const std::vector<LibraryCase>& cases, const DeviceInfo& d,
                              uint32_t validation_layer);

}  // namespace rayspec
