// What the three translation units of the compiled module `_softglass`
// share: the binders each defines, and the conversions to numpy.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

namespace softglass::python {

namespace py = pybind11;

/// Measured curves, micro run files, sweep tables (module.cpp).
void bind_readers(py::module_& m);
/// Laws, predictions and materials (bridge_bindings.cpp).
void bind_bridge(py::module_& m);
/// Macro scenes solved in this process (macro_bindings.cpp).
void bind_macro(py::module_& m);

/// A copy of `values` as a 1-D numpy array.
inline py::array_t<double> to_array(const std::vector<double>& values) {
  return py::array_t<double>(py::ssize_t(values.size()), values.data());
}

}  // namespace softglass::python
