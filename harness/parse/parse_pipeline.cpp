// pipeline: recursion, flags, the stage programs and the shader binding table
// (its records, and their shape: record_data and padding bytes).
#include "case/flag_names.h"
#include "parse/parse_parts.h"

namespace rayspec {
namespace {

// Record data must fit in the record's data bytes: words past them would lie
// in the padding or the next record.
void checkDataFits(YamlReader& r, const YAML::Node& n, const std::string& field, size_t words,
                   uint32_t record_data) {
  if (words * 4 <= record_data) return;
  r.error(n, field,
          std::to_string(words) + " word(s) (" + std::to_string(words * 4) +
              " bytes) of shader record data do not fit in pipeline.sbt.record_data (" +
              std::to_string(record_data) + " bytes per record)");
}

// pipeline.sbt.record_data: bytes of data per record, a multiple of 4 in 0..32.
void parseRecordDataBytes(YamlReader& r, const YAML::Node& n, Pipeline& p) {
  const std::string f = "pipeline.sbt.record_data";
  auto k = r.uint(n, f, kMaxShaderRecordDataBytes);
  if (!k) return;
  if (*k % 4) {
    r.error(n, f, "must be a multiple of 4 (whole words of shader record data)");
    return;
  }
  p.sbt_record_data = *k;
}

// pipeline.sbt.padding: P (every region) or {miss: P, hit: P, callable: P}.
void parsePadding(YamlReader& r, const YAML::Node& n, SbtPadding& out) {
  const std::string f = "pipeline.sbt.padding";
  if (!n.IsMap()) {
    if (auto v = r.uint(n, f, kMaxSbtPaddingBytes)) out = {*v, *v, *v};
    return;
  }
  if (!r.expectMap(n, f, {"miss", "hit", "callable"})) return;
  struct Slot {
    const char* key;
    uint32_t* value;
  };
  for (Slot s : {Slot{"miss", &out.miss}, Slot{"hit", &out.hit}, Slot{"callable", &out.callable}})
    if (auto v = YamlReader::get(n, s.key); v.IsDefined())
      if (auto x = r.uint(v, f + "." + s.key, kMaxSbtPaddingBytes)) *s.value = *x;
}

// One SBT region: a group index, `zero`, or {group, data}.
void parseSbtRegion(YamlReader& r, const YAML::Node& n, const std::string& field, size_t groups,
                    const char* what, uint32_t record_data, std::vector<SbtRecord>& out) {
  if (!r.expectSeq(n, field)) return;
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string f = field + "[" + std::to_string(i) + "]";
    const YAML::Node item = n[i];
    SbtRecord rec;
    if (item.IsMap() && (!r.expectMap(item, f, {"group", "data"}) || !r.require(item, f, "group")))
      continue;
    // (yaml-cpp: assigning to a Node writes through to the node it refers to,
    // so the group node is bound once here.)
    const YAML::Node group = item.IsMap() ? YamlReader::get(item, "group") : item;
    if (item.IsMap()) {
      if (auto d = YamlReader::get(item, "data"); d.IsDefined())
        if (auto words = parseRecordData(r, d, f + ".data")) {
          checkDataFits(r, d, f + ".data", words->size(), record_data);
          rec.data = *words;
        }
    }
    if (group.IsScalar() && group.Scalar() == "zero") {
      if (!rec.data.empty()) r.error(item, f, "an all-zero record carries no data");
    } else if (auto g = r.uint(group, item.IsMap() ? f + ".group" : f)) {
      if (*g >= groups)
        r.error(group, item.IsMap() ? f + ".group" : f,
                "no " + std::string(what) + " " + std::to_string(*g) + " (there are " +
                    std::to_string(groups) + ")");
      rec.group = *g;
    }
    out.push_back(std::move(rec));
  }
}

std::vector<SbtRecord> defaultRegion(size_t n) {
  std::vector<SbtRecord> region(n);
  for (size_t i = 0; i < n; ++i) region[i].group = static_cast<uint32_t>(i);
  return region;
}

void parseHitGroups(YamlReader& r, const YAML::Node& n, const Pipeline& p,
                    std::vector<HitGroup>& out) {
  if (!r.expectSeq(n, "pipeline.hit_groups")) return;
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string f = "pipeline.hit_groups[" + std::to_string(i) + "]";
    HitGroup g;
    g.loc = r.loc(n[i], f);
    if (n[i].IsNull()) {  // `- {}` or `- ~`: a group with no shaders
      out.push_back(std::move(g));
      continue;
    }
    if (r.expectMap(n[i], f, {"closest_hit", "any_hit", "intersection", "payload"})) {
      if (auto v = YamlReader::get(n[i], "payload"); v.IsDefined())
        g.payload = parsePayloadLocation(r, v, f + ".payload", p).value_or(0);
      struct Slot {
        const char* key;
        std::optional<Program>* prog;
      };
      for (Slot s : {Slot{"closest_hit", &g.closest_hit}, Slot{"any_hit", &g.any_hit},
                     Slot{"intersection", &g.intersection}}) {
        const YAML::Node p = YamlReader::get(n[i], s.key);
        if (!p.IsDefined()) continue;
        Program prog;
        parseProgram(r, p, f + "." + s.key, prog);
        *s.prog = std::move(prog);
      }
    }
    out.push_back(std::move(g));
  }
}

