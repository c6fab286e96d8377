#include "program/shader_record_layout.h"

namespace rayspec {

uint32_t memberAlignment(ValueType t, bool scalar) {
  if (scalar) return 4;
  switch (t) {
    case ValueType::Vec2:
      return 8;
    case ValueType::Vec3:
    case ValueType::Vec4:
      return 16;
    default:
      return 4;
  }
}

void layOutShaderRecord(ShaderRecordLayout& layout) {
  uint32_t end = 0;
  for (RecordMember& m : layout.members) {
    const uint32_t align = memberAlignment(m.type, layout.scalar);
    m.offset = (end + align - 1) / align * align;
    end = m.offset + 4 * static_cast<uint32_t>(componentCount(m.type));
  }
  layout.bytes = end;
}

}  // namespace rayspec
