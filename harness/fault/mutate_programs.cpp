// Case mutations of the stage programs: a device that gets a statement's
// meaning wrong acts as the correct one on the changed program.
#include <algorithm>

#include "case/flag_names.h"
#include "fault/fault_impl.h"
#include "fault/program_edit.h"
#include "program/builtins.h"
#include "program/ops.h"
#include "program/payload_words.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

size_t removeEverywhere(Case& c, Stmt::Kind kind, StageMask stages = kAllStages) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage s) {
    if (stages & stageBit(s)) n += removeStmts(p, [&](const Stmt& st) { return st.kind == kind; });
  });
  return n;
}

// Moves each statement of `kind` to the end of its block: what came after
// it now runs before it.
size_t moveToBlockEnd(Case& c, Stmt::Kind kind) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    forEachBlock(p, [&](std::vector<Stmt>& block) {
      for (size_t i = 0; i + 1 < block.size(); ++i) {
        if (block[i].kind != kind) continue;
        Stmt s = std::move(block[i]);
        block.erase(block.begin() + static_cast<long>(i));
        block.push_back(std::move(s));
        ++n;
        break;
      }
    });
  });
  return n;
}

size_t eachReport(Case& c, const std::function<bool(Stmt&)>& edit) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    forEachStmt(p, [&](Stmt& s) {
      if (s.kind == Stmt::Kind::Report && edit(s)) ++n;
    });
  });
  return n;
}

Program ignoreEverything() {
  Stmt s;
  s.kind = Stmt::Kind::Ignore;
  return {s};
}

}  // namespace

std::string ignoreAccepts(Case& c, ModelOptions&) {
  return describeCount(removeEverywhere(c, Stmt::Kind::Ignore),
                       "ignoreIntersectionEXT calls accept");
}

std::string codeAfterIgnoreRuns(Case& c, ModelOptions&) {
  return describeCount(moveToBlockEnd(c, Stmt::Kind::Ignore),
                       "blocks run past ignoreIntersectionEXT");
}

std::string terminateContinues(Case& c, ModelOptions&) {
  return describeCount(removeEverywhere(c, Stmt::Kind::Terminate),
                       "terminateRayEXT calls let traversal go on");
}

std::string codeAfterTerminateRuns(Case& c, ModelOptions&) {
  return describeCount(moveToBlockEnd(c, Stmt::Kind::Terminate), "blocks run past terminateRayEXT");
}

std::string reportReturnInverted(Case& c, ModelOptions&) {
  return describeCount(eachReport(c,
                                  [](Stmt& s) {
                                    if (s.then_.empty() && s.else_.empty()) return false;
                                    std::swap(s.then_, s.else_);
                                    return true;
                                  }),
                       "reports run the other branch");
}

std::string reportKindDropped(Case& c, ModelOptions&) {
  return describeCount(eachReport(c,
                                  [](Stmt& s) {
                                    if (s.hit_kind.kind == Expr::Kind::Literal &&
                                        !s.hit_kind.literal.empty() && s.hit_kind.literal[0] == 0)
                                      return false;
                                    s.hit_kind = uintLiteral(0, s.hit_kind.loc);
                                    return true;
                                  }),
                       "reports lose their hit kind");
}

std::string hitAttributesLost(Case& c, ModelOptions&) {
  return describeCount(eachReport(c,
                                  [](Stmt& s) {
                                    const bool had = !s.attribute.empty() || !s.assigns.empty();
                                    s.attribute.clear();
                                    s.assigns.clear();  // its words
                                    return had;
                                  }),
                       "reports lose their attribute");
}

std::string closestAnyHitSkipped(Case& c, ModelOptions&) {
  size_t n = 0;
  for (HitGroup& g : c.pipeline.hit_groups) {
    n += g.any_hit.has_value();
    g.any_hit.reset();
  }
  return describeCount(n, "any-hit shaders never run");
}

