// Stage programs: a list of statements (table in cases/README.md).
#include <cctype>

#include "case/flag_names.h"
#include "parse/parse_parts.h"
#include "program/builtins.h"
#include "program/locals.h"

namespace rayspec {
namespace {

bool parseStmt(YamlReader& r, const YAML::Node& n, const std::string& field, Stmt& s);

bool parseBlock(YamlReader& r, const YAML::Node& n, const std::string& field,
                std::vector<Stmt>& out) {
  if (n.IsNull()) return true;
  if (!r.expectSeq(n, field)) return false;
  bool ok = true;
  for (size_t i = 0; i < n.size(); ++i) {
    Stmt s;
    ok = parseStmt(r, n[i], field + "[" + std::to_string(i) + "]", s) && ok;
    out.push_back(std::move(s));
  }
  return ok;
}

// The words and sized members a payload, callable data or hit attribute
// type may have (payload_words.h), as the key lists of errors name them.
bool isWordKey(const std::string& key) {
  return payloadWordField(key).has_value() || sizedMemberField(key).has_value();
}
std::string wordKeys() {
  return "word0 .. word" + std::to_string(kPayloadWordNames - 1) +
         ", a sized member int8 .. f64vec4";
}

// {name: expr, ...} with names from `allowed` and the words, into s.assigns.
bool parseAssigns(YamlReader& r, const YAML::Node& n, const std::string& field,
                  std::initializer_list<const char*> allowed, Stmt& s) {
  if (!r.expectMap(n, field, allowed, isWordKey, wordKeys())) return false;
  bool ok = true;
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string name = it->first.Scalar();
    bool known = isWordKey(name);
    for (const char* a : allowed) known = known || name == a;
    if (!known) {
      ok = false;
      continue;
    }
    Expr e;
    ok = parseExpr(r, it->second, field + "." + name, e) && ok;
    s.assigns.emplace_back(name, std::move(e));
  }
  return ok;
}

bool parseRecord(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::Record;
  if (v.IsMap()) {
    bool ok = true;
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string name = it->first.IsScalar() ? it->first.Scalar() : "?";
      Expr e;
      ok = parseExpr(r, it->second, f + "." + name, e) && ok;
      s.assigns.emplace_back(name, std::move(e));
    }
    return ok;
  }
  if (!v.IsSequence()) {
    r.error(v, f, "expected [field, ...] or {field: expr, ...}");
    return false;
  }
  bool ok = true;
  for (size_t i = 0; i < v.size(); ++i) {
    const std::string fi = f + "[" + std::to_string(i) + "]";
    auto name = r.string(v[i], fi);
    if (!name) {
      ok = false;
      continue;
    }
    const std::optional<BuiltinName> b = builtinNamed(*name);
    if (!b) {
      r.error(v[i], fi,
              "record: [" + *name + "] needs a built-in named '" + *name + "'; write record: {" +
                  *name + ": EXPR}");
      ok = false;
      continue;
    }
    s.assigns.emplace_back(*name, builtinExpr(b->id, r.loc(v[i], f + "." + *name), b->word));
  }
  return ok;
}

// tlas: k (a constant: scene.instances[].tlas), or an expression that
// indexes the top levels (one that starts with a digit is a constant).
bool tlasField(YamlReader& r, const YAML::Node& v, const std::string& f, TraceArgs& t) {
  const YAML::Node n = YamlReader::get(v, "tlas");
  if (!n.IsDefined()) return true;
  if (n.IsScalar() && !n.Scalar().empty() &&
      std::isdigit(static_cast<unsigned char>(n.Scalar()[0])))
    return constantIndex(r, v, f, "tlas", kMaxTlases - 1, t.tlas, t.tlas_loc);
  t.tlas_loc = r.loc(n, f + ".tlas");
  Expr e;
  if (!parseExpr(r, n, f + ".tlas", e)) return false;
  t.tlas_index.push_back(std::move(e));
  return true;
}

bool parseTrace(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::Trace;
  if (v.IsNull()) return true;
  if (!r.expectMap(v, f,
                   {"origin", "direction", "tmin", "tmax", "flags", "cull_mask", "sbt_offset",
                    "sbt_stride", "miss", "payload", "tlas", "location", "hit_object"}))
    return false;
  bool ok = tlasField(r, v, f, s.trace);
  if (const YAML::Node h = YamlReader::get(v, "hit_object"); h.IsDefined()) {
    const std::optional<bool> yes = parseSwitch(r, h, f + ".hit_object");
    ok = yes.has_value() && ok;
    s.trace.hit_object = yes.value_or(false);
  }
  ok = constantIndex(r, v, f, "location", kMaxPayloadLocations - 1, s.trace.location,
                     s.trace.location_loc) &&
       ok;
  // The payload the trace starts with (zero where not given), into s.assigns.
  if (const YAML::Node p = YamlReader::get(v, "payload"); p.IsDefined())
    ok = parsePayloadAssigns(r, p, f + ".payload", s) && ok;
  return parseTraceSlots(r, v, f, s.trace) && ok;
}

