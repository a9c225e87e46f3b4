// Doubles as text for the validator's messages, without printf (the WebAssembly module would
// carry its 15 KB, long-double arithmetic included, for these three numbers).
#pragma once

#include <string>

namespace pear::detail {

/// `value` as printf's "%.17g" writes it (enough digits to read the same double back): its
/// exact decimal expansion rounded to 17 significant digits, ties to even; fixed notation for
/// decimal exponents -4 to 16, else d.ddde+XX; trailing zeros dropped. "inf", "-inf", and
/// "nan" for every NaN.
std::string format_g17(double value);

}  // namespace pear::detail