std::string ignoreDiscardsWrites(Case& c, ModelOptions& o) {
  size_t n = 0;
  for (const HitGroup& g : c.pipeline.hit_groups)
    if (g.any_hit)
      walkStatements(*g.any_hit, [&](const Stmt& s) { n += s.kind == Stmt::Kind::Ignore; });
  if (!n) return "";
  o.faults.ignore_discards_writes = true;
  return describeCount(n, "ignores in any-hit that discard what the invocation wrote before");
}

std::string unusedAnyHitIgnores(Case& c, ModelOptions&) {
  size_t n = 0;
  for (HitGroup& g : c.pipeline.hit_groups)
    if (!g.any_hit) {
      g.any_hit = ignoreEverything();
      ++n;
    }
  // All-zero hit records: a group of their own whose any-hit ignores.
  std::vector<SbtRecord>& hits = c.pipeline.sbt_hit;
  bool zero = false;
  for (const SbtRecord& r : hits) zero = zero || !r.group;
  if (zero) {
    HitGroup g;
    g.any_hit = ignoreEverything();
    c.pipeline.hit_groups.push_back(g);
    for (SbtRecord& r : hits)
      if (!r.group) {
        r.group = static_cast<uint32_t>(c.pipeline.hit_groups.size() - 1);
        ++n;
      }
  }
  return describeCount(n,
                       "hit groups (or all-zero records) without any-hit ignore every candidate");
}

std::string payloadWritesLost(Case& c, ModelOptions&) {
  return describeCount(removeEverywhere(c, Stmt::Kind::SetPayload), "payload writes lost");
}

std::string payloadStartLost(Case& c, ModelOptions&) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    forEachStmt(p, [&](Stmt& s) {
      if (s.kind != Stmt::Kind::Trace || s.assigns.empty()) return;
      s.assigns.clear();
      ++n;
    });
  });
  return describeCount(n, "traces start with a zero payload");
}

namespace {

// Removes the word writes of every `kind` statement, and the stores into
// `indexed` (payload.words / call.words); how many.
size_t wordWritesLost(Case& c, Stmt::Kind kind, WordArray indexed) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    n += removeStmts(p, [&](const Stmt& s) {
      return s.kind == Stmt::Kind::Store && wordArrayOfStore(s.local) == indexed;
    });
    forEachStmt(p, [&](Stmt& s) {
      if (s.kind != kind) return;
      auto& a = s.assigns;
      const size_t before = a.size();
      a.erase(std::remove_if(a.begin(), a.end(),
                             [](const auto& f) { return payloadWordField(f.first).has_value(); }),
              a.end());
      n += before - a.size();
    });
  });
  return n;
}

}  // namespace

// A device that copies back only the first 24 bytes of a payload (color,
// value, depth): what miss, closest-hit and any-hit write into its words is lost.
std::string payloadWordsLost(Case& c, ModelOptions&) {
  return describeCount(wordWritesLost(c, Stmt::Kind::SetPayload, WordArray::Payload),
                       "payload word writes lost on the way back");
}

// The same for callable data (its first 48 bytes): a callable's word writes are lost.
std::string callDataWordsLost(Case& c, ModelOptions&) {
  return describeCount(wordWritesLost(c, Stmt::Kind::SetCall, WordArray::Call),
                       "callable data word writes lost on the way back");
}

// R-CULLMASK-BUILTIN: a device that never wires gl_CullMaskEXT to the
// trace's cull mask, reading the all-instances mask 0xFF instead.
std::string cullMaskBuiltinDefault(Case& c, ModelOptions&) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    editExpressions(p, [&](Expr& e) {
      if (!isBuiltin(e, kBiCullMask)) return;
      e = uintLiteral(kVisibilityMask, e.loc);
      ++n;
    });
  });
  return describeCount(n, "reads of gl_CullMaskEXT give 0xFF");
}