// ray_query: {origin .., tlas, triangle: [..], aabb: [..], after: [..],
// order_dependent}: the query's fields as a trace's, its candidate blocks in
// then_ (Candidates, size 0 triangles, 1 AABBs), `after` in else_; size 1
// where it says order_dependent: true.
bool parseRayQuery(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::RayQuery;
  if (!v.IsNull() && !r.expectMap(v, f,
                                  {"origin", "direction", "tmin", "tmax", "flags", "cull_mask",
                                   "tlas", "triangle", "aabb", "after", "order_dependent"}))
    return false;
  bool ok = true;
  if (!v.IsNull()) {
    ok = tlasField(r, v, f, s.trace);
    ok = parseTraceSlots(r, v, f, s.trace) && ok;
    // Declared order-dependent: the model's exact tier tries every order.
    if (const YAML::Node d = YamlReader::get(v, "order_dependent"); d.IsDefined()) {
      const std::optional<bool> yes = parseSwitch(r, d, f + ".order_dependent");
      ok = yes.has_value() && ok;
      s.size = yes.value_or(false) ? 1 : 0;
    }
  }
  const char* blocks[] = {"triangle", "aabb"};
  for (uint32_t k = 0; k < 2; ++k) {
    Stmt c;
    c.kind = Stmt::Kind::Candidates;
    c.size = k;
    c.loc = s.loc;
    if (const YAML::Node b = v.IsNull() ? YAML::Node() : YamlReader::get(v, blocks[k]);
        b.IsDefined()) {
      c.loc = r.loc(b, f + "." + blocks[k]);
      ok = parseBlock(r, b, f + "." + blocks[k], c.then_) && ok;
    }
    s.then_.push_back(std::move(c));
  }
  if (const YAML::Node b = v.IsNull() ? YAML::Node() : YamlReader::get(v, "after"); b.IsDefined())
    ok = parseBlock(r, b, f + ".after", s.else_) && ok;
  return ok;
}

// ray_queries: [{ray_query fields and blocks}, ...]: 2 to kMaxSteppedQueries
// queries alive at once, stepped in turn, each a RayQuery in then_.
bool parseRayQueries(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::RayQueries;
  if (!v.IsSequence() || v.size() < 2 || v.size() > kMaxSteppedQueries) {
    r.error(v, f,
            "a list of 2 to " + std::to_string(kMaxSteppedQueries) +
                " ray queries (each as a ray_query's fields and blocks), stepped in turn");
    return false;
  }
  bool ok = true;
  for (size_t i = 0; i < v.size(); ++i) {
    const std::string fi = f + "[" + std::to_string(i) + "]";
    Stmt q;
    q.loc = r.loc(v[i], fi);
    if (!v[i].IsMap()) {
      r.error(v[i], fi, "a ray query: a map of a ray_query's fields and blocks");
      ok = false;
      continue;
    }
    ok = parseRayQuery(r, v[i], fi, q) && ok;
    s.then_.push_back(std::move(q));
  }
  return ok;
}

// restart_query: {origin .., tlas}: the innermost query initialized again
// with these fields (a ray_query's, defaulted alike).
bool parseRestartQuery(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::RestartQuery;
  if (v.IsNull()) return true;
  if (!r.expectMap(v, f, {"origin", "direction", "tmin", "tmax", "flags", "cull_mask", "tlas"}))
    return false;
  bool ok = tlasField(r, v, f, s.trace);
  return parseTraceSlots(r, v, f, s.trace) && ok;
}

