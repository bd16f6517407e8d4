#!/usr/bin/env python3
"""Amplitude sweeps of `micro oscillate`, drawn as a rheometer's software draws
them: G' and G'' against the strain amplitude on log axes (filled and open
symbols, one colour per volume fraction and frequency, the packings' static
x-y modulus G0_xy dotted: the one the oscillation loads), the relative
intensity I3/I1 of the third harmonic, and the elastic Lissajous figures of the
last cycle, one per amplitude (the first packing's): the stress less its cycle
mean (the packing's residual shear stress), over its largest excursion,
against gamma/gamma0.

    /usr/bin/python3 scripts/plot_oscillation.py OSCILLATION_DIR OUT_PREFIX

reads OSCILLATION_DIR/oscillation.csv and the run files of OSCILLATION_DIR/runs;
writes OUT_PREFIX_moduli.png and OUT_PREFIX_lissajous.png."""
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from plot_flow_curve import read_table

try:
    import h5py
except ImportError:  # the Lissajous figures need the run files
    h5py = None


def moduli(t, prefix):
    series = sorted(set(zip(t["phi"], t["omega_tilde"])))
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(series)))
    fig, (ax, ax3) = plt.subplots(1, 2, figsize=(11, 4.2))
    for (phi, omega), colour in zip(series, colours):
        at = (t["phi"] == phi) & (t["omega_tilde"] == omega)
        order = np.argsort(t["gamma0"][at])
        g0 = t["gamma0"][at][order]
        label = rf"$\phi$ = {phi:.2f}, $\tilde\omega$ = {omega:.3g}"
        ax.errorbar(g0, t["storage"][at][order], yerr=t["storage_se"][at][order], fmt="o-",
                    color=colour, ms=5, capsize=2, label=label + ": G'")
        ax.errorbar(g0, t["loss"][at][order], yerr=t["loss_se"][at][order], fmt="s--",
                    mfc="none", color=colour, ms=5, capsize=2, label="G''")
        static = t["G0_xy"] if "G0_xy" in t else t["G0"]  # tables before G0_xy: the mean
        ax.axhline(static[at][0], color=colour, ls=":", lw=1)
        ax3.plot(g0, t["intensity_3"][at][order], "o-", color=colour, ms=4, label=label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(r"strain amplitude $\gamma_0$")
    ax.set_ylabel(r"$G'/E^*$ (filled), $G''/E^*$ (open); static $G_{0,xy}$ dotted")
    ax.legend(fontsize=7)
    ax3.set_xscale("log")
    ax3.set_yscale("log")
    ax3.set_xlabel(r"strain amplitude $\gamma_0$")
    ax3.set_ylabel(r"$I_3/I_1$")
    fig.tight_layout()
    fig.savefig(prefix + "_moduli.png", dpi=110)


def lissajous(directory, prefix):
    first = {}  # (phi, gamma0) -> the run of the lowest packing seed
    for path in glob.glob(os.path.join(directory, "runs", "*.h5")):
        seed = int(path.rsplit("_seed", 1)[1].split(".")[0])
        with h5py.File(path, "r") as f:
            if "oscillation" not in f or "lissajous" not in f["oscillation"]:
                continue
            g = f["oscillation"]
            # The packings' phi differ in the last digits: the file names' 4 decimals.
            key = (round(float(f["packing/volume_fraction"][()]), 4), float(g["amplitude"][()]))
            if key not in first or seed < first[key][0]:
                first[key] = (seed, g["lissajous/strain"][()], g["lissajous/sigma"][()])
    runs = [(phi, gamma0, strain, sigma) for (phi, gamma0), (_, strain, sigma) in first.items()]
    if not runs:
        return
    phis = sorted(set(r[0] for r in runs))
    fig, axes = plt.subplots(1, len(phis), figsize=(4.2 * len(phis), 4), squeeze=False)
    for ax, phi in zip(axes[0], phis):
        mine = sorted((r for r in runs if r[0] == phi), key=lambda r: r[1])
        colours = plt.cm.plasma(np.linspace(0, 0.85, len(mine)))
        for (_, gamma0, strain, sigma), colour in zip(mine, colours):
            x = (strain - 0.5 * (strain.max() + strain.min())) / gamma0
            excursion = sigma - sigma[:-1].mean()  # the loop's last sample repeats its first
            ax.plot(x, excursion / np.abs(excursion).max(), color=colour, lw=1.2,
                    label=rf"$\gamma_0$ = {gamma0:.3g}")
        ax.set_title(rf"$\phi$ = {phi:.2f}")
        ax.set_xlabel(r"$\gamma/\gamma_0$")
        ax.set_ylabel(r"$(\sigma - \langle\sigma\rangle)/\max|\sigma - \langle\sigma\rangle|$")
        ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(prefix + "_lissajous.png", dpi=110)


def main(directory, prefix):
    moduli(read_table(os.path.join(directory, "oscillation.csv")), prefix)
    if h5py is not None:
        lissajous(directory, prefix)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
