#!/usr/bin/env python3
"""Flow curves of a sweep, like the paper's Fig. 2: sigma, N1 and -N2 against
gamma~ for each volume fraction, and the elastic and viscous parts of sigma.
A quasi-static row (gamma~ = 0, the sweep's AQS case) is drawn as a dashed
horizontal line: the gamma~ -> 0 limit the curve should approach.

    /usr/bin/python3 scripts/plot_flow_curve.py SWEEP/flow_curve.csv OUT_PREFIX

writes OUT_PREFIX_stresses.png and OUT_PREFIX_parts.png."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def read_table(path):
    with open(path) as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    names = [h.split(" [")[0] for h in rows[0]]
    data = np.array([[float(v) for v in row] for row in rows[1:]])
    return {name: data[:, k] for k, name in enumerate(names)}


def quasi_static(ax, t, phi, name, sign, colour):
    """The quasi-static value of `name` at phi, if any, as a dashed line (log axes: > 0 only)."""
    for value in sign * t[name][(t["phi"] == phi) & (t["gamma_tilde"] == 0)]:
        if value > 0:
            ax.axhline(value, color=colour, ls="--", lw=1)


def main(table_path, prefix):
    t = read_table(table_path)
    phis = sorted(set(t["phi"]))
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(phis)))

    fig, axes = plt.subplots(1, 3, figsize=(13, 4))
    for phi, colour in zip(phis, colours):
        at = (t["phi"] == phi) & (t["gamma_tilde"] > 0)
        rate = t["gamma_tilde"][at]
        for ax, name, sign in zip(axes, ["sigma", "N1", "N2"], [1, 1, -1]):
            ax.errorbar(rate, sign * t[name][at], yerr=t[name + "_se"][at], fmt="o-", color=colour,
                        ms=4, capsize=2, label=rf"$\phi$ = {phi:.2f}")
            quasi_static(ax, t, phi, name, sign, colour)
    for ax, label in zip(axes, [r"$\sigma/E^*$", r"$N_1/E^*$", r"$-N_2/E^*$"]):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(r"$\tilde\gamma = \dot\gamma\eta_s/E^*$")
        ax.set_ylabel(label)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(prefix + "_stresses.png", dpi=110)

    fig, ax = plt.subplots(figsize=(5.5, 4))
    for phi, colour in zip(phis, colours):
        at = (t["phi"] == phi) & (t["gamma_tilde"] > 0)
        rate = t["gamma_tilde"][at]
        ax.plot(rate, t["sigma_elastic"][at], "o-", color=colour, ms=4, label=rf"$\phi$ = {phi:.2f}")
        ax.plot(rate, t["sigma_viscous"][at], "s--", color=colour, ms=4)
        # The films' part, where friction pair dashpots make up the rest of σ^v.
        if "sigma_film" in t and not np.allclose(t["sigma_film"][at], t["sigma_viscous"][at]):
            ax.plot(rate, t["sigma_film"][at], "^:", color=colour, ms=4)
        quasi_static(ax, t, phi, "sigma_elastic", 1, colour)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(r"$\tilde\gamma$")
    ax.set_ylabel(r"$\sigma^e/E^*$ (circles), $\sigma^v/E^*$ (squares), films' part (triangles)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(prefix + "_parts.png", dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