bool parseReport(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::Report;
  auto attribute_key = [](const std::string& key) {
    const auto w = payloadWordField(key);
    return (w && *w < kMaxAttributeWords) || sizedMemberField(key).has_value();
  };
  if (!r.expectMap(v, f, {"t", "kind", "attribute", "accepted", "rejected"}, attribute_key,
                   "word0 .. word5, a sized member int8 .. f64vec4"))
    return false;
  if (!(r.require(v, f, "t") & r.require(v, f, "kind"))) return false;
  bool ok = parseExpr(r, YamlReader::get(v, "t"), f + ".t", s.t);
  ok = parseExpr(r, YamlReader::get(v, "kind"), f + ".kind", s.hit_kind) && ok;
  if (auto a = YamlReader::get(v, "attribute"); a.IsDefined()) {
    Expr e;
    ok = parseExpr(r, a, f + ".attribute", e) && ok;
    s.attribute.push_back(std::move(e));
  }
  for (auto it = v.begin(); it != v.end(); ++it) {
    const std::string key = it->first.Scalar();
    if (!attribute_key(key)) continue;
    Expr e;
    ok = parseExpr(r, it->second, f + "." + key, e) && ok;
    s.assigns.emplace_back(key, std::move(e));
  }
  if (auto a = YamlReader::get(v, "accepted"); a.IsDefined())
    ok = parseBlock(r, a, f + ".accepted", s.then_) && ok;
  if (auto a = YamlReader::get(v, "rejected"); a.IsDefined())
    ok = parseBlock(r, a, f + ".rejected", s.else_) && ok;
  return ok;
}

bool parseCall(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::Call;
  if (!r.expectMap(v, f, {"index", "location", "position", "normal", "value", "color"}, isWordKey,
                   wordKeys()))
    return false;
  if (!r.require(v, f, "index")) return false;
  bool ok = parseExpr(r, YamlReader::get(v, "index"), f + ".index", s.call_index);
  ok = constantIndex(r, v, f, "location", kMaxCallDataLocations - 1, s.call_location,
                     s.call_location_loc) &&
       ok;
  for (auto it = v.begin(); it != v.end(); ++it) {
    const std::string key = it->first.IsScalar() ? it->first.Scalar() : "";
    if (key != "position" && key != "normal" && key != "value" && key != "color" && !isWordKey(key))
      continue;
    Expr e;
    ok = parseExpr(r, it->second, f + "." + key, e) && ok;
    s.assigns.emplace_back(key, std::move(e));
  }
  return ok;
}

bool parseIf(YamlReader& r, const YAML::Node& n, const std::string& field, Stmt& s) {
  s.kind = Stmt::Kind::If;
  if (!r.expectMap(n, field, {"if", "then", "else"})) return false;
  bool ok = parseExpr(r, YamlReader::get(n, "if"), field + ".if", s.cond);
  if (auto t = YamlReader::get(n, "then"); t.IsDefined())
    ok = parseBlock(r, t, field + ".then", s.then_) && ok;
  if (auto e = YamlReader::get(n, "else"); e.IsDefined())
    ok = parseBlock(r, e, field + ".else", s.else_) && ok;
  return ok;
}

// A map whose keys are names the case chooses.
bool anyMap(YamlReader& r, const YAML::Node& n, const std::string& field) {
  if (n.IsMap()) return true;
  r.error(n, field, "expected a map");
  return false;
}

// repeat: COUNT, with var: NAME, from: FIRST and do: [..].
bool parseRepeat(YamlReader& r, const YAML::Node& n, const std::string& field, Stmt& s) {
  s.kind = Stmt::Kind::Repeat;
  if (!r.expectMap(n, field, {"repeat", "var", "from", "do"})) return false;
  bool ok = parseExpr(r, YamlReader::get(n, "repeat"), field + ".repeat", s.count);
  s.from.type = ValueType::Uint;
  s.from.literal = {0.0};
  s.from.loc = s.loc;
  if (auto v = YamlReader::get(n, "from"); v.IsDefined())
    ok = parseExpr(r, v, field + ".from", s.from) && ok;
  if (auto v = YamlReader::get(n, "var"); v.IsDefined()) {
    auto name = r.string(v, field + ".var");
    ok = name.has_value() && ok;
    if (name) s.local = *name;
  }
  if (auto v = YamlReader::get(n, "do"); v.IsDefined())
    ok = parseBlock(r, v, field + ".do", s.then_) && ok;
  return ok;
}

