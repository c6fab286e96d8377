// Faults of shader code (R-LIVE-STATE, R-CONTROL-FLOW): a compiler that loses
// a shader's live values across a call, runs a loop once too often, turns
// ignore / terminate inside a function into a plain return, or ignores the
// specialization constants a stage is created with.
#include "fault/fault_impl.h"
#include "fault/program_edit.h"
#include "program/ops.h"
#include "program/payload_words.h"
#include "program/walk_program.h"

namespace rayspec {
namespace {

bool declaresLocal(const Stmt& s) {
  return s.kind == Stmt::Kind::Let || s.kind == Stmt::Kind::Array || s.kind == Stmt::Kind::Struct ||
         (s.kind == Stmt::Kind::Repeat && !s.local.empty()) ||
         (s.kind == Stmt::Kind::Invoke && !s.params.empty());
}

// Every statement inside a function body (the bodies copied into invokes).
void forEachFunctionStmt(Case& c, const std::function<void(Stmt&)>& visit) {
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    forEachStmt(p, [&](Stmt& s) {
      if (s.kind == Stmt::Kind::Invoke) forEachStmt(s.then_, visit);
    });
  });
}

// Every `from` op renamed `to` (an op of the same argument and result types).
size_t renameOps(Case& c, Op from, Op to) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    editExpressions(p, [&](Expr& e) {
      if (e.kind != Expr::Kind::Op || e.op != from) return;
      setOp(e, to);
      ++n;
    });
  });
  return n;
}

// `e` becomes e + 1 (a Uint expression), written where e was.
void addOne(Expr& e) {
  const SourceLoc loc = e.loc;
  e = opExpr(Op::Add, {std::move(e), uintLiteral(1, loc)}, ValueType::Uint, loc);
}

}  // namespace

// A compiler that emits an inclusive or for an exclusive one.
std::string bitwiseXorAsOr(Case& c, ModelOptions&) {
  return describeCount(renameOps(c, Op::BitXor, Op::BitOr), "bit_xor computed as bit_or");
}

// A compiler that drops a transpose: mat3_mul computed as mat3_tmul.
std::string matrixTransposed(Case& c, ModelOptions&) {
  return describeCount(renameOps(c, Op::Mat3Mul, Op::Mat3TMul),
                       "matrix products computed with the transpose");
}

// A compiler that swaps the operands of cross(): every product's sign flips.
std::string crossOperandsSwapped(Case& c, ModelOptions&) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    editExpressions(p, [&](Expr& e) {
      if (e.kind != Expr::Kind::Op || e.op != Op::Cross || e.args.size() != 2) return;
      std::swap(e.args[0], e.args[1]);
      ++n;
    });
  });
  return describeCount(n, "cross products with their operands swapped");
}

// A compiler that converts where it should reinterpret: floatBitsToUint as
// uint(), uintBitsToFloat as float().
std::string floatBitsConverted(Case& c, ModelOptions&) {
  return describeCount(
      renameOps(c, Op::FloatBits, Op::ToUint) + renameOps(c, Op::BitsFloat, Op::ToFloat),
      "bit casts converted as values");
}

// A compiler that addresses a data array one word too far: every payload,
// child, call and callee word indexed by a value is word (i + 1) % N.
std::string wordIndexOffByOne(Case& c, ModelOptions&) {
  size_t n = 0;
  auto one_past = [&](Expr& index) {
    addOne(index);
    ++n;
  };
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    editExpressions(p, [&](Expr& e) {
      if (e.kind == Expr::Kind::Op && wordArrayOf(e.op) && e.args.size() == 1) one_past(e.args[0]);
    });
    forEachStmt(p, [&](Stmt& s) {
      if (s.kind == Stmt::Kind::Store && wordArrayOfStore(s.local)) one_past(s.index);
    });
  });
  return describeCount(n, "indexed payload and callable data words one word too far");
}