// pipeline.raygens: several raygen groups, pipeline.raygen_group the one the
// raygen region selects (default 0); instead of pipeline.raygen.
void parseRaygenGroups(YamlReader& r, const YAML::Node& n, Pipeline& p) {
  const YAML::Node list = YamlReader::get(n, "raygens");
  const YAML::Node group = YamlReader::get(n, "raygen_group");
  if (!list.IsDefined()) {
    if (group.IsDefined()) r.error(group, "pipeline.raygen_group", "needs pipeline.raygens");
    return;
  }
  if (YamlReader::has(n, "raygen"))
    r.error(list, "pipeline.raygens", "give pipeline.raygen or pipeline.raygens, not both");
  std::vector<Program> programs;
  if (r.expectSeq(list, "pipeline.raygens"))
    for (size_t i = 0; i < list.size(); ++i) {
      Program prog;
      parseProgram(r, list[i], "pipeline.raygens[" + std::to_string(i) + "]", prog);
      programs.push_back(std::move(prog));
    }
  if (programs.empty()) {
    r.error(list, "pipeline.raygens", "needs at least one raygen program");
    return;
  }
  uint32_t selected = 0;
  if (group.IsDefined())
    if (auto g = r.uint(group, "pipeline.raygen_group", programs.size() - 1)) selected = *g;
  p.raygen_group = selected;
  p.raygen = programs[selected];
  for (size_t i = 0; i < programs.size(); ++i)
    if (i != selected) p.other_raygens.push_back(std::move(programs[i]));
}

// R-NULL-SHADERS: under no_null_any_hit / no_null_closest_hit every hit
// group names that shader (VUID-VkRayTracingPipelineCreateInfoKHR-flags-03470,
// -03471); an all-zero SBT record is what may still be reached (undefined).
void checkNoNullGroups(YamlReader& r, const Pipeline& p) {
  for (const HitGroup& g : p.hit_groups) {
    if ((p.flags & kPipelineNoNullAnyHit) && !g.any_hit)
      r.error(g.loc,
              "pipeline.flags has no_null_any_hit, so every hit group needs an any_hit "
              "(VUID-VkRayTracingPipelineCreateInfoKHR-flags-03470)");
    if ((p.flags & kPipelineNoNullClosestHit) && !g.closest_hit)
      r.error(g.loc,
              "pipeline.flags has no_null_closest_hit, so every hit group needs a "
              "closest_hit (VUID-VkRayTracingPipelineCreateInfoKHR-flags-03471)");
  }
}

// pipeline.hit_attribute: {words: N, sized: [types]}, the hit attribute's
// words and sized members after its vec2, 32 bytes in all.
void parseHitAttribute(YamlReader& r, const YAML::Node& v, Pipeline& p) {
  if (!r.expectMap(v, "pipeline.hit_attribute", {"words", "sized"})) return;
  if (auto w = YamlReader::get(v, "words"); w.IsDefined())
    if (auto x = r.uint(w, "pipeline.hit_attribute.words", kMaxAttributeWords))
      p.attribute_words = *x;
  const YAML::Node sized = YamlReader::get(v, "sized");
  if (!sized.IsDefined()) return;
  p.attribute_sized =
      parseSizedMembers(r, sized, "pipeline.hit_attribute.sized").value_or(SizedMembers{});
  if (p.attributeBytes() > kMaxAttributeBytes)
    r.error(
        sized, "pipeline.hit_attribute.sized",
        "the hit attribute holds " + std::to_string(p.attributeBytes()) + " bytes (its vec2, " +
            std::to_string(p.attribute_words) +
            " word(s) and these members, each aligned to the largest scalar of any), over the " +
            std::to_string(kMaxAttributeBytes) + " every device allows (maxRayHitAttributeSize)");
}

}  // namespace

