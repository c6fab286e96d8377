// Case mutations of the shader binding table: a device that reads the wrong
// record, or the wrong data.
#include <functional>

#include "fault/fault_impl.h"
#include "fault/program_edit.h"
#include "plan/walk_program.h"
#include "program/shader_record_layout.h"

namespace rayspec {
namespace {

// Whether a callable can reach itself through the callable records (a
// computed index may reach any): the model and a device would recurse
// without end, so such a mutation is not applicable.
bool callablesRecurse(const Pipeline& p) {
  const std::vector<SbtRecord>& recs = p.sbt_callable;
  std::vector<std::vector<size_t>> next(recs.size());
  for (size_t r = 0; r < recs.size(); ++r) {
    if (!recs[r].group || *recs[r].group >= p.callables.size()) continue;
    walkStatements(p.callables[*recs[r].group], [&](const Stmt& s) {
      if (s.kind != Stmt::Kind::Call) return;
      if (s.call_index.kind != Expr::Kind::Literal || s.call_index.literal.empty()) {
        for (size_t k = 0; k < recs.size(); ++k) next[r].push_back(k);
      } else if (s.call_index.literal[0] < recs.size()) {
        next[r].push_back(static_cast<size_t>(s.call_index.literal[0]));
      }
    });
  }
  std::vector<int> state(recs.size(), 0);  // 0 new, 1 on the path, 2 done
  std::function<bool(size_t)> cycle = [&](size_t r) {
    if (state[r] == 1) return true;
    if (state[r] == 2) return false;
    state[r] = 1;
    for (size_t k : next[r])
      if (cycle(k)) return true;
    state[r] = 2;
    return false;
  };
  for (size_t r = 0; r < recs.size(); ++r)
    if (cycle(r)) return true;
  return false;
}

// Record i runs the group after its own (wrapping); all-zero records stay.
std::string shift(std::vector<SbtRecord>& region, size_t groups, const char* what) {
  if (groups < 2) return {};
  size_t n = 0;
  for (SbtRecord& r : explicitSbt(region, groups))
    if (r.group) {
      r.group = static_cast<uint32_t>((*r.group + 1) % groups);
      ++n;
    }
  return n ? std::to_string(n) + " " + what + " records run the next group's shaders"
           : std::string();
}

}  // namespace

std::string hitRecordShifted(Case& c, ModelOptions&) {
  return shift(c.pipeline.sbt_hit, c.pipeline.hit_groups.size(), "hit");
}

std::string missRecordShifted(Case& c, ModelOptions&) {
  return shift(c.pipeline.sbt_miss, c.pipeline.miss.size(), "miss");
}

std::string callableRecordShifted(Case& c, ModelOptions&) {
  const std::string what = shift(c.pipeline.sbt_callable, c.pipeline.callables.size(), "callable");
  return callablesRecurse(c.pipeline) ? std::string() : what;
}

std::string callableIndexIgnored(Case& c, ModelOptions&) {
  Pipeline& p = c.pipeline;
  size_t n = 0;
  std::vector<SbtRecord>& recs = explicitSbt(p.sbt_callable, p.callables.size());
  if (recs.size() < 2) return {};
  for (SbtRecord& r : recs) {
    n += r.group != recs[0].group || r.data != recs[0].data;
    r = recs[0];
  }
  if (!n || callablesRecurse(p)) return {};
  return std::to_string(n) + " callable records run record 0";
}

std::string customIndexTruncated(Case& c, ModelOptions&) {
  size_t n = 0;
  for (Instance& inst : c.scene.instances) {
    n += (inst.custom_index & kInstanceFieldMask) > 0xFFFF;
    inst.custom_index &= 0xFFFF;
  }
  return n ? std::to_string(n) + " instance custom indices keep 16 bits" : std::string();
}

std::string instanceSbtOffsetIgnored(Case& c, ModelOptions&) {
  size_t n = 0;
  for (Instance& inst : c.scene.instances) {
    n += inst.sbt_offset != 0;
    inst.sbt_offset = 0;
  }
  return n ? std::to_string(n) + " instance SBT offsets read as 0" : std::string();
}

std::string zeroRecordRunsGroup0(Case& c, ModelOptions&) {
  size_t n = 0;
  Pipeline& p = c.pipeline;
  for (auto [region, groups] :
       {std::pair{&p.sbt_hit, p.hit_groups.size()}, std::pair{&p.sbt_miss, p.miss.size()},
        std::pair{&p.sbt_callable, p.callables.size()}})
    for (SbtRecord& r : *region)
      if (!r.group && groups) {
        r.group = 0;
        ++n;
      }
  return n ? std::to_string(n) + " all-zero records run group 0" : std::string();
}

std::string shaderRecordDataZeroed(Case& c, ModelOptions&) {
  size_t n = 0;
  Pipeline& p = c.pipeline;
  auto zero = [&](std::vector<uint32_t>& data) {
    for (uint32_t& w : data) {
      n += w != 0;
      w = 0;
    }
  };
  zero(p.raygen_data);
  for (std::vector<SbtRecord>* region : {&p.sbt_hit, &p.sbt_miss, &p.sbt_callable})
    for (SbtRecord& r : *region) zero(r.data);
  return n ? std::to_string(n) + " shader record words read as 0" : std::string();
}

// A device that lays the shader record block out by the other rule (std430
// for scalar, scalar for std430): the members read other words.
std::string recordLayoutSwapped(Case& c, ModelOptions&) {
  ShaderRecordLayout& l = c.pipeline.record_layout;
  if (!l.declared()) return {};
  const ShaderRecordLayout before = l;
  l.scalar = !l.scalar;
  layOutShaderRecord(l);
  size_t moved = 0;
  for (size_t i = 0; i < l.members.size(); ++i)
    moved += l.members[i].offset != before.members[i].offset;
  if (!moved) return {};
  return std::to_string(moved) + " shader record member(s) read at their " +
         (l.scalar ? "scalar" : "std430") + " offsets";
}

}  // namespace rayspec
