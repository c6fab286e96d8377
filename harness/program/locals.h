// Local variables of stage programs and functions: `let`, `array`, a
// repeat's variable and a function's parameters, read as `var.NAME`. A local
// is visible from its declaration to the end of its block; a function sees
// only its parameters and its own locals (as in GLSL).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "program/program.h"
#include "program/stage_interface.h"

namespace rayspec {

// A lower-case letter, then lower-case letters, digits or '_', 32 at most.
bool isLocalName(const std::string& name);
// A struct's member as a local: STRUCT.MEMBER, each part a local's name.
bool isMemberName(const std::string& name);
inline std::string memberLocal(const std::string& structure, const std::string& member) {
  return structure + "." + member;
}

// The type a case file names in lower case, as GLSL does: bool, uint, float,
// vec2, vec3, vec4.
std::optional<ValueType> valueTypeNamed(const std::string& name);

struct LocalInfo {
  ValueType type = ValueType::Uint;  // an array's element type
  uint32_t elements = 0;             // an array's size; 0 for a scalar
  bool read_only = false;            // a repeat's variable
  bool is_struct = false;            // a struct (its members are the locals NAME.MEMBER)
  uint32_t slot = 0;                 // first slot in the frame (model)
};

// The locals visible at one point: blocks nest, functions start a new frame.
class LocalScope {
 public:
  const LocalInfo* find(const std::string& name) const;
  // The members of the struct `name` visible here, in declaration order.
  std::vector<std::string> membersOf(const std::string& name) const;
  // Why `var.NAME` (a member read or written, STRUCT.MEMBER, or a struct
  // read whole) names no value here; nullopt when it does.
  std::optional<std::string> memberProblem(const std::string& name) const;
  // Declares a local in the innermost block; its slot is the frame's next.
  const LocalInfo& declare(const std::string& name, LocalInfo info);
  void openBlock() { blocks_.push_back(names_.size()); }
  void closeBlock();
  // A function's frame: nothing of the caller is visible in it.
  struct Frame {
    std::vector<std::pair<std::string, LocalInfo>> names;
    std::vector<size_t> blocks;
    uint32_t next_slot = 0, frame_slots = 0;
  };
  Frame openFrame();
  void closeFrame(Frame saved);
  uint32_t frameSlots() const { return frame_slots_; }  // slots the frame needs
  // The specialization constants `const.NAME` reads (seen in every frame).
  void setConstants(const std::vector<SpecConstant>* constants) { constants_ = constants; }
  const SpecConstant* findConstant(const std::string& name) const;
  // Forbidden interface uses (program/stage_interface.h) are noted here
  // instead of refused, for a shader the case expects to be rejected.
  void waiveInterfaceRules(std::vector<InterfaceUse>* uses) { interface_uses_ = uses; }
  // Whether a use of `qualifier` was let through (and noted).
  bool letThrough(const std::string& qualifier, const std::string& what,
                  const SourceLoc& loc) const {
    if (!interface_uses_) return false;
    interface_uses_->push_back({qualifier, what, loc});
    return true;
  }
  // The block of the innermost ray_query the statements checked now are in:
  // where its getters (candidate.*, committed.*, query.*) may be read.
  enum class QueryBlock { None, Triangle, Aabb, After };
  void setQueryBlock(QueryBlock b) { query_block_ = b; }
  QueryBlock queryBlock() const { return query_block_; }
  // The shader record block's members `shader_record.NAME` reads.
  void setRecordLayout(const ShaderRecordLayout* layout) { record_layout_ = layout; }
  const RecordMember* findRecordMember(const std::string& name) const {
    return record_layout_ ? record_layout_->find(name) : nullptr;
  }

 private:
  const std::vector<SpecConstant>* constants_ = nullptr;
  const ShaderRecordLayout* record_layout_ = nullptr;
  std::vector<InterfaceUse>* interface_uses_ = nullptr;
  QueryBlock query_block_ = QueryBlock::None;
  std::vector<std::pair<std::string, LocalInfo>> names_;
  std::vector<size_t> blocks_;
  uint32_t next_slot_ = 0, frame_slots_ = 0;
};

}  // namespace rayspec
