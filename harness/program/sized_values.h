// The values of the sized scalars (program/sized_types.h), the same on both
// sides: which values a type holds exactly, and an integer's bits wrapped
// to its type. The type checker holds literals to them; the model computes
// with them.
#pragma once

#include <cstdint>

#include "program/program.h"

namespace rayspec {

// 0, or a normal float16 (11 significant bits, 2^-14 <= |v| <= 65504).
bool exactInFloat16(double v);
// 0, or a normal float32 that equals v.
bool exactInFloat32(double v);
// 0, or a finite normal double.
bool normalOrZero(double v);
// An integer type's value from any 64 bits: the low `bits` bits, extended by
// the type's signedness (two's complement in 64 bits for a signed one).
uint64_t wrapToType(ValueType t, uint64_t bits);

}  // namespace rayspec
