// deal.II's exception text as the one-line message of an InputError
// (common/errors.h), for every tool that reads parameter files with deal.II's
// ParameterHandler: micro's parameter and sweep files, bridge's law files,
// macro's scene and material files.
#pragma once

#include <string>
#include <string_view>

namespace softglass {

/// The user's part of a deal.II exception's what(): the text after
/// "Additional information:" (all of it when absent), without the stack trace
/// and the closing rule, its whitespace collapsed to single spaces, and the
/// pattern of an unbounded number entry in words a user reads ("a number
/// (without units)").
std::string deal_ii_message(std::string_view what);

}  // namespace softglass
