"""Laws, predictions and materials from Python against the `bridge` command
line given the same inputs: the module calls the same library functions, so
the numbers must agree to the digits the command prints (10 significant
digits for values, 4 for bands)."""

import numpy as np
import pytest

import softglass
from conftest import BUNDLED_LAW, run_tool

PHI, VISCOSITY = 0.85, 0.89e-3
# 1000 1/s lies above the simulated window (gamma~ <= 1e-4 at E* = 3857 Pa
# reaches 433 1/s): one extrapolated, flagged point.
RATES = [0.01, 0.1, 1.0, 10.0, 100.0, 1000.0]

MODES = {
    "a": dict(modulus=3857.0),
    "b": dict(plateau_modulus=143.0),
    "c": dict(yield_stress=15.4, plateau_modulus=143.0),
}


def cli_options(mode):
    return [f"--{name.replace('_', '-')}={value}" for name, value in mode.items()]


def cli_prediction(tmp_path, options, form="tabulated"):
    out = tmp_path / f"prediction_{len(list(tmp_path.iterdir()))}.csv"
    run_tool("bridge", "predict", BUNDLED_LAW, "--phi", PHI, "--viscosity", VISCOSITY,
             "--rates", ",".join(map(str, RATES)), "--law-form", form, "-o", out, *options)
    return softglass.read_table(out)["columns"]


def assert_same_prediction(p, cli):
    np.testing.assert_allclose(p.rate, cli["shear_rate"], rtol=1e-12)
    # Values printed with 10 significant digits, bands with 4.
    for ours, theirs in [("sigma", "shear_stress"), ("N1", "N1"), ("N2", "N2")]:
        np.testing.assert_allclose(getattr(p, ours), cli[theirs], rtol=1e-9, err_msg=ours)
        np.testing.assert_allclose(getattr(p, ours + "_band"), cli[theirs + "_band"], rtol=1e-3,
                                   err_msg=ours + " band")
    np.testing.assert_array_equal(p.extrapolated, cli["extrapolated"] == 1)
    if "shear_stress_model_error" in cli:
        np.testing.assert_allclose(p.sigma_model_error, cli["shear_stress_model_error"],
                                   rtol=1e-3)
    else:
        assert np.isnan(p.sigma_model_error).all()


@pytest.fixture(scope="module")
def law():
    return softglass.load_law(BUNDLED_LAW)


@pytest.mark.parametrize("form", ["tabulated", "herschel-bulkley"])
@pytest.mark.parametrize("letter", sorted(MODES))
def test_prediction_equals_bridge_predict(law, tmp_path, letter, form):
    p = law.predict(RATES, phi=PHI, viscosity=VISCOSITY, form=form, **MODES[letter])
    assert p.mode.startswith(f"({letter})")
    assert_same_prediction(p, cli_prediction(tmp_path, cli_options(MODES[letter]), form))
    if letter == "a":  # the window is 0.0043 ... 433 1/s (gamma~ E*/eta_s)
        assert list(p.extrapolated) == [False] * 5 + [True]


def test_fitted_modulus_recovers_the_modulus_of_a_modelled_curve(law, tmp_path):
    """Mode (d) on a curve the model made with E* = 3857 Pa finds that E*,
    and predicts what the command line predicts from the same file."""
    made = law.predict(RATES[:5], phi=PHI, viscosity=VISCOSITY, modulus=3857.0)
    data = tmp_path / "modelled.csv"
    data.write_text("shear rate [1/s],stress [Pa]\n"
                    + "".join(f"{r:.10g},{s:.10g}\n" for r, s in zip(made.rate, made.sigma)))
    curve = softglass.measured_curve(data)
    p = law.predict(RATES, phi=PHI, viscosity=VISCOSITY, fit_to=curve)
    assert p.mode.startswith("(d)")
    # Exact model data: only the 10 written digits and the fit's tolerance remain.
    assert p.modulus.value == pytest.approx(3857.0, rel=1e-6)
    assert_same_prediction(p, cli_prediction(tmp_path, [f"--fit-to={data}"]))


def test_emulsion_modulus_is_9_92_tension_over_radius(law):
    by_droplets = law.predict(RATES, phi=PHI, viscosity=VISCOSITY, interfacial_tension=0.01,
                              radius=5e-6)
    given = law.predict(RATES, phi=PHI, viscosity=VISCOSITY, modulus=9.92 * 0.01 / 5e-6)
    np.testing.assert_allclose(by_droplets.sigma, given.sigma, rtol=1e-14)


def fragment_lines(text):
    """A material fragment's entries: without its comments (the provenance
    differs by date) and without what the command printed before it."""
    lines = [line for line in text.splitlines() if line.strip() and not line.lstrip().startswith("#")]
    first = next(i for i, line in enumerate(lines) if line.startswith("subsection"))
    return lines[first:]


def test_material_yield_stress_from_the_bundled_law(law):
    """tau_y = E* sigma~_y at a simulated phi (docs/bridge.md, bridge material)."""
    m = law.material(phi=PHI, viscosity=VISCOSITY, modulus=3857.0)
    hb = law.herschel_bulkley("sigma")
    at = list(law.phi).index(PHI)
    assert m.yield_stress.value == pytest.approx(3857.0 * hb["yield"][at], rel=1e-12)
    # K = E* k~ (eta_s/E*)^m, n = m at the same phi.
    assert m.flow_index.value == pytest.approx(hb["exponent"][at], rel=1e-12)
    assert m.consistency.value == pytest.approx(
        3857.0 * hb["consistency"][at] * (VISCOSITY / 3857.0) ** hb["exponent"][at], rel=1e-10)
    assert m.source.startswith("(a)")


@pytest.mark.parametrize("options", [["--modulus=3857"], ["--plateau-modulus=143"]])
def test_material_fragment_equals_bridge_material(law, options):
    name, value = options[0][2:].split("=")
    m = law.material(phi=0.825, viscosity=VISCOSITY, **{name.replace("-", "_"): float(value)})
    cli = run_tool("bridge", "material", BUNDLED_LAW, "--phi", 0.825, "--viscosity", VISCOSITY,
                   *options)
    assert fragment_lines(m.text()) == fragment_lines(cli)


def test_tabulated_material_equals_bridge_material_tabulated(law):
    m = law.tabulated_material(phi=PHI, viscosity=VISCOSITY, yield_stress=15.4,
                               plateau_modulus=143.0)
    cli = run_tool("bridge", "material", BUNDLED_LAW, "--phi", PHI, "--viscosity", VISCOSITY,
                   "--yield-stress", 15.4, "--plateau-modulus", 143, "--tabulated")
    assert fragment_lines(m.text()) == fragment_lines(cli)
    # Mode (c): the measured yield stress is the material's.
    assert m.yield_stress.value == pytest.approx(15.4, rel=1e-12)
    rows = m.rows
    assert np.all(np.diff(rows["rate"]) > 0) and np.all(np.diff(rows["sigma"]) > 0)


def test_bad_input_is_a_value_error_naming_the_problem(law, tmp_path):
    with pytest.raises(softglass.InputError, match="no E"):
        law.predict(RATES, phi=PHI, viscosity=VISCOSITY)
    with pytest.raises(ValueError, match="phi"):
        law.material(phi=0.95, viscosity=VISCOSITY, modulus=3857.0)
    with pytest.raises(softglass.InputError, match="herschel-bulkley"):
        law.predict(RATES, phi=PHI, viscosity=VISCOSITY, modulus=1.0, form="power")
    with pytest.raises(softglass.InputError, match="missing.prm"):
        softglass.load_law(tmp_path / "missing.prm")