// switch: VALUE, with cases: {LABEL: [..], ...} and default: [..].
bool parseSwitch(YamlReader& r, const YAML::Node& n, const std::string& field, Stmt& s) {
  s.kind = Stmt::Kind::Switch;
  if (!r.expectMap(n, field, {"switch", "cases", "default"})) return false;
  bool ok = parseExpr(r, YamlReader::get(n, "switch"), field + ".switch", s.cond);
  if (auto v = YamlReader::get(n, "cases"); v.IsDefined()) {
    if (!anyMap(r, v, field + ".cases")) return false;
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string key = it->first.IsScalar() ? it->first.Scalar() : "?";
      const std::string fc = field + ".cases." + key;
      Stmt c;
      c.kind = Stmt::Kind::Case;
      c.loc = r.loc(it->first, fc);
      const auto label = r.uint(it->first, fc, 0xFFFFFFFFu);
      ok = label.has_value() && parseBlock(r, it->second, fc, c.then_) && ok;
      if (label) c.size = *label;
      s.then_.push_back(std::move(c));
    }
  }
  if (auto v = YamlReader::get(n, "default"); v.IsDefined())
    ok = parseBlock(r, v, field + ".default", s.else_) && ok;
  return ok;
}

// invoke: FUNCTION, with with: {PARAM: expr}; the body is filled in by
// expandInvokes (parse_functions.cpp).
bool parseInvoke(YamlReader& r, const YAML::Node& n, const std::string& field, Stmt& s) {
  s.kind = Stmt::Kind::Invoke;
  if (!r.expectMap(n, field, {"invoke", "with"})) return false;
  auto name = r.string(YamlReader::get(n, "invoke"), field + ".invoke");
  if (!name) return false;
  s.local = *name;
  const YAML::Node with = YamlReader::get(n, "with");
  if (!with.IsDefined()) return true;
  if (!anyMap(r, with, field + ".with")) return false;
  bool ok = true;
  for (auto it = with.begin(); it != with.end(); ++it) {
    const std::string key = it->first.IsScalar() ? it->first.Scalar() : "?";
    Expr e;
    ok = parseExpr(r, it->second, field + ".with." + key, e) && ok;
    s.assigns.emplace_back(key, std::move(e));
  }
  return ok;
}

// array: {name: NAME, of: TYPE, size: N}
bool parseArray(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::Array;
  if (!r.expectMap(v, f, {"name", "of", "size"}) || !r.require(v, f, "name") ||
      !r.require(v, f, "size"))
    return false;
  auto name = r.string(YamlReader::get(v, "name"), f + ".name");
  auto size = r.uint(YamlReader::get(v, "size"), f + ".size", kMaxArrayElements);
  if (name) s.local = *name;
  if (size) s.size = *size;
  bool ok = name && size;
  if (auto t = YamlReader::get(v, "of"); t.IsDefined()) {
    auto type_name = r.string(t, f + ".of");
    const auto type = type_name ? valueTypeNamed(*type_name) : std::nullopt;
    if (!type || *type == ValueType::Bool) {
      if (type_name) r.error(t, f + ".of", "an array holds " + arrayTypeSpellings());
      return false;
    }
    s.local_type = *type;
  }
  return ok;
}

// store: {array: NAME, index: expr, value: expr}
bool parseStore(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::Store;
  if (!r.expectMap(v, f, {"array", "index", "value"}) || !r.require(v, f, "array") ||
      !r.require(v, f, "index") || !r.require(v, f, "value"))
    return false;
  auto name = r.string(YamlReader::get(v, "array"), f + ".array");
  if (name) s.local = *name;
  bool ok = name && parseExpr(r, YamlReader::get(v, "index"), f + ".index", s.index);
  Expr e;
  ok = parseExpr(r, YamlReader::get(v, "value"), f + ".value", e) && ok;
  s.assigns.emplace_back("value", std::move(e));
  return ok;
}

// struct: {name: NAME, members: {MEMBER: TYPE, ...}}, in the order written.
bool parseStruct(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::Struct;
  if (!r.expectMap(v, f, {"name", "members"}) || !r.require(v, f, "name") ||
      !r.require(v, f, "members"))
    return false;
  auto name = r.string(YamlReader::get(v, "name"), f + ".name");
  if (name) s.local = *name;
  const YAML::Node members = YamlReader::get(v, "members");
  if (!anyMap(r, members, f + ".members")) return false;
  bool ok = name.has_value();
  for (auto it = members.begin(); it != members.end(); ++it) {
    const std::string member = it->first.IsScalar() ? it->first.Scalar() : "?";
    const std::string mf = f + ".members." + member;
    auto type_name = r.string(it->second, mf);
    const auto type = type_name ? valueTypeNamed(*type_name) : std::nullopt;
    if (!type || *type == ValueType::Bool) {
      if (type_name)
        r.error(it->second, mf,
                "unknown member type '" + *type_name + "': a member is " + arrayTypeSpellings());
      ok = false;
      continue;
    }
    s.params.emplace_back(member, *type);
  }
  return ok;
}

