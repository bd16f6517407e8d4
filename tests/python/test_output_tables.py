"""Every table the tools write loads as it is with numpy.genfromtxt(names=True,
comments='#') and pandas.read_csv(comment='#'), to the same names and numbers
the tools' own reader (softglass.read_table) finds: the header of bare names
first, the units and the provenance on '#' lines (common/csv_writer.h)."""

import numpy as np
import pandas
import pytest

import softglass
from conftest import BUNDLED_LAW, SOURCE, run_tool
from test_macro import couette_scene

EXPORTS = SOURCE / "tests" / "data" / "instrument_exports"


def tables(folder):
    """Tables of bridge predict, bridge rescale (with a text column) and macro run."""
    run_tool("bridge", "predict", BUNDLED_LAW, "--phi", 0.85, "--viscosity", 0.89e-3,
             "--plateau-modulus", 143, "--rates", "0.01,1,100", "-o", folder / "predicted.csv")
    run_tool("bridge", "rescale", EXPORTS / "trios_text_export.txt", "--viscosity", 0.89e-3,
             "--yield-strain", 0.04, "--modulus", 3857, "-o", folder / "rescaled.csv")
    run_tool("macro", "run", "--quiet", "-o", folder / "couette",
             couette_scene(folder, [0.01, 0.1, 1.0]))
    return [folder / "predicted.csv", folder / "rescaled.csv", folder / "rescaled_curves.csv",
            folder / "couette" / "results.csv"]


def test_numpy_and_pandas_load_every_table_as_written(tmp_path):
    for path in tables(tmp_path):
        own = softglass.read_table(path)
        names = list(own["columns"])
        loaded = np.genfromtxt(path, delimiter=",", names=True, comments="#", dtype=None,
                               encoding="utf-8")
        frame = pandas.read_csv(path, comment="#")
        assert list(frame.columns) == names, path
        assert len(frame) == len(np.atleast_1d(loaded)) > 0, path
        for name, values in own["columns"].items():
            if isinstance(values, list):  # a text column: curve labels
                assert list(frame[name]) == values, (path, name)
                continue
            np.testing.assert_array_equal(frame[name].to_numpy(), values, err_msg=f"{path} {name}")
            # genfromtxt turns names into identifiers ("E*" -> "E"): found by position.
            position = names.index(name)
            np.testing.assert_array_equal(np.atleast_1d(loaded)[loaded.dtype.names[position]],
                                          values, err_msg=f"{path} {name}")
        assert any(unit for unit in own["units"].values()), f"{path}: the units line was read"


def test_a_table_of_an_earlier_version_still_reads(tmp_path):
    # Comments first and units in the header: what the tools wrote before.
    old = tmp_path / "old.csv"
    old.write_text("# provenance\nphi [1],sigma [E*]\n0.8,0.001\n")
    table = softglass.read_table(old)
    assert table["units"] == {"phi": "1", "sigma": "E*"}
    np.testing.assert_array_equal(table["columns"]["sigma"], [0.001])
    with pytest.raises(softglass.InputError, match="units"):
        bad = tmp_path / "bad.csv"
        bad.write_text("phi,sigma\n# units: 1\n0.8,0.001\n")
        softglass.read_table(bad)
