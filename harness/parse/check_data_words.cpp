// The payload and callable data locations traces and calls name, and the
// words programs read and write, against the types of pipeline.payloads and
// pipeline.callable_data:
// - a trace's location must be declared, its starting words
//   (trace.payload.word<i>) within its location's type; a miss, closest-hit
//   or any-hit reads and writes words of its own incoming type only (its
//   `payload:` location); raygen's payload.word<i> and a stage's
//   child.word<i> (the last trace's payload) are within the largest type;
// - the same for the sized members (pipeline.payloads[].sized): a read or
//   write names a member its type declares;
// - the same for a call (call.location, call.word<i>), a callable's
//   call.word<i> and call_data words (its `call_data:` location), and a
//   stage's callee.word<i> (the last call's data).
#include "parse/parse_parts.h"
#include "program/ops.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

constexpr const char* kPayloads = "pipeline.payloads";
constexpr const char* kCallData = "pipeline.callable_data";

// A stage and the location of its own incoming payload or callable data type.
struct Incoming {
  Stage stage = Stage::Raygen;
  uint32_t location = 0;
};

class WordChecker {
 public:
  WordChecker(YamlReader& r, const Pipeline& p) : r_(r), p_(p) {}

  void program(const Program& prog, const std::string& field, Incoming incoming) {
    if (r_.isBadProgram(field)) return;
    in_ = incoming;
    walkExpressions(prog, [&](const Expr& e) {
      if (e.kind == Expr::Kind::Builtin) read(e, field);
      if (auto which = e.kind == Expr::Kind::Op ? wordArrayOf(e.op) : std::nullopt)
        indexed(e.loc, field, "{" + e.name + ": ...}", *which);
    });
    walkStatements(prog, [&](const Stmt& s) {
      if (s.kind == Stmt::Kind::SetPayload)
        writes(s, field, "payload.", words(WordArray::Payload), sized(WordArray::Payload),
               typeOf(WordArray::Payload), kPayloads);
      if (s.kind == Stmt::Kind::SetCall)
        writes(s, field, "call_data.", words(WordArray::Call), sized(WordArray::Call),
               typeOf(WordArray::Call), kCallData);
      if (auto which = s.kind == Stmt::Kind::Store ? wordArrayOfStore(s.local) : std::nullopt)
        indexed(s.loc, field, "store to " + s.local, *which);
      // execute passes a payload location as a trace does.
      if (s.kind == Stmt::Kind::Trace || s.kind == Stmt::Kind::ExecuteHitObject) trace(s, field);
      if (s.kind == Stmt::Kind::Call) call(s, field);
    });
  }

 private:
  uint32_t words(WordArray which) const { return p_.indexedWords(which, in_.stage, in_.location); }

  std::string typeOf(WordArray which) const {
    const bool own = in_.stage != Stage::Raygen;
    switch (which) {
      case WordArray::Payload:
        return own ? "this shader's payload type" : "the largest payload type";
      case WordArray::Child:
        return "the largest payload type";
      case WordArray::Call:
        return "this callable's data type";
      case WordArray::Callee:
        return "the largest callable data type";
    }
    return "";
  }

  static const char* listOf(WordArray which) {
    return which == WordArray::Payload || which == WordArray::Child ? kPayloads : kCallData;
  }

  void read(const Expr& e, const std::string& field) {
    if (const auto which = wordArrayOf(e.builtin))
      within(e.loc, field, e.name, e.word, words(*which), typeOf(*which), listOf(*which));
    if (const auto data = sizedDataOf(static_cast<Builtin>(e.builtin))) {
      const WordArray which = static_cast<WordArray>(*data);  // the same order, less Attribute
      if (*data != SizedData::Attribute)
        member(e.loc, field, e.name, static_cast<ValueType>(e.word), sized(which), typeOf(which),
               listOf(which));
    }
  }

  // The sized members of `which` as this stage declares it.
  SizedMembers sized(WordArray which) const {
    const bool raygen = in_.stage == Stage::Raygen;
    switch (which) {
      case WordArray::Payload:
        return raygen ? p_.allPayloadSized() : p_.payloadSized(in_.location);
      case WordArray::Child:
        return p_.allPayloadSized();
      case WordArray::Call:
        return p_.callDataSized(in_.location);
      case WordArray::Callee:
        return p_.allCallDataSized();
    }
    return {};
  }