// let / set: {NAME: expr, ...}; set also {STRUCT.MEMBER: expr}.
bool parseLocals(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  if (!anyMap(r, v, f)) return false;
  bool ok = true;
  for (auto it = v.begin(); it != v.end(); ++it) {
    const std::string name = it->first.IsScalar() ? it->first.Scalar() : "?";
    if (!isLocalName(name) && !(s.kind == Stmt::Kind::Set && isMemberName(name))) {
      r.error(it->first, f + "." + name,
              s.kind == Stmt::Kind::Set
                  ? "set names a local (a lower-case letter, then letters, digits or _, at most "
                    "32) or a struct's member, STRUCT.MEMBER"
                  : "a local's name is a lower-case letter, then letters, digits or _ (at most "
                    "32)");
      ok = false;
      continue;
    }
    Expr e;
    ok = parseExpr(r, it->second, f + "." + name, e) && ok;
    s.assigns.emplace_back(name, std::move(e));
  }
  return ok;
}

bool scalarStmt(YamlReader& r, const YAML::Node& n, const std::string& field, Stmt& s) {
  static const std::pair<const char*, Stmt::Kind> kScalars[] = {
      {"ignore", Stmt::Kind::Ignore},
      {"terminate", Stmt::Kind::Terminate},
      {"break", Stmt::Kind::Break},
      {"continue", Stmt::Kind::Continue},
      {"return", Stmt::Kind::Return},
      {"confirm", Stmt::Kind::Confirm},
      {"terminate_query", Stmt::Kind::TerminateQuery},
      {"record_empty", Stmt::Kind::RecordEmpty}};
  for (const auto& [name, kind] : kScalars)
    if (n.Scalar() == name) {
      s.kind = kind;
      return true;
    }
  r.error(n, field,
          "unknown statement '" + n.Scalar() +
              "' (ignore, terminate, break, continue, return, confirm, terminate_query, "
              "record_empty)");
  return false;
}

// Every statement's key, for the error of an unknown one.
const char* const kStatementNames =
    "count, record, payload, call_data, ignore, terminate, report, trace, call, light, if, let, "
    "set, array, struct, store, repeat, switch, invoke, break, continue, return, ray_query, "
    "ray_queries, "
    "confirm, generate, terminate_query, restart_query, execute, record_miss, record_empty, "
    "record_hit, reorder";

using StmtParser = bool (*)(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s);

// if, repeat, switch and invoke: the statements whose map holds more keys
// than their own (then/else, body, cases, arguments); nullopt when n is none
// of them, else whether it parsed.
std::optional<bool> parseControlStmt(YamlReader& r, const YAML::Node& n, const std::string& field,
                                     Stmt& s) {
  static const std::pair<const char*, StmtParser> kControl[] = {
      {"if", parseIf}, {"repeat", parseRepeat}, {"switch", parseSwitch}, {"invoke", parseInvoke}};
  for (const auto& [key, parse] : kControl)
    if (YamlReader::has(n, key)) {
      s.loc = r.loc(n, field + "." + key);
      return parse(r, n, field, s);
    }
  return std::nullopt;
}

bool parseCount(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::Count;
  auto name = r.string(v, f);
  if (name) s.counter = *name;
  return name.has_value();
}

bool parseSetPayload(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::SetPayload;
  return parsePayloadAssigns(r, v, f, s);
}

bool parseSetCallData(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::SetCall;
  return parsePayloadAssigns(r, v, f, s);  // color, value and the words
}

bool parseLet(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::Let;
  return parseLocals(r, v, f, s);
}

bool parseSetLocals(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::Set;
  return parseLocals(r, v, f, s);
}

bool parseGenerate(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::Generate;
  return parseExpr(r, v, f, s.t);
}

bool parseLight(YamlReader& r, const YAML::Node& v, const std::string& f, Stmt& s) {
  s.kind = Stmt::Kind::Light;
  auto name = r.string(v, f);
  if (!name) return false;
  s.light = *name;
  if (s.light != "point" && s.light != "spot" && s.light != "directional") {
    r.error(v, f, "unknown light '" + s.light + "' (point, spot, directional)");
    return false;
  }
  return true;
}