// pipeline.traces: trace_ray (traceRayEXT, the default), ray_query (every
// trace a ray query loop, R-RQ-EQUIV), ray_query_compute (the same loops in
// raygen run as a compute shader) or ray_query_in_hit (the traces of
// closest-hit and miss stages alone); what the ray query forms cannot
// express is checked with the whole case (parse_case.cpp).
void parseTraces(YamlReader& r, const YAML::Node& v, Pipeline& p) {
  const std::optional<std::string> s = r.string(v, "pipeline.traces");
  if (!s) return;
  if (*s == "ray_query" || *s == "ray_query_compute") {
    p.ray_query = true;
    p.from_compute = *s == "ray_query_compute";
  } else if (*s == "ray_query_in_hit") {
    p.ray_query_in_hit = true;
  } else if (*s != "trace_ray") {
    r.error(
        v, "pipeline.traces",
        "must be trace_ray, ray_query, ray_query_compute or ray_query_in_hit, not '" + *s + "'");
  }
}

namespace {

// pipeline.max_recursion, pipeline.callable_depth and pipeline.flags.
void parseDepthsAndFlags(YamlReader& r, const YAML::Node& n, Pipeline& p) {
  if (auto v = YamlReader::get(n, "max_recursion"); v.IsDefined())
    if (auto x = r.uint(v, "pipeline.max_recursion", 31)) {
      if (*x == 0) r.error(v, "pipeline.max_recursion", "must be at least 1 (raygen traces)");
      p.max_recursion = *x;
    }
  if (auto v = YamlReader::get(n, "callable_depth"); v.IsDefined())
    if (auto x = r.uint(v, "pipeline.callable_depth", kMaxCallableDepth)) {
      if (*x == 0) r.error(v, "pipeline.callable_depth", "must be at least 1");
      p.callable_depth = *x;
    }
  if (auto v = YamlReader::get(n, "flags"); v.IsDefined())
    if (auto x = r.flags(v, "pipeline.flags", pipelineFlagNames())) p.flags = *x;
}

// pipeline.deferred: {threads: N} (1..kMaxDeferredThreads) or {threads: max}.
void parseDeferred(YamlReader& r, const YAML::Node& n, Pipeline& p) {
  if (!r.expectMap(n, "pipeline.deferred", {"threads"})) return;
  const YAML::Node v = YamlReader::get(n, "threads");
  if (!v.IsDefined()) {
    r.error(n, "pipeline.deferred",
            "needs threads: a count of 1 to " + std::to_string(kMaxDeferredThreads) + ", or max");
    return;
  }
  if (v.IsScalar() && v.Scalar() == "max") {
    p.deferred_threads = 0;
    return;
  }
  if (auto x = r.uint(v, "pipeline.deferred.threads", kMaxDeferredThreads)) {
    if (*x == 0) r.error(v, "pipeline.deferred.threads", "must be at least 1 (or max)");
    p.deferred_threads = *x;
  }
}

// The shape of every record of pipeline.sbt (record_data, padding,
// record_layout); false when there is no pipeline.sbt or it is not a map of
// its fields (then its regions are not read either).
bool parseRecordShape(YamlReader& r, const YAML::Node& sbt, Pipeline& p) {
  const bool sbt_ok = sbt.IsDefined() && r.expectMap(sbt, "pipeline.sbt",
                                                     {"record_data", "padding", "miss", "hit",
                                                      "callable", "record_layout"});
  if (!sbt_ok) return false;
  if (auto v = YamlReader::get(sbt, "record_data"); v.IsDefined()) parseRecordDataBytes(r, v, p);
  if (auto v = YamlReader::get(sbt, "padding"); v.IsDefined()) parsePadding(r, v, p.sbt_padding);
  if (auto v = YamlReader::get(sbt, "record_layout"); v.IsDefined()) parseRecordLayout(r, v, p);
  return true;
}

// The shaders after raygen, each after what it names: the payload types
// before the shaders that name a location, the constants before the programs
// that read them, the callable data types before the callables; then the
// functions copied into every program and the specializations, which name
// shaders.
void parseShaders(YamlReader& r, const YAML::Node& n, Pipeline& p) {
  if (auto v = YamlReader::get(n, "payloads"); v.IsDefined()) parsePayloadTypes(r, v, p);
  if (auto v = YamlReader::get(n, "constants"); v.IsDefined()) parseConstants(r, v, p);
  if (auto v = YamlReader::get(n, "hit_attribute"); v.IsDefined()) parseHitAttribute(r, v, p);
  if (auto v = YamlReader::get(n, "miss"); v.IsDefined()) parseMissShaders(r, v, p);
  if (auto v = YamlReader::get(n, "hit_groups"); v.IsDefined())
    parseHitGroups(r, v, p, p.hit_groups);
  if (auto v = YamlReader::get(n, "callable_data"); v.IsDefined()) parseCallDataTypes(r, v, p);
  if (auto v = YamlReader::get(n, "callables"); v.IsDefined()) parseCallables(r, v, p);
  expandFunctions(r, YamlReader::get(n, "functions"), p);
  if (auto v = YamlReader::get(n, "specialize"); v.IsDefined()) parseSpecialize(r, v, p);
}

// The SBT's miss, hit and callable regions: a record a group, in order,
// unless pipeline.sbt gives a region (sbt_ok: parseRecordShape's answer).
void parseSbtRegions(YamlReader& r, const YAML::Node& sbt, bool sbt_ok, Pipeline& p) {
  p.sbt_miss = defaultRegion(p.miss.size());
  p.sbt_hit = defaultRegion(p.hit_groups.size());
  p.sbt_callable = defaultRegion(p.callables.size());
  if (!sbt_ok) return;
  const uint32_t k = p.sbt_record_data;
  if (auto v = YamlReader::get(sbt, "miss"); v.IsDefined()) {
    p.sbt_miss.clear();
    parseSbtRegion(r, v, "pipeline.sbt.miss", p.miss.size(), "miss shader", k, p.sbt_miss);
  }
  if (auto v = YamlReader::get(sbt, "hit"); v.IsDefined()) {
    p.sbt_hit.clear();
    parseSbtRegion(r, v, "pipeline.sbt.hit", p.hit_groups.size(), "hit group", k, p.sbt_hit);
  }
  if (auto v = YamlReader::get(sbt, "callable"); v.IsDefined()) {
    p.sbt_callable.clear();
    parseSbtRegion(r, v, "pipeline.sbt.callable", p.callables.size(), "callable", k,
                   p.sbt_callable);
  }
}

// pipeline.layout: sets (the default: descriptor set 0) or empty (no set, no
// push constant: R-EMPTY-LAYOUT, checkEmptyLayout).
void parseLayout(YamlReader& r, const YAML::Node& v, Pipeline& p) {
  const std::optional<std::string> name = r.string(v, "pipeline.layout");
  if (!name) return;
  if (*name == "empty" || *name == "sets") {
    p.empty_layout = *name == "empty";
    return;
  }
  r.error(v, "pipeline.layout", "unknown layout '" + *name + "' (sets, empty)");
}

}  // namespace

