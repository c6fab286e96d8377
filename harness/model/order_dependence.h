// Whether a trace's candidate programs may depend on the order candidates
// arrive in (R-ORDER-UNSPEC): found from the programs themselves, once per
// pipeline and per ray_query statement, so that the exact tier tries other
// orders there (model_exact_tier.cpp) and nowhere else. A program may
// depend on the order where it
//   - ends traversal (terminate, terminate_query) or restarts it
//     (restart_query);
//   - reads what earlier candidates committed (a query's committed.*
//     getters; ray_tmax in an intersection program, the committed t);
//   - reports a t that is not its box's own (ray_tmin, a constant: two
//     boxes' reports tie, R-TIE);
//   - reads a local (a query's frame's, declared outside its blocks), a
//     payload word or a record field that a candidate program writes;
//   - writes one of those with anything but one and the same constant (the
//     last candidate's write stays);
//   - or its ray_query says so (order_dependent: true).
// Counters are left out: those candidate programs bump are informational
// (compare/counter_modes.h). An order-dependent program still gives one
// answer where every order leaves the same behind: the exact tier decides.
#pragma once

#include <string>

#include "model/model_program.h"

namespace rayspec {

struct OrderDependence {
  bool yes = false;
  std::string why;               // e.g. "reads committed.type"
  const CStmt* where = nullptr;  // the statement that makes it so (null: the block as a whole)
  // Only reports at a t not the box's own: every order gives one of the tied
  // reports' answers (past the bound a tie, not a case error).
  bool ties_only = false;
};

// A ray_query statement's candidate blocks (its then_).
OrderDependence queryOrderDependence(const CStmt& query);
// A ray_queries statement (its queries in then_, stepped in turn): whether
// one query's candidate blocks write a local of the frame, the payload or a
// record field that another query's blocks read or write, so that the
// interleaving of their candidates (unspecified) may decide. Counters are
// left out: their atomic adds commute.
OrderDependence steppedQueriesShare(const CStmt& stepped);
// A pipeline's any-hit and intersection programs.
OrderDependence pipelineOrderDependence(const CPipeline& p);
// "file:line field" of a statement (its case source), for a diagnosis.
std::string statementPlace(const CStmt* s);

}  // namespace rayspec
