// The widths Vulkan gives the fields of an instance and the arguments of a
// trace, each beside the rule that holds a device to it. A value wider than
// its field is cut to these low bits, as the device's bit fields and
// traceRayEXT cut it; the parser refuses a case value wider than its field
// where the field is stored (the instance's), and the model and the GLSL
// mask what a program computes (a trace's arguments).
#pragma once

#include <cstdint>

namespace rayspec {

// VkAccelerationStructureInstanceKHR's 24-bit fields: instanceCustomIndex
// (gl_InstanceCustomIndexEXT, R-BUILTIN) and
// instanceShaderBindingTableRecordOffset (the hit group index, R-SBT-HIT);
// also the largest instance and geometry index a ray spec may name
// (maxInstanceCount and maxGeometryCount reach 2^24 - 1).
constexpr uint32_t kInstanceFieldBits = 24;
constexpr uint32_t kInstanceFieldMask = (1u << kInstanceFieldBits) - 1;  // 0xFFFFFF

// traceRayEXT's sbtRecordOffset and sbtRecordStride: only their low 4 bits
// enter the hit group index (R-SBT-HIT: instance offset + geometry x stride
// + offset).
constexpr uint32_t kTraceSbtFieldBits = 4;
constexpr uint32_t kTraceSbtFieldMask = (1u << kTraceSbtFieldBits) - 1;  // 0xF

// The instance mask and the cull mask: 8 bits; an instance is visited when
// their AND is not zero (R-MASK). The instance's flags are 8 bits too.
constexpr uint32_t kVisibilityMaskBits = 8;
constexpr uint32_t kVisibilityMask = (1u << kVisibilityMaskBits) - 1;  // 0xFF
constexpr uint32_t kInstanceFlagsMask = 0xFF;  // VkGeometryInstanceFlagsKHR's 8 bits

// traceRayEXT's missIndex: its low 16 bits pick the miss record (R-SBT-MISS).
constexpr uint32_t kTraceMissIndexBits = 16;
constexpr uint32_t kTraceMissIndexMask = (1u << kTraceMissIndexBits) - 1;  // 0xFFFF

}  // namespace rayspec