void parsePipeline(YamlReader& r, const YAML::Node& n, Pipeline& p) {
  p.raygen.clear();
  Stmt trace;
  trace.kind = Stmt::Kind::Trace;
  trace.loc = r.loc(n, "pipeline.raygen");
  p.raygen.push_back(trace);  // default raygen: [trace: {}]
  if (!n.IsDefined()) return;
  if (!r.expectMap(n, "pipeline",
                   {"max_recursion", "flags",         "raygen",         "raygens",   "raygen_group",
                    "raygen_data",   "miss",          "hit_groups",     "callables", "sbt",
                    "libraries",     "payloads",      "callable_depth", "functions", "constants",
                    "specialize",    "hit_attribute", "callable_data",  "traces",    "deferred",
                    "tlas_function", "layout"}))
    return;
  parseDepthsAndFlags(r, n, p);
  if (auto v = YamlReader::get(n, "deferred"); v.IsDefined()) parseDeferred(r, v, p);
  if (auto v = YamlReader::get(n, "tlas_function"); v.IsDefined())
    p.tlas_function = parseTrueFalse(r, v, "pipeline.tlas_function").value_or(false);
  if (auto v = YamlReader::get(n, "layout"); v.IsDefined()) parseLayout(r, v, p);
  if (auto v = YamlReader::get(n, "raygen"); v.IsDefined()) {
    p.raygen.clear();
    parseProgram(r, v, "pipeline.raygen", p.raygen);
  }
  parseRaygenGroups(r, n, p);
  // The record shape first: the data of every record must fit in it.
  const YAML::Node sbt = YamlReader::get(n, "sbt");
  const bool sbt_ok = parseRecordShape(r, sbt, p);
  if (auto v = YamlReader::get(n, "raygen_data"); v.IsDefined())
    if (auto words = parseRecordData(r, v, "pipeline.raygen_data")) {
      checkDataFits(r, v, "pipeline.raygen_data", words->size(), p.sbt_record_data);
      p.raygen_data = *words;
    }
  parseShaders(r, n, p);
  if (auto v = YamlReader::get(n, "libraries"); v.IsDefined()) parseLibraries(r, v, p);
  checkNoNullGroups(r, p);
  checkAttributeWords(r, p);
  if (auto v = YamlReader::get(n, "traces"); v.IsDefined()) parseTraces(r, v, p);
  parseSbtRegions(r, sbt, sbt_ok, p);
}

}  // namespace rayspec
