// Exactness claims (issue 55): a record compares Uint fields exactly, so the
// bits of a Float (float_bits) may be taken only of a value every device
// gives bit for bit: one the case itself gave (a literal, a specialization
// constant, shader record data, a trace's or query's own ray parameters as
// passed, bits_float of such bits), picked (x .. w, vec*), or chosen (min,
// max, round) from such values. A Float the device computes (hit_t, a
// triangle's t or barycentrics, object-space rays, arithmetic that may be
// rounded, fused or folded otherwise) is not portable under float_bits: its
// bits depend on the device's float algorithm, and the model cannot
// reproduce them. Locals carry what any assignment gives them (flow-
// insensitive: a local some statement sets to a computed value is computed).
#pragma once

#include <optional>

#include "program/ops.h"

namespace rayspec {

// The first float_bits of a device-computed Float in `p`, as an error at it.
std::optional<ProgramError> checkBitCasts(const Program& p, Stage stage);

}  // namespace rayspec
