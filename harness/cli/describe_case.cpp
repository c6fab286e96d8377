#include "cli/describe_case.h"

#include <cstdio>
#include <sstream>

#include "cli/model_expectations.h"
#include "glsl/emit_compute.h"

namespace rayspec {
namespace {

std::string hex(uint32_t v) {
  std::ostringstream s;
  s << "0x" << std::hex << v;
  return s.str();
}

size_t statementCount(const Program& p) {
  size_t n = 0;
  for (const Stmt& s : p) n += 1 + statementCount(s.then_) + statementCount(s.else_);
  return n;
}

void describeRecords(std::ostringstream& s, const char* region,
                     const std::vector<SbtRecord>& records) {
  s << "  sbt " << region << ":";
  for (const SbtRecord& r : records) {
    s << ' ' << (r.group ? "group " + std::to_string(*r.group) : std::string("zero"));
    if (!r.data.empty()) s << "+" << r.data.size() << "w";
  }
  s << '\n';
}

// pipeline.libraries as an indented tree.
void describeLibraries(const std::vector<PipelineLibrary>& libs, const std::string& indent,
                       std::ostringstream& s) {
  auto list = [](const char* what, const std::vector<uint32_t>& v) {
    std::string out;
    for (uint32_t i : v)
      out += std::string(out.empty() ? " " : ", ") + what + " " + std::to_string(i);
    return out;
  };
  for (const PipelineLibrary& lib : libs) {
    s << indent << "library:" << list("miss", lib.miss) << list("hit group", lib.hit_groups)
      << list("callable", lib.callables) << '\n';
    describeLibraries(lib.libraries, indent + "  ", s);
  }
}

// The payload and callable data types by location, and the shader record
// block's members, where the case declares them.
void describeInterfaceTypes(const Pipeline& p, std::ostringstream& s) {
  if (p.payload_words.size() > 1 || p.maxPayloadWords() > 0) {
    s << "  payload types by location:";
    for (size_t l = 0; l < p.payload_words.size(); ++l)
      s << " " << l << ": " << p.payloadBytes(l) << " bytes";
    s << '\n';
  }
  if (p.call_data_words.size() > 1 || p.maxCallDataWords() > 0) {
    s << "  callable data types by location:";
    for (size_t l = 0; l < p.call_data_words.size(); ++l)
      s << " " << l << ": " << 48 + 4 * p.callDataWords(l) << " bytes";
    s << '\n';
  }
  if (p.record_layout.declared()) {
    s << "  shader record members (" << (p.record_layout.scalar ? "scalar" : "std430") << "):";
    for (const RecordMember& m : p.record_layout.members)
      s << " " << m.name << " (" << valueTypeName(m.type) << ") at byte " << m.offset;
    s << '\n';
  }
}

// How the rays are launched: the trace command, or a compute dispatch.
std::string launchText(const Case& c) {
  if (!c.pipeline.from_compute)
    return std::string("launched by ") + traceCommandName(c.rays.command);
  const std::array<uint32_t, 3> g = computeGroups(c.rays.launchSize());
  return "launched by vkCmdDispatch of " + std::to_string(g[0]) + " x " + std::to_string(g[1]) +
         " x " + std::to_string(g[2]) + " workgroups of " + std::to_string(kComputeGroupSize) +
         " (pipeline.traces: ray_query_compute: raygen runs as a compute shader whose traces "
         "are ray queries; no ray tracing pipeline)";
}

std::string pointText(const std::array<double, 3>& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.9g, %.9g, %.9g)", p[0], p[1], p[2]);
  return buf;
}

// pipeline.deferred: the threads that join each pipeline's deferred operation.
void describeDeferred(const Pipeline& p, std::ostringstream& s) {
  if (!p.deferred_threads) return;
  s << "  created through a deferred operation joined by "
    << (*p.deferred_threads ? std::to_string(*p.deferred_threads) + " threads"
                            : std::string("its maximum concurrency of threads"))
    << '\n';
}

}  // namespace

std::string describeAimTargets(const std::vector<AimTarget>& aimed) {
  std::ostringstream s;
  if (aimed.empty()) return "";
  s << "Aimed rays (rays.aim: what each ray is aimed at):\n";
  for (size_t i = 0; i < aimed.size() && i < kShownRays; ++i) {
    const AimTarget& t = aimed[i];
    s << "  ray " << i << ": " << nameOf(t.feature) << " of instance " << t.instance << " geometry "
      << t.geometry << (t.primitives.size() == 1 ? " triangle" : " triangles");
    for (size_t k = 0; k < t.primitives.size(); ++k) s << (k ? ", " : " ") << t.primitives[k];
    s << " at " << pointText(t.object);
    if (t.world != t.object) s << " (world " << pointText(t.world) << ")";
    s << '\n';
  }
  if (aimed.size() > kShownRays) s << "  ... " << aimed.size() - kShownRays << " more rays\n";
  return s.str();
}

