// deal.II exceptions as the one-line messages of common/errors.h.
#pragma once

#include <string>

namespace dealii {
class ExceptionBase;
}

namespace softglass::macro::io {

/// The exception's own text (what went wrong, the entry, the value), without
/// source locations or backtrace, on one line.
std::string one_line(const dealii::ExceptionBase& error);

}  // namespace softglass::macro::io
