"""The file readers: measured rheometer files, micro run files against
`micro summary`, and sweep tables."""

import numpy as np
import pytest

import softglass
from conftest import SOURCE, run_tool


def test_castor_oil_flow_sweep_in_si_units(castor_oil):
    curves = softglass.read_measured_curves(castor_oil)
    assert len(curves) == 1
    c = curves[0]
    assert len(c) == 71
    assert np.all(np.diff(c.shear_rate) > 0), "sorted by rate"
    # The export's first row: 260.59 Pa at 1000 1/s, torque 16042.9 uN.m.
    assert c.shear_rate[-1] == pytest.approx(1000.0)
    assert c.stress[-1] == pytest.approx(260.59)
    full = softglass.read_rheometer_curves(castor_oil)[0]
    assert full["kind"] == "flow_curve"
    assert full["torque"][-1] == pytest.approx(16042.9e-6)
    assert softglass.measured_curve(castor_oil).label == c.label


def test_units_are_converted_and_missing_units_refused(tmp_path):
    data = tmp_path / "long.csv"
    data.write_text("sample,shear rate [1/min],stress [kPa]\n"
                    + "".join(f"s1,{60 * r},{s}\n" for r, s in [(1, 0.1), (2, 0.2), (3, 0.3), (4, 0.4)]))
    c = softglass.measured_curve(data, "s1")
    np.testing.assert_allclose(c.shear_rate, [1, 2, 3, 4])
    np.testing.assert_allclose(c.stress, [100, 200, 300, 400])
    bare = tmp_path / "bare.csv"
    bare.write_text("shear rate,stress\n" + "".join(f"{r},{r}\n" for r in range(1, 6)))
    with pytest.raises(softglass.InputError, match="unit"):
        softglass.read_measured_curves(bare)
    curve = softglass.read_measured_curves(bare, rate_unit="1/s", stress_unit="Pa")[0]
    np.testing.assert_allclose(curve.stress, [1, 2, 3, 4, 5])
    with pytest.raises(softglass.InputError, match="s2"):
        softglass.measured_curve(data, "s2")


TINY_RUN = """subsection particles
  set number          = 200
  set volume fraction = 0.7
  set seed            = {seed}
end
subsection neighbours
  set skin = 0.3
end
subsection shear
  set gamma dot tilde = 1e-4
  set min strain = 0.3
  set max strain = 0.3
  set min stationary strain = 0.2
end
"""


@pytest.fixture(scope="module")
def two_runs(tmp_path_factory):
    """Two short runs of one state point from two packings (seconds each)."""
    folder = tmp_path_factory.mktemp("runs")
    runs = []
    for seed in (1, 2):
        prm = folder / f"run{seed}.prm"
        prm.write_text(TINY_RUN.format(seed=seed))
        run_tool("micro", "run", "--quiet", "-o", folder / f"run{seed}.h5", prm)
        runs.append(folder / f"run{seed}.h5")
    return runs


def test_run_file_and_packing_average_equal_micro_summary(two_runs, tmp_path):
    run = softglass.read_run(two_runs[0])
    assert run["phi"] == pytest.approx(0.7, rel=1e-3) and run["gamma_tilde"] == 1e-4
    assert run["particles"] == 200
    summary_csv = tmp_path / "summary.csv"
    run_tool("micro", "summary", *two_runs, "--csv", summary_csv)
    cli = softglass.read_table(summary_csv)["columns"]
    average = softglass.summarize_runs(two_runs)
    assert average["runs"] == 2
    names, means, errors = cli["observable"], cli["mean"], cli["standard_error"]
    assert "sigma" in names
    for name, mean, error in zip(names, means, errors):
        # written with 11 and 5 significant digits ({:.10e}, {:.4e})
        assert average["observables"][name]["mean"] == pytest.approx(mean, rel=1e-9, abs=1e-300)
        assert average["observables"][name]["standard_error"] == pytest.approx(error, rel=1e-4)
    # The average of two runs is the mean of their means.
    second = softglass.read_run(two_runs[1])
    assert average["observables"]["sigma"]["mean"] == pytest.approx(
        0.5 * (run["observables"]["sigma"]["mean"] + second["observables"]["sigma"]["mean"]),
        rel=1e-12)


def test_time_series_holds_the_sampled_stress(two_runs):
    series = softglass.read_time_series(two_runs[0])
    strain = series["strain"]
    assert len(strain) > 10 and np.all(np.diff(strain) > 0)
    total = series["sigma_elastic"] + series["sigma_viscous"]
    np.testing.assert_allclose(series["sigma"], total, rtol=1e-12, atol=1e-18)


def test_sweep_tables(tmp_path):
    table = softglass.read_flow_curve_table(SOURCE / "cases" / "bridge_synthetic_sweep.csv")
    raw = softglass.read_table(SOURCE / "cases" / "bridge_synthetic_sweep.csv")
    np.testing.assert_array_equal(table["sigma"], raw["columns"]["sigma"])
    np.testing.assert_array_equal(table["phi"], raw["columns"]["phi"])
    assert raw["units"]["sigma"] == "E*"
    assert table["packings"].dtype.kind == "i"
    runs = softglass.read_packing_runs(SOURCE / "cases" / "bridge_synthetic_sweep_packings.csv")
    assert len(runs["seed"]) > len(table["phi"])
    # A table in pascals is refused: the bridge reads reduced units only.
    pascals = tmp_path / "pascals.csv"
    pascals.write_text(
        (SOURCE / "cases" / "bridge_synthetic_sweep.csv").read_text().replace("[E*]", "[Pa]"))
    with pytest.raises(softglass.InputError, match="Pa"):
        softglass.read_flow_curve_table(pascals)