std::string describeCase(const Case& c) {
  std::ostringstream s;
  s << "Case " << c.name << "  (" << c.file << ")\n";
  s << "  family: " << (c.family.empty() ? "(none: a file outside the cases folder)" : c.family)
    << "\n  rules:";
  for (const auto& r : c.rules) s << ' ' << r;
  s << '\n';
  if (!c.description.empty()) s << "  " << c.description << '\n';
  s << "Scene:\n";
  for (const Blas& b : c.scene.blases) {
    s << "  blas " << b.name << ":\n";
    for (size_t g = 0; g < b.geometries.size(); ++g) {
      const Geometry& geo = b.geometries[g];
      s << "    geometry " << g << ": " << geo.primitiveCount()
        << (geo.kind == Geometry::Kind::Triangles ? " triangles" : " aabbs") << ", flags "
        << hex(geo.flags) << (geo.transform ? ", geometry transform" : "") << '\n';
    }
  }
  for (size_t i = 0; i < c.scene.instances.size(); ++i) {
    const Instance& in = c.scene.instances[i];
    s << "  instance " << i << ": blas "
      << (in.blas ? c.scene.blases[*in.blas].name : std::string("null")) << ", mask "
      << hex(in.mask) << ", custom " << in.custom_index << ", sbt offset " << in.sbt_offset
      << ", flags " << hex(in.flags) << '\n';
  }
  s << "Rays: " << c.rays.launchSize()[0] << " x " << c.rays.launchSize()[1] << " x "
    << c.rays.launchSize()[2] << " ("
    << (c.rays.same ? "every id the same ray" : std::to_string(c.rays.rays.size()) + " rays")
    << "), defaults tmin " << c.rays.defaults.tmin << " tmax " << c.rays.defaults.tmax << " flags "
    << hex(c.rays.defaults.flags) << ", " << launchText(c) << '\n';
  const Pipeline& p = c.pipeline;
  s << "Pipeline: max recursion " << p.max_recursion << ", flags " << hex(p.flags) << ", "
    << (p.callable_depth
            ? "stack size set for callables " + std::to_string(*p.callable_depth) + " deep"
            : "default stack size (callables " + std::to_string(kDefaultCallableDepth) + " deep)")
    << '\n';
  s << "  raygen: " << statementCount(p.raygen) << " statements\n";
  for (size_t i = 0; i < p.miss.size(); ++i)
    s << "  miss " << i << ": " << statementCount(p.miss[i]) << " statements"
      << (p.missPayload(i) ? ", payload type of location " + std::to_string(p.missPayload(i)) : "")
      << '\n';
  for (size_t i = 0; i < p.hit_groups.size(); ++i) {
    const HitGroup& g = p.hit_groups[i];
    s << "  hit group " << i << ":";
    if (g.closest_hit) s << " closest-hit(" << statementCount(*g.closest_hit) << ")";
    if (g.any_hit) s << " any-hit(" << statementCount(*g.any_hit) << ")";
    if (g.intersection) s << " intersection(" << statementCount(*g.intersection) << ")";
    if (g.payload) s << ", payload type of location " << g.payload;
    s << '\n';
  }
  for (size_t i = 0; i < p.callables.size(); ++i)
    s << "  callable " << i << ": " << statementCount(p.callables[i]) << " statements"
      << (p.callableData(i)
              ? ", callable data type of location " + std::to_string(p.callableData(i))
              : "")
      << '\n';
  if (p.raygenGroupCount() > 1)
    s << "  raygen groups: " << p.raygenGroupCount() << ", the region selects " << p.raygen_group
      << '\n';
  describeLibraries(p.libraries, "  ", s);
  describeDeferred(p, s);
  describeInterfaceTypes(p, s);
  if (p.sbt_record_data != kMaxShaderRecordDataBytes || p.sbt_padding.miss || p.sbt_padding.hit ||
      p.sbt_padding.callable)
    s << "  sbt record: handle + " << p.sbt_record_data << " data bytes + padding (miss "
      << p.sbt_padding.miss << ", hit " << p.sbt_padding.hit << ", callable "
      << p.sbt_padding.callable << ")\n";
  describeRecords(s, "miss", p.sbt_miss);
  describeRecords(s, "hit", p.sbt_hit);
  describeRecords(s, "callable", p.sbt_callable);
  if (!c.static_undefined.empty()) {
    // A robustness probe (R-UB): what it does that is undefined, found by the parser.
    s << "Undefined behaviour (R-UB probe: only survival is checked):\n";
    for (const StaticUndefined& u : c.static_undefined)
      s << "  " << u.loc.file << ':' << u.loc.line << ':' << u.loc.column << ": " << u.loc.field
        << ": " << u.message << " [" << undefinedReasonName(u.reason) << "]\n";
  }
  return s.str();
}

}  // namespace rayspec
