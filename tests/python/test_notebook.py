"""docs/examples/measured_to_prediction.ipynb, executed as a reader would
run it (nbclient, Debian's python3 kernel): from the measured castor-oil
flow sweep to the prediction overlay."""

import re

import nbclient
import nbformat
import pytest

from conftest import SOURCE

NOTEBOOK = SOURCE / "docs" / "examples" / "measured_to_prediction.ipynb"


def test_measured_to_prediction_notebook(castor_oil, tmp_path, monkeypatch):
    monkeypatch.setenv("SOFTGLASS_EXAMPLE_OUTPUT", str(tmp_path))
    # The kernel's debugger warns about frozen modules on every start: noise here.
    monkeypatch.setenv("PYDEVD_DISABLE_FILE_VALIDATION", "1")
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    nbclient.NotebookClient(notebook, timeout=120, kernel_name="python3",
                            resources={"metadata": {"path": str(NOTEBOOK.parent)}}).execute()
    printed = "".join(output.get("text", "") for cell in notebook.cells
                      if cell.cell_type == "code" for output in cell.outputs)
    assert "71 points" in printed
    plateau = float(re.search(r"G' plateau = ([0-9.]+) Pa", printed).group(1))
    assert plateau == pytest.approx(143, abs=2)  # the data's README: about 143 Pa
    medians = {mode: float(error) for mode, error in
               re.findall(r"^\((\w)\).*median \|predicted/measured - 1\| = ([0-9.]+) %",
                          printed, re.M)}
    assert sorted(medians) == ["b", "c", "d"]
    # Mode (c) takes the stress scale from the data and fits best; (b) and (d)
    # stay within the median error docs/tutorial.md states for this sweep
    # (38 % in (b)) and docs/validation.md's macro comparison (40 %).
    assert medians["c"] < min(medians["b"], medians["d"])
    assert max(medians.values()) < 45
    png = tmp_path / "measured_to_prediction.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
