#include "spirv/builtin_inputs.h"

#include <spirv-tools/libspirv.h>

#include <map>
#include <set>

namespace rayspec {
namespace {

constexpr uint32_t kOpEntryPoint = 15, kOpDecorate = 71, kOpVariable = 59;
constexpr uint32_t kDecorationBuiltIn = 11, kStorageInput = 1;

struct Module {
  struct EntryPoint {
    std::string name;
    std::vector<uint32_t> interface;
  };
  std::vector<EntryPoint> entry_points;
  std::map<uint32_t, uint32_t> builtin_of;  // variable id -> BuiltIn
  std::set<uint32_t> inputs;                // ids of Input variables
};

uint32_t operandWord(const spv_parsed_instruction_t& in, uint16_t i) {
  return in.words[in.operands[i].offset];
}

spv_result_t collect(void* user, const spv_parsed_instruction_t* in) {
  Module& m = *static_cast<Module*>(user);
  if (in->opcode == kOpEntryPoint && in->num_operands >= 3) {
    const spv_parsed_operand_t& name = in->operands[2];
    Module::EntryPoint ep{reinterpret_cast<const char*>(in->words + name.offset), {}};
    for (uint16_t i = 3; i < in->num_operands; ++i) ep.interface.push_back(operandWord(*in, i));
    m.entry_points.push_back(std::move(ep));
  } else if (in->opcode == kOpDecorate && in->num_operands >= 3 &&
             operandWord(*in, 1) == kDecorationBuiltIn) {
    m.builtin_of[operandWord(*in, 0)] = operandWord(*in, 2);
  } else if (in->opcode == kOpVariable && in->num_operands >= 3 &&
             operandWord(*in, 2) == kStorageInput) {
    m.inputs.insert(in->result_id);
  }
  return SPV_SUCCESS;
}

}  // namespace

std::string duplicateBuiltinInputs(const std::vector<uint32_t>& words) {
  Module m;
  spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_2);
  const spv_result_t parsed =
      spvBinaryParse(context, &m, words.data(), words.size(), nullptr, collect, nullptr);
  spvContextDestroy(context);
  if (parsed != SPV_SUCCESS) return "the module could not be parsed for its built-in inputs\n";
  std::string problems;
  for (const Module::EntryPoint& ep : m.entry_points) {
    std::map<uint32_t, int> seen;  // BuiltIn -> Input variables carrying it
    for (uint32_t id : ep.interface) {
      auto b = m.builtin_of.find(id);
      if (b != m.builtin_of.end() && m.inputs.count(id) && ++seen[b->second] == 2)
        problems += "entry point '" + ep.name + "' lists two Input variables with BuiltIn " +
                    std::to_string(b->second) + " (VUID-StandaloneSpirv-OpEntryPoint-09658)\n";
    }
  }
  return problems;
}

}  // namespace rayspec
