// The hit-object statements of the stage vocabulary (GL_NV_shader_invocation_reorder):
// execute, record_miss, record_hit and reorder (table in cases/README.md).
#include "parse/parse_parts.h"

namespace rayspec {

// execute: {payload: {..}, location: k}: the hit object's shader run with
// that payload (as a trace starts it).
bool parseExecute(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::ExecuteHitObject;
  if (v.IsNull()) return true;
  if (!r.expectMap(v, f, {"payload", "location"})) return false;
  bool ok = constantIndex(r, v, f, "location", kMaxPayloadLocations - 1, s.trace.location,
                          s.trace.location_loc);
  if (const YAML::Node p = YamlReader::get(v, "payload"); p.IsDefined())
    ok = parsePayloadAssigns(r, p, f + ".payload", s) && ok;
  return ok;
}

// record_miss: {miss, origin, direction, tmin, tmax}: a miss recorded into
// the hit object without tracing, its fields defaulted as a trace's.
bool parseRecordMiss(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::RecordMiss;
  if (v.IsNull()) return true;
  if (!r.expectMap(v, f, {"miss", "origin", "direction", "tmin", "tmax"})) return false;
  return parseTraceSlots(r, v, f, s.trace);
}

// record_hit: {instance, primitive, geometry, hit_kind, attributes, sbt_offset
// and sbt_stride or sbt_index, origin, direction, tmin, tmax}: a hit recorded
// into the hit object without tracing (size 1: by its SBT record index).
bool parseRecordHit(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::RecordHit;
  if (!r.expectMap(v, f,
                   {"instance", "primitive", "geometry", "hit_kind", "attributes", "sbt_offset",
                    "sbt_stride", "sbt_index", "origin", "direction", "tmin", "tmax"}))
    return false;
  const bool by_index = YamlReader::has(v, "sbt_index");
  if (by_index && (YamlReader::has(v, "sbt_offset") || YamlReader::has(v, "sbt_stride"))) {
    r.error(v, f, "record_hit takes sbt_index or sbt_offset and sbt_stride, not both");
    return false;
  }
  s.size = by_index ? 1 : 0;
  bool ok = true;
  for (const char* key :
       {"instance", "primitive", "geometry", "hit_kind", "attributes", "sbt_index"}) {
    const YAML::Node e = YamlReader::get(v, key);
    if (!e.IsDefined() && std::string(key) == "sbt_index") continue;
    if (!e.IsDefined()) {
      r.error(v, f, std::string("record_hit needs '") + key + "'");
      ok = false;
      continue;
    }
    Expr x;
    ok = parseExpr(r, e, f + "." + key, x) && ok;
    s.assigns.emplace_back(key, std::move(x));
  }
  return parseTraceSlots(r, v, f, s.trace) && ok;
}

// reorder: {hit_object: true, hint: expr, bits: expr}: reorderThreadNV with
// the hit object, the hint, or both.
bool parseReorder(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::Reorder;
  if (!r.expectMap(v, f, {"hit_object", "hint", "bits"})) return false;
  bool ok = true;
  if (const YAML::Node h = YamlReader::get(v, "hit_object"); h.IsDefined()) {
    const std::optional<bool> yes = parseSwitch(r, h, f + ".hit_object");
    ok = yes.has_value();
    s.size = yes.value_or(false) ? 1 : 0;
  }
  const bool hint = YamlReader::has(v, "hint"), bits = YamlReader::has(v, "bits");
  if (hint != bits || (!hint && s.size == 0)) {
    r.error(v, f, "reorder takes hit_object: true, hint and bits, or all three");
    return false;
  }
  for (const char* key : {"hint", "bits"})
    if (hint) {
      Expr e;
      ok = parseExpr(r, YamlReader::get(v, key), f + "." + key, e) && ok;
      s.assigns.emplace_back(key, std::move(e));
    }
  return ok;
}

}  // namespace rayspec
