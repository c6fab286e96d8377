#include "program/locals.h"

#include <algorithm>

namespace rayspec {

bool isLocalName(const std::string& name) {
  if (name.empty() || name.size() > 32 || name[0] < 'a' || name[0] > 'z') return false;
  return std::all_of(name.begin(), name.end(), [](char ch) {
    return (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_';
  });
}

bool isMemberName(const std::string& name) {
  const size_t dot = name.find('.');
  return dot != std::string::npos && isLocalName(name.substr(0, dot)) &&
         isLocalName(name.substr(dot + 1));
}

std::optional<ValueType> valueTypeNamed(const std::string& name) {
  for (ValueType t : enumValues<ValueType>())
    if (name == valueTypeSpelling(t)) return t;
  return std::nullopt;
}

const SpecConstant* LocalScope::findConstant(const std::string& name) const {
  if (!constants_) return nullptr;
  for (const SpecConstant& c : *constants_)
    if (c.name == name) return &c;
  return nullptr;
}

const LocalInfo* LocalScope::find(const std::string& name) const {
  for (auto it = names_.rbegin(); it != names_.rend(); ++it)
    if (it->first == name) return &it->second;
  return nullptr;
}

std::vector<std::string> LocalScope::membersOf(const std::string& name) const {
  std::vector<std::string> members;
  const std::string prefix = name + ".";
  for (const auto& [local, info] : names_)
    if (local.rfind(prefix, 0) == 0) members.push_back(local.substr(prefix.size()));
  return members;
}

std::optional<std::string> LocalScope::memberProblem(const std::string& name) const {
  const size_t dot = name.find('.');
  const LocalInfo* whole = find(name.substr(0, dot));
  if (dot == std::string::npos) {
    if (whole && whole->is_struct)
      return "'" + name + "' is a struct: name one of its members (" + name + ".MEMBER)";
    return std::nullopt;
  }
  const std::string base = name.substr(0, dot), member = name.substr(dot + 1);
  if (!whole) return "no struct '" + base + "' is declared here";
  if (!whole->is_struct) return "'" + base + "' is not a struct: it has no member '" + member + "'";
  if (find(name)) return std::nullopt;
  std::string known;
  for (const std::string& m : membersOf(base)) known += (known.empty() ? "" : ", ") + m;
  return "struct '" + base + "' has no member '" + member + "' (its members: " + known + ")";
}

const LocalInfo& LocalScope::declare(const std::string& name, LocalInfo info) {
  info.slot = next_slot_;
  next_slot_ += std::max<uint32_t>(info.elements, 1);
  frame_slots_ = std::max(frame_slots_, next_slot_);
  names_.emplace_back(name, info);
  return names_.back().second;
}

void LocalScope::closeBlock() {
  if (blocks_.empty()) return;
  const size_t keep = blocks_.back();
  blocks_.pop_back();
  names_.resize(keep);
  // Slots of a closed block are free again for its siblings.
  next_slot_ = 0;
  for (const auto& [name, info] : names_)
    next_slot_ = std::max(next_slot_, info.slot + std::max<uint32_t>(info.elements, 1));
}

LocalScope::Frame LocalScope::openFrame() {
  Frame saved{std::move(names_), std::move(blocks_), next_slot_, frame_slots_};
  names_.clear();
  blocks_.clear();
  next_slot_ = frame_slots_ = 0;
  return saved;
}

void LocalScope::closeFrame(Frame saved) {
  names_ = std::move(saved.names);
  blocks_ = std::move(saved.blocks);
  next_slot_ = saved.next_slot;
  frame_slots_ = saved.frame_slots;
}

}  // namespace rayspec
