"""One flow curve of a measured file, chosen by its label."""

from ._softglass import InputError, read_measured_curves


def measured_curve(file, label=None, rate_unit="", stress_unit=""):
    """The curve `label` of a measured rheometer file, or its only curve.

    Raises InputError naming the labels when the file holds several curves
    and none is named, or none has that label (as `bridge predict --curve`).
    """
    curves = read_measured_curves(file, rate_unit, stress_unit)
    if label is None:
        if len(curves) != 1:
            raise InputError(f"{file} holds {len(curves)} curves: name one with label=")
        return curves[0]
    for curve in curves:
        if curve.label == label:
            return curve
    labels = ", ".join(c.label for c in curves)
    raise InputError(f"{file} has no curve '{label}'; it has: {labels}")
