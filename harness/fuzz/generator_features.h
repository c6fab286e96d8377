// The device features `rayspec fuzz --without` leaves out of the cases it
// generates, for a device that lacks them (a driver without VK_KHR_ray_query
// reports every case with a ray query NotSupported; one without shaderInt64
// every case whose typed live state holds an int64). Each is named as
// `rayspec devices` names it: the label of its row in
// vulkan/device_info_fields.h (run/library_support.h featureRows), the row
// whose absence vulkan/case_support.h makes a case NotSupported for. A seed
// makes one case with a set of features left out, and another without.
#pragma once

#include <string>

#include "base/result.h"
#include "program/program.h"

namespace rayspec {

struct GeneratorFeatures {
  // VK_KHR_ray_query: ray_query statements and traces inlined as ray
  // queries (pipeline.traces ray_query, ray_query_compute).
  bool ray_query = true;
  // The device features of the sized types (program/sized_types.h): typed
  // live state of those types (locals, struct members, array elements).
  bool shader_int8 = true, shader_int16 = true, shader_int64 = true;
  bool shader_float16 = true, shader_float64 = true;
};

// The names --without takes, in the rows' order: "VK_KHR_ray_query,
// shaderInt8, shaderInt16, shaderInt64, shaderFloat16, shaderFloat64".
std::string leavableFeatureNames();

// `name` left out of `features`; an error naming the names --without takes
// for any other.
Result<void> leaveOut(GeneratorFeatures& features, const std::string& name);

// Whether a value of type t may be drawn: the device feature it needs
// (vulkan/case_support.h sizedTypeFeature) is not left out; a type that
// needs none always.
bool allowsType(const GeneratorFeatures& features, ValueType t);

// What is left out, as a case file and fuzz.txt say it: "without
// VK_KHR_ray_query"; "" when nothing is.
std::string leftOutText(const GeneratorFeatures& features);

}  // namespace rayspec
