// The payload locations traces name and the payload words programs read and
// write, against the payload types of pipeline.payloads: a trace's location
// must be declared, its starting words (trace.payload.word<i>) within its
// location's type; a miss, closest-hit or any-hit reads and writes words of
// its own incoming type only (its `payload:` location); raygen's
// payload.word<i> and a stage's child.word<i> (the last trace's payload) are
// within the largest type.
#include "case/case_parts.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

class WordChecker {
 public:
  WordChecker(YamlReader& r, const Pipeline& p) : r_(r), p_(p) {}

  // `incoming`: the words of the stage's own payload type (raygen: the largest).
  void program(const Program& prog, const std::string& field, uint32_t incoming) {
    if (r_.isBadProgram(field)) return;
    const uint32_t largest = p_.maxPayloadWords();
    walkExpressions(prog, [&](const Expr& e) {
      if (e.kind != Expr::Kind::Builtin) return;
      if (auto w = payloadWordBuiltin(e.name))
        within(e.loc, field, e.name, w->index, w->child ? largest : incoming,
               w->child ? "the largest payload type" : "this shader's payload type");
    });
    walkStatements(prog, [&](const Stmt& s) {
      if (s.kind == Stmt::Kind::SetPayload)
        for (const auto& [name, value] : s.assigns)
          if (auto i = payloadWordField(name))
            within(value.loc, field, "payload." + name, *i, incoming, "this shader's payload type");
      if (s.kind == Stmt::Kind::Trace) trace(s, field);
    });
  }

 private:
  void trace(const Stmt& s, const std::string& field) {
    const uint32_t location = s.trace.location;
    if (location >= p_.payload_words.size()) {
      error(s.trace.location_loc, field,
            "payload location " + std::to_string(location) + ", but pipeline.payloads declares " +
                std::to_string(p_.payload_words.size()));
      return;
    }
    for (const auto& [name, value] : s.assigns)
      if (auto i = payloadWordField(name))
        within(value.loc, field, "trace.payload." + name, *i, p_.payload_words[location],
               "location " + std::to_string(location) + "'s payload type");
  }

  void within(const SourceLoc& at, const std::string& field, const std::string& what,
              uint32_t index, uint32_t words, const std::string& type) {
    if (index < words) return;
    error(at, field,
          what + ": word " + std::to_string(index) + ", but " + type + " has " +
              std::to_string(words) + " word(s) (pipeline.payloads[].words)");
  }

  void error(const SourceLoc& at, const std::string& field, const std::string& message) {
    SourceLoc loc = at;
    if (loc.file.empty()) loc.file = r_.file();
    if (loc.field.empty()) loc.field = field;
    r_.error(loc, message);
  }

  YamlReader& r_;
  const Pipeline& p_;
};

}  // namespace

void checkPayloadWords(YamlReader& r, const Case& c) {
  const Pipeline& p = c.pipeline;
  WordChecker check(r, p);
  auto words_of = [&](uint32_t location) {
    return location < p.payload_words.size() ? p.payload_words[location] : 0u;
  };
  check.program(p.raygen, "pipeline.raygen", p.maxPayloadWords());
  for (const Program& g : p.other_raygens)
    check.program(g, "pipeline.raygens", p.maxPayloadWords());
  for (size_t i = 0; i < p.miss.size(); ++i)
    check.program(p.miss[i], "pipeline.miss[" + std::to_string(i) + "]",
                  words_of(p.missPayload(i)));
  for (size_t i = 0; i < p.hit_groups.size(); ++i) {
    const HitGroup& g = p.hit_groups[i];
    const std::string f = "pipeline.hit_groups[" + std::to_string(i) + "].";
    if (g.closest_hit) check.program(*g.closest_hit, f + "closest_hit", words_of(g.payload));
    if (g.any_hit) check.program(*g.any_hit, f + "any_hit", words_of(g.payload));
    if (g.intersection) check.program(*g.intersection, f + "intersection", 0);
  }
  for (size_t i = 0; i < p.callables.size(); ++i)
    check.program(p.callables[i], "pipeline.callables[" + std::to_string(i) + "]", 0);
}

}  // namespace rayspec
