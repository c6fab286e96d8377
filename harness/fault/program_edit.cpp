#include "fault/program_edit.h"

#include "plan/walk_program.h"

namespace rayspec {

std::string describeCount(size_t n, const std::string& what) {
  return n ? std::to_string(n) + " " + what : std::string();
}

namespace {

void eachTraceFlags(Case& c, const std::function<void(Expr&)>& visit) {
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    forEachStmt(p, [&](Stmt& s) {
      if (s.kind == Stmt::Kind::Trace)
        for (Expr& e : s.trace.flags) visit(e);
    });
  });
}

bool isLiteral(const Expr& e) {
  return e.kind == Expr::Kind::Literal && !e.literal.empty();
}

}  // namespace

void forEachProgram(const Pipeline& p, const std::function<void(const Program&, Stage)>& visit) {
  visit(p.raygen, Stage::Raygen);
  for (const Program& m : p.miss) visit(m, Stage::Miss);
  for (const HitGroup& g : p.hit_groups) {
    if (g.closest_hit) visit(*g.closest_hit, Stage::ClosestHit);
    if (g.any_hit) visit(*g.any_hit, Stage::AnyHit);
    if (g.intersection) visit(*g.intersection, Stage::Intersection);
  }
  for (const Program& k : p.callables) visit(k, Stage::Callable);
}

Expr uintLiteral(uint32_t v, const SourceLoc& loc) {
  Expr e;
  e.kind = Expr::Kind::Literal;
  e.type = ValueType::Uint;
  e.literal = {static_cast<double>(v)};
  e.loc = loc;
  return e;
}

void forEachProgram(Pipeline& p, const std::function<void(Program&, Stage)>& visit) {
  // One walk for both: the const one hands out what this pipeline owns.
  forEachProgram(static_cast<const Pipeline&>(p),
                 [&](const Program& prog, Stage s) { visit(const_cast<Program&>(prog), s); });
}

void forEachBlock(Program& p, const std::function<void(std::vector<Stmt>&)>& visit) {
  visit(p);
  for (Stmt& s : p) {
    forEachBlock(s.then_, visit);
    forEachBlock(s.else_, visit);
  }
}

void forEachStmt(Program& p, const std::function<void(Stmt&)>& visit) {
  forEachBlock(p, [&](std::vector<Stmt>& block) {
    for (Stmt& s : block) visit(s);
  });
}

size_t removeStmts(Program& p, const std::function<bool(const Stmt&)>& drop) {
  size_t removed = 0;
  forEachBlock(p, [&](std::vector<Stmt>& block) {
    const size_t before = block.size();
    std::erase_if(block, drop);
    removed += before - block.size();
  });
  return removed;
}

bool clearRayFlags(Case& c, uint32_t bits) {
  bool changed = false;
  auto clear = [&](uint32_t& flags) {
    changed = changed || (flags & bits);
    flags &= ~bits;
  };
  for (Ray& r : c.rays.rays) clear(r.flags);
  clear(c.rays.defaults.flags);
  eachTraceFlags(c, [&](Expr& e) {
    if (!isLiteral(e)) return;
    uint32_t f = static_cast<uint32_t>(e.literal[0]);
    clear(f);
    e.literal[0] = f;
  });
  return changed;
}

bool setRayFlags(Case& c, uint32_t bits) {
  bool changed = false;
  auto set = [&](uint32_t& flags) {
    changed = changed || (flags & bits) != bits;
    flags |= bits;
  };
  for (Ray& r : c.rays.rays) set(r.flags);
  set(c.rays.defaults.flags);
  eachTraceFlags(c, [&](Expr& e) {
    if (!isLiteral(e)) return;
    uint32_t f = static_cast<uint32_t>(e.literal[0]);
    set(f);
    e.literal[0] = f;
  });
  return changed;
}

bool mayUseRayFlags(const Case& c, uint32_t bits) {
  bool used = (c.rays.defaults.flags & bits) != 0;
  for (const Ray& r : c.rays.rays) used = used || (r.flags & bits);
  forEachProgram(c.pipeline, [&](const Program& p, Stage) {
    walkStatements(p, [&](const Stmt& s) {
      if (s.kind != Stmt::Kind::Trace) return;
      for (const Expr& e : s.trace.flags)
        used = used || !isLiteral(e) || (static_cast<uint32_t>(e.literal[0]) & bits);
    });
  });
  return used;
}

std::vector<SbtRecord>& explicitSbt(std::vector<SbtRecord>& region, size_t shaders) {
  if (region.empty())
    for (size_t i = 0; i < shaders; ++i) region.push_back({static_cast<uint32_t>(i), {}});
  return region;
}

}  // namespace rayspec
