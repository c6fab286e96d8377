// Byte offsets of the shader record block's members (pipeline.sbt.record_layout)
// under the two layouts a shaderRecordEXT block may declare:
// - std430: a scalar is aligned to 4 bytes, a vec2 to 8, a vec3 and a vec4 to
//   16 (a vec3 takes 12 bytes, so a scalar may follow in its last 4);
// - scalar (GL_EXT_scalar_block_layout): every member is aligned to its
//   component size, 4 bytes.
// The GLSL side declares the block with the same members and layout and lets
// the compiler place them; the model reads the record's words at these offsets.
#pragma once

#include <cstdint>

#include "program/program.h"

namespace rayspec {

// The alignment of a member of type t.
uint32_t memberAlignment(ValueType t, bool scalar);
// Fills each member's offset and the layout's bytes.
void layOutShaderRecord(ShaderRecordLayout& layout);

}  // namespace rayspec
