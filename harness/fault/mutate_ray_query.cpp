// Ray query rules broken (R-RQ-INIT .. R-RQ-VALUES): a device whose
// ray_query statements keep the last query's commit, offer opaque triangles,
// ignore confirm or terminate, or read committed values from the candidate
// (the model's test-only hooks, model/model_faults.h). On a case a
// --through ray-query* run sends its traces as query loops, each breaks
// those loops as well where it has a meaning there (ModelFaultSeam::inlinedQuery).
#include <initializer_list>

#include "fault/fault_impl.h"
#include "program/builtins.h"
#include "program/ops.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

// How many statements of `kind` the case's programs hold.
size_t countStatements(const Case& c, Stmt::Kind kind) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](const Program& p, Stage) {
    walkStatements(p, [&](const Stmt& s) { n += s.kind == kind; });
  });
  return n;
}

// How many reads of the built-ins `ids` the case's programs hold.
size_t countGetters(const Case& c, std::initializer_list<Builtin> ids) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](const Program& p, Stage) {
    walkExpressions(p, [&](const Expr& e) {
      for (Builtin id : ids) n += isBuiltin(e, id);
    });
  });
  return n;
}

// How many candidate blocks of the case's ray queries may leave their loop.
size_t loopLeavingBlocks(const Case& c) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](const Program& p, Stage) {
    walkStatements(p, [&](const Stmt& s) {
      if (s.kind == Stmt::Kind::Candidates) n += leavesQueryLoop(s.then_);
    });
  });
  return n;
}

// How many traces a --through ray-query* run inlines as ray query loops
// (glsl/emit_ray_query.h): every trace under pipeline.ray_query, those of
// closest-hit and miss under ray_query_in_hit. A planted query fault breaks
// their loops too, where it has a meaning there (ModelFaultSeam::inlinedQuery).
size_t inlinedTraces(const Case& c) {
  const Pipeline& p = c.pipeline;
  if (!p.ray_query && !p.ray_query_in_hit) return 0;
  size_t n = 0;
  forEachProgram(p, [&](const Program& program, Stage stage) {
    if (stage == Stage::Raygen && !p.ray_query) return;
    walkStatements(program, [&](const Stmt& s) { n += s.kind == Stmt::Kind::Trace; });
  });
  return n;
}

// What a fault breaks: `n` of the case's own statements (`what`), and its
// inlined traces, whose loops `inlined` ("" where none).
std::string plantedOn(size_t n, const std::string& what, const Case& c,
                      const std::string& inlined) {
  std::string out = describeCount(n, what);
  const size_t traces = inlined.empty() ? 0 : inlinedTraces(c);
  if (traces)
    out += (out.empty() ? "" : "; ") +
           describeCount(traces, "traces inlined as ray query loops that " + inlined);
  return out;
}

}  // namespace

std::string queryInitKeepsCommitted(Case& c, ModelOptions& o) {
  const size_t n = countStatements(c, Stmt::Kind::RayQuery);
  if (!n) return "";
  o.faults.rq_init_keeps_committed = true;
  return describeCount(n, "ray queries that start from the launch ray's last committed hit");
}

std::string queryOffersOpaque(Case& c, ModelOptions& o) {
  const std::string what =
      plantedOn(countStatements(c, Stmt::Kind::RayQuery),
                "ray queries that return opaque triangles as candidates", c,
                "run the any-hit of an opaque triangle (committed where it accepts)");
  if (what.empty()) return "";
  o.faults.rq_opaque_offered = true;
  return what;
}

std::string queryConfirmIgnored(Case& c, ModelOptions& o) {
  const std::string what =
      plantedOn(countStatements(c, Stmt::Kind::Confirm), "confirms that commit nothing", c,
                "commit no non-opaque triangle's accepted hit");
  if (what.empty()) return "";
  o.faults.rq_confirm_ignored = true;
  return what;
}

std::string queryGenerateIgnored(Case& c, ModelOptions& o) {
  const std::string what =
      plantedOn(countStatements(c, Stmt::Kind::Generate), "generates that commit nothing", c,
                countStatements(c, Stmt::Kind::Report)
                    ? "commit no accepted reportIntersectionEXT (which returns true)"
                    : "");
  if (what.empty()) return "";
  o.faults.rq_generate_ignored = true;
  return what;
}

std::string queryCandidateShrinksInterval(Case& c, ModelOptions& o) {
  const size_t n = countStatements(c, Stmt::Kind::RayQuery);
  if (!n) return "";
  o.faults.rq_candidate_shrinks_interval = true;
  return describeCount(n, "ray queries whose interval shrinks to each candidate they return");
}

// Ray flags come from the case's rays as well: every query may terminate on
// its first hit. An inlined trace's candidates come far to near (a legal
// order), so that what terminates is not the closest: near to far, the
// farther ones lie beyond it and the traversal it did not end finds nothing.
std::string queryTerminateIgnored(Case& c, ModelOptions& o) {
  const std::string what = plantedOn(
      countStatements(c, Stmt::Kind::RayQuery),
      "ray queries that neither terminate_query nor TerminateOnFirstHit end", c,
      "neither an any-hit's terminate nor TerminateOnFirstHit ends (candidates far to near)");
  if (what.empty()) return "";
  o.faults.rq_terminate_ignored = true;
  if (inlinedTraces(c)) o.faults.order = CandidateOrder::ReverseDistance;
  return what;
}

