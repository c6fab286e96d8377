// The shader record reads of every stage program against the record's data
// bytes (pipeline.sbt.record_data): shader_record_uint / shader_record_float(i)
// (and hit_object_record_uint / _float(i), of the hit object's record) read
// bytes 4i..4i+3, the lights (the `light:` statement and the light_*
// ops) read floats 0..5 (point, directional) or 0..7 (spot). A read past the
// data would read the record's padding or the next record: an error at the
// read. Every index is a literal (program/type_check.cpp), so all are known.
// Where pipeline.sbt.record_layout declares the record's members, the block
// holds those members only: every word or light read is an error.
#include "parse/parse_parts.h"
#include "program/ops.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

// Bytes of record data a light of this kind reads (shaders/lights.glsl).
uint32_t lightBytes(const std::string& kind) {
  return kind == "spot" ? 32 : 24;
}

// Bytes the expression itself reads (not its arguments); 0 when none or unknown.
uint32_t bytesRead(const Expr& e, std::string* what) {
  if (e.kind != Expr::Kind::Op) return 0;
  if (e.op == Op::RecordUint || e.op == Op::RecordFloat || e.op == Op::HitObjectRecordUint ||
      e.op == Op::HitObjectRecordFloat) {
    if (e.args.size() != 1 || e.args[0].kind != Expr::Kind::Literal ||
        e.args[0].literal.size() != 1)
      return 0;
    const double i = e.args[0].literal[0];
    if (!(i >= 0 && i < 1e6)) return 0;
    const uint32_t word = static_cast<uint32_t>(i);
    *what = e.name + "(" + std::to_string(word) + ") reads bytes " + std::to_string(4 * word) +
            ".." + std::to_string(4 * word + 3);
    return 4 * word + 4;
  }
  if (e.name.rfind("light_", 0) == 0) {
    const uint32_t n = lightBytes(e.name.substr(6));
    *what = e.name + " reads floats 0.." + std::to_string(n / 4 - 1) + " (bytes 0.." +
            std::to_string(n - 1) + ")";
    return n;
  }
  return 0;
}

class ReadChecker {
 public:
  ReadChecker(YamlReader& r, uint32_t record_data, bool members)
      : r_(r), k_(record_data), members_(members) {}

  void program(const Program& p, const std::string& field) {
    if (r_.isBadProgram(field)) return;
    walkExpressions(p, [&](const Expr& e) {
      std::string what;
      if (const uint32_t n = bytesRead(e, &what); n > k_ || (n && members_))
        fail(e.loc, field, what);
    });
    walkStatements(p, [&](const Stmt& s) {
      if (s.kind != Stmt::Kind::Light) return;
      const uint32_t n = lightBytes(s.light);
      if (n > k_ || members_)
        fail(s.loc, field,
             "light: " + s.light + " reads floats 0.." + std::to_string(n / 4 - 1) + " (bytes 0.." +
                 std::to_string(n - 1) + ")");
    });
  }

 private:
  void fail(const SourceLoc& at, const std::string& field, const std::string& what) {
    SourceLoc loc = at;
    if (loc.file.empty()) loc.file = r_.file();
    if (loc.field.empty()) loc.field = field;
    if (members_) {
      r_.error(loc, what +
                        ", but pipeline.sbt.record_layout declares the record's members: read "
                        "them as shader_record.NAME");
      return;
    }
    r_.error(loc, what + " of its shader record, past pipeline.sbt.record_data (" +
                      std::to_string(k_) +
                      " bytes per record): it would read the padding or the next record");
  }

  YamlReader& r_;
  uint32_t k_;
  bool members_;
};

}  // namespace

void checkRecordReads(YamlReader& r, const Case& c) {
  const Pipeline& p = c.pipeline;
  const bool members = p.record_layout.declared();
  if (p.sbt_record_data >= kMaxShaderRecordDataBytes && !members) return;  // every read fits
  ReadChecker check(r, p.sbt_record_data, members);
  check.program(p.raygen, "pipeline.raygen");
  for (const Program& g : p.other_raygens) check.program(g, "pipeline.raygens");
  for (size_t i = 0; i < p.miss.size(); ++i)
    check.program(p.miss[i], "pipeline.miss[" + std::to_string(i) + "]");
  for (size_t i = 0; i < p.hit_groups.size(); ++i) {
    const HitGroup& g = p.hit_groups[i];
    const std::string f = "pipeline.hit_groups[" + std::to_string(i) + "].";
    if (g.closest_hit) check.program(*g.closest_hit, f + "closest_hit");
    if (g.any_hit) check.program(*g.any_hit, f + "any_hit");
    if (g.intersection) check.program(*g.intersection, f + "intersection");
  }
  for (size_t i = 0; i < p.callables.size(); ++i)
    check.program(p.callables[i], "pipeline.callables[" + std::to_string(i) + "]");
}

}  // namespace rayspec
