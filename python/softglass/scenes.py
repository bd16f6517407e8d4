"""Macro scenes solved in this process (`macro run` without its files)."""

import os
import tempfile

from ._softglass import _run_scene


class SceneResults:
    """The rows of a scene's results.csv as arrays.

    results["torque"] is the column `torque` (SI units, units["torque"]);
    `drive` names the operating-point column (rotation_rate or
    pressure_gradient). description and model are the lines results.csv
    opens with; source the material's prediction mode; extrapolation a note
    when a tabulated law was extrapolated; instrument the rheometer's
    conversions (strain_constant, stress_constant) or None.
    """

    def __init__(self, solved):
        self.columns = solved["columns"]
        self.units = solved["units"]
        self.drive = solved["drive"]
        self.description = solved["description"]
        self.model = solved["model"]
        self.source = solved["source"]
        self.extrapolation = solved["extrapolation"]
        self.instrument = solved["instrument"]

    def __getitem__(self, name):
        return self.columns[name]

    def __contains__(self, name):
        return name in self.columns

    def __repr__(self):
        rows = len(self.columns[self.drive])
        return f"SceneResults({rows} operating points, columns {list(self.columns)})"


def run_scene(scene_file, material=None, preset="", points=None, quiet=True):
    """Solves `scene_file` at its operating points, as `macro run` does.

    material: None (the scene's own), the path of a material fragment, or a
    material of Law.material / Law.tabulated_material (written to a temporary
    fragment). preset: overrides the file's solver preset (fast, standard,
    accurate). points: operating points [rad/s or Pa/m] instead of the
    file's sweep. quiet: no progress display. Returns SceneResults.
    """
    if material is None or isinstance(material, (str, os.PathLike)):
        return SceneResults(_run_scene(scene_file, material or "", preset, points, quiet))
    with tempfile.TemporaryDirectory(prefix="softglass-material-") as folder:
        fragment = os.path.join(folder, "material.prm")
        material.save(fragment)
        return SceneResults(_run_scene(scene_file, fragment, preset, points, quiet))