// R-BUILTIN: a device whose gl_IncomingRayFlagsEXT holds the pipeline's skip
// flags (SKIP_TRIANGLES, SKIP_AABBS) as the ray flags they act as, which the
// specification forbids (Built-In Variables, IncomingRayFlagsKHR).
std::string incomingFlagsWithPipelineSkip(Case& c, ModelOptions&) {
  uint32_t added = 0;
  if (c.pipeline.flags & kPipelineSkipTriangles) added |= kRaySkipTriangles;
  if (c.pipeline.flags & kPipelineSkipAabbs) added |= kRaySkipAabbs;
  if (!added) return {};
  // The reads first, then the edits: an edited read holds a read of its own.
  std::vector<Expr*> reads;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    editExpressions(p, [&](Expr& e) {
      if (isBuiltin(e, kBiFlags)) reads.push_back(&e);
    });
  });
  for (Expr* e : reads)
    *e = opExpr(Op::BitOr, {*e, uintLiteral(added, e->loc)}, ValueType::Uint, e->loc);
  return describeCount(reads.size(),
                       "reads of gl_IncomingRayFlagsEXT that hold the pipeline's skip flags");
}

// R-NULL-SHADERS: a device that reads a NO_NULL_*_SHADERS flag backwards,
// running the pipeline as if every shader of that kind were absent.
std::string noNullShadersDropped(Case& c, ModelOptions&) {
  const uint32_t flags = c.pipeline.flags;
  size_t n = 0;
  for (HitGroup& g : c.pipeline.hit_groups) {
    if ((flags & kPipelineNoNullAnyHit) && g.any_hit) n += (g.any_hit.reset(), 1);
    if ((flags & kPipelineNoNullClosestHit) && g.closest_hit) n += (g.closest_hit.reset(), 1);
    if ((flags & kPipelineNoNullIntersection) && g.intersection) n += (g.intersection.reset(), 1);
  }
  if (flags & kPipelineNoNullMiss)
    for (Program& m : c.pipeline.miss) n += (m.clear(), 1);
  return describeCount(n, "shaders a no_null_* flag promises run as absent");
}

std::string tlasIgnored(Case& c, ModelOptions&) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    forEachStmt(p, [&](Stmt& s) {
      if (s.kind != Stmt::Kind::Trace && s.kind != Stmt::Kind::RayQuery &&
          s.kind != Stmt::Kind::RestartQuery)
        return;
      if (s.trace.tlas == 0 && s.trace.tlas_index.empty()) return;
      s.trace.tlas = 0;
      s.trace.tlas_index.clear();  // a dynamic index too
      ++n;
    });
  });
  return describeCount(n,
                       "traces and ray queries traverse the first top level instead of the one "
                       "they name");
}

// R-LIBRARY: a linked pipeline that loses what its libraries hold.
size_t loseLibraryGroups(Pipeline& p, const std::vector<PipelineLibrary>& libs) {
  size_t n = 0;
  for (const PipelineLibrary& lib : libs) {
    for (uint32_t i : lib.miss) p.miss[i].clear();
    for (uint32_t i : lib.callables) p.callables[i].clear();
    for (uint32_t i : lib.hit_groups) {
      HitGroup& g = p.hit_groups[i];
      if (g.closest_hit) g.closest_hit->clear();
      g.any_hit.reset();
      if (g.intersection) g.intersection->clear();
    }
    n += lib.miss.size() + lib.callables.size() + lib.hit_groups.size() +
         loseLibraryGroups(p, lib.libraries);
  }
  return n;
}

std::string libraryGroupsLost(Case& c, ModelOptions&) {
  return describeCount(loseLibraryGroups(c.pipeline, c.pipeline.libraries),
                       "groups of pipeline libraries do nothing");
}

// R-DEFERRED: a pipeline used before its deferred operation completed, its
// groups after raygen not made yet.
std::string deferredGroupsLost(Case& c, ModelOptions&) {
  Pipeline& p = c.pipeline;
  if (!p.deferred_threads) return "";
  PipelineLibrary all;
  for (uint32_t i = 0; i < p.miss.size(); ++i) all.miss.push_back(i);
  for (uint32_t i = 0; i < p.hit_groups.size(); ++i) all.hit_groups.push_back(i);
  for (uint32_t i = 0; i < p.callables.size(); ++i) all.callables.push_back(i);
  return describeCount(loseLibraryGroups(p, {all}),
                       "groups of a pipeline used before its deferred operation completed do "
                       "nothing");
}

