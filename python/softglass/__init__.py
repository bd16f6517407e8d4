"""softglass in Python: soft glasses from particles to rheometer torques.

The project's C++ libraries in this process (the compiled module _softglass):
laws, predictions and materials of the bridge, macro scenes, and the readers
of measured rheometer files, micro run files and sweep tables. Nothing is
recomputed in Python. docs/python.md is the manual.
"""

from ._softglass import (
    InputError,
    NumericalError,
    OutputExistsError,
    MeasuredCurve,
    MaterialValue,
    Prediction,
    HerschelBulkleyMaterial,
    TabulatedMaterial,
    Law,
    load_law,
    read_measured_curves,
    read_rheometer_curves,
    read_amplitude_sweeps,
    read_table,
    read_flow_curve_table,
    read_packing_runs,
    read_run,
    read_time_series,
    summarize_runs,
)
from .measured import measured_curve
from .scenes import SceneResults, run_scene


def _save(material, path):
    """Writes the material fragment (text()) to `path`, for a scene's `include`."""
    import pathlib

    pathlib.Path(path).write_text(material.text())


HerschelBulkleyMaterial.save = _save
TabulatedMaterial.save = _save

__all__ = [
    "InputError",
    "NumericalError",
    "OutputExistsError",
    "MeasuredCurve",
    "MaterialValue",
    "Prediction",
    "HerschelBulkleyMaterial",
    "TabulatedMaterial",
    "Law",
    "load_law",
    "measured_curve",
    "read_measured_curves",
    "read_rheometer_curves",
    "read_amplitude_sweeps",
    "read_table",
    "read_flow_curve_table",
    "read_packing_runs",
    "read_run",
    "read_time_series",
    "summarize_runs",
    "run_scene",
    "SceneResults",
]
