"""Macro scenes solved in the Python process against `macro run` and
against the closed form of the infinite Couette cell."""

import math

import numpy as np
import pytest

import softglass
from conftest import BUNDLED_LAW, SOURCE, run_tool

R1, R2, L = 0.014, 0.0152, 0.042  # the castor-oil DIN cell of cases/couette.prm [m]


def couette_scene(folder, points, material="macro_material_castoroil85.prm", preset="fast"):
    """The infinitely long Couette cell (a 1-D solve: fast)."""
    scene = folder / "couette.prm"
    scene.write_text(f"""set scene = couette
include {SOURCE / 'cases' / material}
subsection couette
  set inner radius = {R1}
  set outer radius = {R2}
  set length       = {L}
  set end effects  = false
end
subsection solver
  set preset = {preset}
end
subsection sweep
  set values = {', '.join(map(str, points))}
end
""")
    return scene


def test_scene_results_equal_macro_run(tmp_path):
    scene = couette_scene(tmp_path, [0.01, 0.3, 10.0])
    run_tool("macro", "run", "--quiet", "-o", tmp_path / "out", scene)
    cli = softglass.read_table(tmp_path / "out" / "results.csv")
    ours = softglass.run_scene(scene)
    assert ours.drive == "rotation_rate"
    assert list(ours.columns) == list(cli["columns"])
    assert ours.units == cli["units"]
    for name, values in cli["columns"].items():
        if name != "wall_time":  # results.csv holds 10 significant digits
            np.testing.assert_allclose(ours[name], values, rtol=1e-9, err_msg=name)
    assert ours.instrument["strain_constant"] > 0


def couette_torque(omega, tau_y, K, n):
    """The torque M [N m] of the infinite Couette cell turning at omega [rad/s]:
    tau(r) = M/(2 pi L r^2), omega = integral of gamma_dot(r)/r over the gap,
    gamma_dot = ((tau - tau_y)/K)^(1/n) where tau > tau_y (a plug elsewhere);
    solved for M by bisection, the integral by Simpson's rule in ln r."""
    s = np.linspace(math.log(R1), math.log(R2), 4001)  # ds = dr/r

    def rotation(M):
        tau = M / (2 * math.pi * L * np.exp(2 * s))
        rate = (np.clip(tau - tau_y, 0, None) / K) ** (1 / n)
        h = s[1] - s[0]
        return h / 3 * (rate[0] + rate[-1] + 4 * rate[1:-1:2].sum() + 2 * rate[2:-1:2].sum())

    low, high = 2 * math.pi * L * R1**2 * tau_y, 1.0
    for _ in range(200):
        middle = 0.5 * (low + high)
        low, high = (middle, high) if rotation(middle) < omega else (low, middle)
    return 0.5 * (low + high)


def test_law_material_in_couette_matches_the_closed_form(tmp_path):
    """A Herschel-Bulkley material made from the bundled law, solved in the
    cell; the torque against the closed form, where the gap is partly
    (5e-4 rad/s: below 1.8e-3 rad/s the yield radius lies inside the gap)
    and fully (5 rad/s) yielded."""
    law = softglass.load_law(BUNDLED_LAW)
    material = law.material(phi=0.85, viscosity=0.89e-3, modulus=3857.0)
    # The scene reads the material fragment, which holds 6 significant digits.
    tau_y, K, n = (float(f"{float(v):.6g}") for v in
                   (material.yield_stress, material.consistency, material.flow_index))
    points = [5e-4, 5.0]
    results = softglass.run_scene(couette_scene(tmp_path, points, preset="standard"), material)
    assert results.source.startswith("(a)")
    for k, omega in enumerate(points):
        exact = couette_torque(omega, tau_y, K, n)
        # The scene's own closed form (macro/exact/couette.h) and this one agree
        # to the quadratures' accuracy (this one's: 1e-9 on doubling the
        # intervals); the finite elements to their error estimate.
        assert results["torque_ideal_geometry"][k] == pytest.approx(exact, rel=1e-8)
        estimate = abs(results["torque_discretisation_error"][k]) + abs(
            results["torque_regularisation_error"][k])
        # The standard preset regularises at 1e-4 of the rate scale (docs/macro.md).
        assert abs(results["torque"][k] - exact) <= max(3 * estimate, 1e-4 * exact), omega
    # Partly yielded at the lower rate, fully at the higher.
    assert 0 < results["yielded_fraction"][0] < 1 and results["yielded_fraction"][1] == 1


def test_points_replace_the_sweep_and_bad_scenes_are_value_errors(tmp_path):
    scene = couette_scene(tmp_path, [1.0, 2.0])
    assert list(softglass.run_scene(scene, points=[3.0])["rotation_rate"]) == [3.0]
    with pytest.raises(softglass.InputError, match="points"):
        softglass.run_scene(scene, points=[-1.0])
    bad = tmp_path / "bad.prm"
    bad.write_text(scene.read_text().replace("set length", "set colour = red\n  set length"))
    with pytest.raises(softglass.InputError, match="colour"):
        softglass.run_scene(bad)