// R-TLAS-ARRAY: a device that reads a dynamically indexed array of top
// levels one element on (a descriptor stride or base misread): the level of
// index i is (i + 1) % the levels.
std::string tlasIndexOffByOne(Case& c, ModelOptions&) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    forEachStmt(p, [&](Stmt& s) {
      if (s.trace.tlas_index.empty()) return;
      addOne(s.trace.tlas_index[0]);
      ++n;
    });
  });
  return describeCount(n, "dynamic top-level indices read one element on");
}

std::string localsLostAcrossCalls(Case& c, ModelOptions& o) {
  bool locals = false;
  size_t calls = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    forEachStmt(p, [&](Stmt& s) {
      locals = locals || declaresLocal(s);
      calls +=
          s.kind == Stmt::Kind::Trace || s.kind == Stmt::Kind::Call || s.kind == Stmt::Kind::Report;
    });
  });
  if (!locals) return "";
  o.faults.locals_lost_across_calls = true;
  return describeCount(calls, "traces, calls and reports after which every local reads zero");
}

// The locals (arrays, lets and struct members) of the case whose type `which` says yes to.
size_t countLocals(Case& c, bool (*which)(ValueType)) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    forEachStmt(p, [&](Stmt& s) {
      if (s.kind == Stmt::Kind::Array) n += which(s.local_type);
      if (s.kind == Stmt::Kind::Struct)  // its members
        for (const auto& [member, type] : s.params) n += which(type);
      if (s.kind == Stmt::Kind::Let)
        for (const auto& [name, value] : s.assigns) n += which(value.type);
    });
  });
  return n;
}

// A device whose spills of narrow and wide registers keep half their bits.
std::string sizedLocalsHalved(Case& c, ModelOptions& o) {
  const size_t sized = countLocals(c, isSized);
  if (!sized) return "";
  o.faults.sized_locals_halved = true;
  return describeCount(sized,
                       "sized scalar and vector locals (int8 .. f64vec4) that keep only their "
                       "upper half of bits after each trace, call and report");
}

// A device that spills a vector's lanes to the wrong slots.
std::string sizedVectorsRotated(Case& c, ModelOptions& o) {
  const size_t vectors = countLocals(c, isSizedVector);
  if (!vectors) return "";
  o.faults.sized_vectors_rotated = true;
  return describeCount(vectors,
                       "sized vector locals (i8vec2 .. f64vec4) whose components come back "
                       "rotated after each trace, call and report");
}

// A device that drops the OpConstantNull a sized array is initialised from.
std::string sizedNullNotZero(Case& c, ModelOptions& o) {
  size_t arrays = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    forEachStmt(p,
                [&](Stmt& s) { arrays += s.kind == Stmt::Kind::Array && isSized(s.local_type); });
  });
  if (!arrays) return "";
  o.faults.sized_null_not_zero = true;
  return describeCount(arrays,
                       "sized arrays (declared = {}, an OpConstantNull) whose elements start "
                       "as one instead of zero");
}

std::string loopTripOffByOne(Case& c, ModelOptions&) {
  size_t n = 0;
  forEachProgram(c.pipeline, [&](Program& p, Stage) {
    forEachStmt(p, [&](Stmt& s) {
      if (s.kind != Stmt::Kind::Repeat) return;
      addOne(s.count);
      ++n;
    });
  });
  return describeCount(n, "repeats run one trip more");
}

std::string functionIgnoreLost(Case& c, ModelOptions&) {
  size_t n = 0;
  forEachFunctionStmt(c, [&](Stmt& s) {
    if (s.kind != Stmt::Kind::Ignore && s.kind != Stmt::Kind::Terminate) return;
    s.kind = Stmt::Kind::Return;
    ++n;
  });
  return describeCount(n, "ignores and terminates inside functions only return");
}

std::string specializationIgnored(Case& c, ModelOptions&) {
  size_t n = 0;
  for (const auto& [shader, values] : c.pipeline.specialize) n += values.size();
  c.pipeline.specialize.clear();
  return describeCount(n, "specialization constants a shader sets keep their defaults");
}

}  // namespace rayspec