// The statements that are a map of one key, by that key.
const std::pair<const char*, StmtParser> kKeyedStatements[] = {{"count", parseCount},
                                                               {"record", parseRecord},
                                                               {"payload", parseSetPayload},
                                                               {"call_data", parseSetCallData},
                                                               {"report", parseReport},
                                                               {"let", parseLet},
                                                               {"set", parseSetLocals},
                                                               {"array", parseArray},
                                                               {"struct", parseStruct},
                                                               {"store", parseStore},
                                                               {"trace", parseTrace},
                                                               {"ray_query", parseRayQuery},
                                                               {"ray_queries", parseRayQueries},
                                                               {"restart_query", parseRestartQuery},
                                                               {"generate", parseGenerate},
                                                               {"call", parseCall},
                                                               {"light", parseLight},
                                                               {"execute", parseExecute},
                                                               {"record_miss", parseRecordMiss},
                                                               {"record_hit", parseRecordHit},
                                                               {"reorder", parseReorder}};

bool parseStmt(YamlReader& r, const YAML::Node& n, const std::string& field, Stmt& s) {
  s.loc = r.loc(n, field);
  if (n.IsScalar()) return scalarStmt(r, n, field, s);
  if (!n.IsMap() || n.size() == 0) {
    r.error(n, field, "expected a statement ({count: NAME}, {record: ...}, ignore, ...)");
    return false;
  }
  if (const std::optional<bool> control = parseControlStmt(r, n, field, s)) return *control;
  if (n.size() != 1) {
    r.error(n, field, "one statement per list item (or if/then/else)");
    return false;
  }
  auto it = n.begin();
  const std::string key = it->first.IsScalar() ? it->first.Scalar() : "?";
  const std::string f = field + "." + key;
  s.loc = r.loc(it->first, f);
  for (const auto& [name, parse] : kKeyedStatements)
    if (key == name) return parse(r, it->second, f, s);
  r.error(it->first, f, "unknown statement '" + key + "' (" + kStatementNames + ")");
  return false;
}

}  // namespace

// A payload's fields: color, value and the words of its type (checkDataWords).
bool parsePayloadAssigns(YamlReader& r, const YAML::Node& n, const std::string& field, Stmt& s) {
  return parseAssigns(r, n, field, {"color", "value"}, s);
}

// A trace's constant index `key` (tlas, location) up to max, and where it is
// written; false when it is there but not such a number.
bool constantIndex(YamlReader& r, const YAML::Node& v, const std::string& f, const char* key,
                   uint32_t max, uint32_t& out, SourceLoc& loc) {
  const YAML::Node n = YamlReader::get(v, key);
  if (!n.IsDefined()) return true;
  loc = r.loc(n, f + "." + key);
  const auto index = r.uint(n, f + "." + key, max);
  if (index) out = *index;
  return index.has_value();
}

// The trace fields a trace or ray_query gives (origin .. miss), each an
// expression; flags also a list of ray flag names.
bool parseTraceSlots(YamlReader& r, const YAML::Node& v, const std::string& f, TraceArgs& t) {
  bool ok = true;
  struct Slot {
    const char* key;
    std::vector<Expr>* exprs;
  };
  const Slot slots[] = {{"origin", &t.origin},
                        {"direction", &t.direction},
                        {"tmin", &t.tmin},
                        {"tmax", &t.tmax},
                        {"flags", &t.flags},
                        {"cull_mask", &t.cull_mask},
                        {"sbt_offset", &t.sbt_offset},
                        {"sbt_stride", &t.sbt_stride},
                        {"miss", &t.miss}};
  for (const Slot& slot : slots) {
    const YAML::Node a = YamlReader::get(v, slot.key);
    if (!a.IsDefined()) continue;
    const std::string fa = f + "." + slot.key;
    Expr e;
    if (std::string(slot.key) == "flags" && a.IsSequence()) {
      // A list of ray flag names is a Uint literal.
      auto bits = r.flags(a, fa, rayFlagNames());
      if (!bits) {
        ok = false;
        continue;
      }
      e.kind = Expr::Kind::Literal;
      e.type = ValueType::Uint;
      e.literal = {static_cast<double>(*bits)};
      e.loc = r.loc(a, fa);
    } else if (!parseExpr(r, a, fa, e)) {
      ok = false;
      continue;
    }
    slot.exprs->push_back(std::move(e));
  }
  return ok;
}

bool parseProgram(YamlReader& r, const YAML::Node& n, const std::string& field, Program& out) {
  out.clear();
  if (!n.IsSequence()) {
    r.error(n, field, "a stage program is a list of statements");
    r.markBadProgram(field);
    return false;
  }
  const bool ok = parseBlock(r, n, field, out);
  if (!ok) r.markBadProgram(field);
  return ok;
}

}  // namespace rayspec
