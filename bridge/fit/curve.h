// One flow curve: a quantity against a rate, with the standard error of each value.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

namespace softglass::bridge {

/// Rates x > 0 in increasing order, values y and their standard errors se > 0
/// (the weights of the fits: residuals are (y − model)/se).
/// `error_dof` is the number of degrees of freedom behind the standard errors
/// (infinite: the errors are known), which sets the reference distribution of
/// the goodness-of-fit test (fit/least_squares.h).
struct Curve {
  std::vector<double> x, y, se;
  double error_dof = std::numeric_limits<double>::infinity();
  std::size_t size() const { return x.size(); }
};

}  // namespace softglass::bridge