  void member(const SourceLoc& at, const std::string& field, const std::string& what, ValueType t,
              const SizedMembers& members, const std::string& type, const char* list) {
    if (holdsSized(members, t)) return;
    error(
        at, field,
        what + ": " + type + " has no " + valueTypeSpelling(t) + " member (" + list + "[].sized)");
  }

  // A read or store indexed by a value takes its index modulo the words: the
  // type must have some.
  void indexed(const SourceLoc& at, const std::string& field, const std::string& what,
               WordArray which) {
    if (words(which) > 0) return;
    error(at, field,
          what + " indexes words, but " + typeOf(which) + " has none (" + listOf(which) +
              "[].words)");
  }

  void writes(const Stmt& s, const std::string& field, const std::string& prefix, uint32_t words,
              const SizedMembers& sized, const std::string& type, const char* list) {
    for (const auto& [name, value] : s.assigns) {
      if (auto i = payloadWordField(name))
        within(value.loc, field, prefix + name, *i, words, type, list);
      if (auto t = sizedMemberField(name))
        member(value.loc, field, prefix + name, *t, sized, type, list);
    }
  }

  void trace(const Stmt& s, const std::string& field) {
    const uint32_t location = s.trace.location;
    if (!declared(location, p_.payload_words.size(), s.trace.location_loc, field,
                  "payload location", kPayloads))
      return;
    writes(s, field, "trace.payload.", p_.payload_words[location], p_.payloadSized(location),
           "location " + std::to_string(location) + "'s payload type", kPayloads);
  }

  void call(const Stmt& s, const std::string& field) {
    const uint32_t location = s.call_location;
    if (!declared(location, p_.call_data_words.size(),
                  s.call_location_loc.line ? s.call_location_loc : s.loc, field,
                  "callable data location", kCallData))
      return;
    writes(s, field, "call.", p_.call_data_words[location], p_.callDataSized(location),
           "location " + std::to_string(location) + "'s callable data type", kCallData);
  }

  bool declared(uint32_t location, size_t count, const SourceLoc& at, const std::string& field,
                const std::string& what, const std::string& list) {
    if (location < count) return true;
    error(at, field,
          what + " " + std::to_string(location) + ", but " + list + " declares " +
              std::to_string(count));
    return false;
  }

  void within(const SourceLoc& at, const std::string& field, const std::string& what,
              uint32_t index, uint32_t words, const std::string& type, const char* list) {
    if (index < words) return;
    error(at, field,
          what + ": word " + std::to_string(index) + ", but " + type + " has " +
              std::to_string(words) + " word(s) (" + list + "[].words)");
  }

  void error(const SourceLoc& at, const std::string& field, const std::string& message) {
    SourceLoc loc = at;
    if (loc.file.empty()) loc.file = r_.file();
    if (loc.field.empty()) loc.field = field;
    r_.error(loc, message);
  }

  YamlReader& r_;
  const Pipeline& p_;
  Incoming in_;
};

}  // namespace

void checkDataWords(YamlReader& r, const Case& c) {
  const Pipeline& p = c.pipeline;
  WordChecker check(r, p);
  const Incoming raygen{Stage::Raygen, 0};
  check.program(p.raygen, "pipeline.raygen", raygen);
  for (const Program& g : p.other_raygens) check.program(g, "pipeline.raygens", raygen);
  for (size_t i = 0; i < p.miss.size(); ++i)
    check.program(p.miss[i], "pipeline.miss[" + std::to_string(i) + "]",
                  {Stage::Miss, p.missPayload(i)});
  for (size_t i = 0; i < p.hit_groups.size(); ++i) {
    const HitGroup& g = p.hit_groups[i];
    const std::string f = "pipeline.hit_groups[" + std::to_string(i) + "].";
    if (g.closest_hit)
      check.program(*g.closest_hit, f + "closest_hit", {Stage::ClosestHit, g.payload});
    if (g.any_hit) check.program(*g.any_hit, f + "any_hit", {Stage::AnyHit, g.payload});
    if (g.intersection)
      check.program(*g.intersection, f + "intersection", {Stage::Intersection, 0});
  }
  for (size_t i = 0; i < p.callables.size(); ++i)
    check.program(p.callables[i], "pipeline.callables[" + std::to_string(i) + "]",
                  {Stage::Callable, p.callableData(i)});
}

}  // namespace rayspec