std::string queryCommittedReadsCandidate(Case& c, ModelOptions& o) {
  size_t reads = 0;
  auto visit = [&](const Program& p) {
    walkExpressions(p, [&](const Expr& e) {
      reads += e.kind == Expr::Kind::Builtin && isCommittedGetter(e.builtin) &&
               e.builtin != kBiQCommittedType;
    });
  };
  forEachProgram(c.pipeline, [&](Program& p, Stage) { visit(p); });
  if (!reads) return "";
  o.faults.rq_committed_reads_candidate = true;
  return describeCount(reads, "committed getters that read the current candidate");
}

std::string queryCustomIndexIsInstanceId(Case& c, ModelOptions& o) {
  const size_t reads = countGetters(c, {kBiQCommittedCustomIndex, kBiQCandCustomIndex});
  const std::string what = plantedOn(
      reads, "ray query custom index reads that give the instance id", c,
      countGetters(c, {kBiCustomIndex}) ? "give the instance id for gl_InstanceCustomIndexEXT"
                                        : "");
  if (what.empty()) return "";
  o.faults.rq_custom_index_is_instance_id = true;
  return what;
}

// R-RQ-COMMIT: the closest commit stays, because a commit shrinks the
// interval later candidates are tested in (R-RQ-CANDIDATES: as a trace's).
std::string queryCommitKeepsInterval(Case& c, ModelOptions& o) {
  const size_t n =
      countStatements(c, Stmt::Kind::Confirm) + countStatements(c, Stmt::Kind::Generate);
  const std::string what =
      plantedOn(n,
                "commits that leave the query's interval at its tmax (triangles beyond "
                "the committed t still offered, a generate beyond it accepted)",
                c, "commit the last accepted triangle, not the closest (tmax never shrinks)");
  if (what.empty()) return "";
  o.faults.rq_commit_keeps_interval = true;
  return what;
}

// Candidates far to near (a legal order), so that the second confirm a
// block makes is of a nearer candidate, which R-RQ-COMMIT commits.
std::string queryConfirmOnlyFirst(Case& c, ModelOptions& o) {
  const std::string what = plantedOn(countStatements(c, Stmt::Kind::Confirm),
                                     "confirms that commit nothing once something is committed "
                                     "(candidates far to near)",
                                     c,
                                     "commit no accepted triangle once something is committed "
                                     "(candidates far to near)");
  if (what.empty()) return "";
  o.faults.rq_confirm_only_first = true;
  o.faults.order = CandidateOrder::ReverseDistance;
  return what;
}

// The blocks are chosen by rayQueryGetIntersectionTypeEXT (glsl/emit_query.cpp).
std::string queryCandidateTypeSwapped(Case& c, ModelOptions& o) {
  const std::string what =
      plantedOn(countStatements(c, Stmt::Kind::RayQuery),
                "ray queries whose candidates read the other type (and run the other block)", c,
                "run no intersection for a box and no any-hit for a non-opaque triangle, and "
                "commit neither");
  if (what.empty()) return "";
  o.faults.rq_candidate_type_swapped = true;
  return what;
}

std::string queryFrontFaceInverted(Case& c, ModelOptions& o) {
  const size_t reads = countGetters(c, {kBiQCommittedFrontFace, kBiQCandFrontFace});
  const std::string what = plantedOn(
      reads, "ray query front face reads that give a triangle's other face", c,
      countGetters(c, {kBiHitKind}) ? "give a triangle's other face as its hit_kind" : "");
  if (what.empty()) return "";
  o.faults.rq_front_face_inverted = true;
  return what;
}

// What a block reads of its candidate's object-space ray: the getters, and
// the crossing of its box (sphere_* in an aabb block: program/ops.h).
std::string queryObjectRayWorld(Case& c, ModelOptions& o) {
  size_t n = countGetters(c, {kBiQCandObjectOrigin, kBiQCandObjectDirection});
  forEachProgram(c.pipeline, [&](const Program& p, Stage stage) {
    if (stage == Stage::Intersection) return;  // its own box's, not a query's
    walkExpressions(p, [&](const Expr& e) { n += e.kind == Expr::Kind::Op && isSphereOp(e.op); });
  });
  if (!n) return "";
  o.faults.rq_object_ray_world = true;
  return describeCount(n,
                       "reads of a ray query candidate's object-space ray (getters, sphere_*) "
                       "that give the world-space ray");
}

std::string queryBreakLosesCommit(Case& c, ModelOptions& o) {
  const size_t n = loopLeavingBlocks(c);
  if (!n) return "";
  o.faults.rq_break_loses_commit = true;
  return describeCount(n, "candidate blocks whose break out of the loop loses what is committed");
}

std::string queryFunctionGetsCopy(Case& c, ModelOptions& o) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](const Program& p, Stage) {
    walkStatements(p, [&](const Stmt& s) { n += s.kind == Stmt::Kind::Invoke && s.query_param; });
  });
  if (!n) return "";
  o.faults.rq_function_gets_copy = true;
  return describeCount(n, "calls of functions taking a ray query that get a copy of it");
}

std::string queryRestartKeepsCommitted(Case& c, ModelOptions& o) {
  const size_t n = countStatements(c, Stmt::Kind::RestartQuery);
  if (!n) return "";
  o.faults.rq_restart_keeps_committed = true;
  return describeCount(n, "restarts of a query in traversal that keep what is committed");
}

std::string queryStepWrongQuery(Case& c, ModelOptions& o) {
  const size_t n = countStatements(c, Stmt::Kind::RayQueries);
  if (!n) return "";
  o.faults.rq_step_wrong_query = true;
  return describeCount(n, "arrays of ray queries stepped one element off");
}

}  // namespace rayspec