// R-RAYGEN-REGION: the launch runs group 0 (other_raygens[0] when another
// group is selected).
std::string raygenGroupIgnored(Case& c, ModelOptions&) {
  Pipeline& p = c.pipeline;
  if (p.raygen_group == 0) return "";
  std::swap(p.raygen, p.other_raygens[0]);
  return "the launch runs raygen group 0 instead of group " + std::to_string(p.raygen_group);
}

std::string callableDataNotReturned(Case& c, ModelOptions&) {
  const StageMask callable = stageBit(Stage::Callable);
  return describeCount(removeEverywhere(c, Stmt::Kind::SetCall, callable) +
                           removeEverywhere(c, Stmt::Kind::Light, callable),
                       "callable data writes lost");
}

std::string nestedTraceDropped(Case& c, ModelOptions&) {
  return describeCount(
      removeEverywhere(c, Stmt::Kind::Trace, kAllStages & ~stageBit(Stage::Raygen)),
      "nested traces do nothing");
}

// A nested hit's built-ins replace its caller's (model/model_faults.h): what
// a device whose nested query shares its caller's query would read, and
// what lavapipe's pipeline reads (builtins/after-nested).
std::string nestedTraceClobbersHit(Case& c, ModelOptions& o) {
  size_t traces = 0;
  for (const HitGroup& h : c.pipeline.hit_groups)
    if (h.closest_hit)
      walkStatements(*h.closest_hit, [&](const Stmt& s) { traces += s.kind == Stmt::Kind::Trace; });
  if (!traces) return "";
  o.faults.nested_trace_clobbers_hit = true;
  return describeCount(traces,
                       "closest-hit traces after which the nested hit's built-ins are read");
}

// R-AHIT-DUP, legal: any-hit runs twice in a row for each candidate of a
// geometry without NO_DUPLICATE_ANY_HIT_INVOCATION (the model's own repeat).
std::string anyHitRunsTwice(Case& c, ModelOptions& o) {
  o.any_hit_repeat = AnyHitRepeat::All;
  size_t n = 0;
  for (const Blas& b : c.scene.blases)
    for (const Geometry& g : b.geometries) n += !(g.flags & kGeometryNoDuplicateAnyHit);
  bool any_hit = false;
  for (const HitGroup& g : c.pipeline.hit_groups) any_hit = any_hit || g.any_hit.has_value();
  return describeCount(any_hit ? n : 0, "geometries without no_duplicate_any_hit repeat any-hit");
}

// R-ISECT-MULTI, legal: an intersection shader runs twice for its primitive.
// Its second run reports again, and any-hit runs again for that report; a
// device must not do so on a NO_DUPLICATE_ANY_HIT_INVOCATION geometry
// (R-AHIT-DUP), so with any such box geometry in the scene a hit group with
// an any-hit keeps one run.
std::string intersectionRunsTwice(Case& c, ModelOptions&) {
  bool no_duplicate_boxes = false;
  for (const Blas& b : c.scene.blases)
    for (const Geometry& g : b.geometries)
      no_duplicate_boxes = no_duplicate_boxes || (g.kind == Geometry::Kind::Aabbs &&
                                                  (g.flags & kGeometryNoDuplicateAnyHit));
  size_t n = 0;
  for (HitGroup& g : c.pipeline.hit_groups)
    if (g.intersection && !g.intersection->empty() && !(no_duplicate_boxes && g.any_hit)) {
      const Program once = *g.intersection;
      g.intersection->insert(g.intersection->end(), once.begin(), once.end());
      ++n;
    }
  return describeCount(n, "intersection shaders run twice");
}

}  // namespace rayspec
