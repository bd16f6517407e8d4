#!/usr/bin/env python3
"""Wall slip from `micro slip` (docs/physics.md, "Wall slip"): the slip speed
U = V_s eta_s/(E* R) against the wall stress sigma_w/E* of every run (filled:
the gap slides as a plug, bulk rate < 1 % of the apparent rate; open: the
bulk flows too), one colour per volume fraction, with the plug's slip law of
the packings at rest drawn through them (plug_slip.csv, the packings' mean)
and the velocity profiles across the gap of the first packing's runs.

    /usr/bin/python3 scripts/plot_slip.py OUT_PREFIX SLIP_DIR [SLIP_DIR ...]

reads SLIP_DIR/slip.csv, SLIP_DIR/plug_slip.csv and SLIP_DIR/runs/*.h5;
writes OUT_PREFIX_law.png and OUT_PREFIX_profiles.png."""
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
except ImportError:  # the profiles need the run files
    h5py = None


def law(dirs, prefix):
    fig, ax = plt.subplots(figsize=(6.2, 4.6))
    colours = plt.cm.viridis(np.linspace(0, 0.8, len(dirs)))
    for d, colour in zip(dirs, colours):
        t, plug = read_table(os.path.join(d, "slip.csv")), read_table(os.path.join(d, "plug_slip.csv"))
        phi = t["phi"][0]
        speed = t["slip_velocity"] * t["gamma_app"]
        sliding = t["bulk_rate"] < 0.01
        ax.loglog(t["wall_stress"][sliding], speed[sliding], "o", color=colour,
                  label=f"runs, phi = {phi:.2f} (plug)")
        ax.loglog(t["wall_stress"][~sliding], speed[~sliding], "o", mfc="none", color=colour,
                  label=f"runs, phi = {phi:.2f} (bulk flows)")
        u = np.unique(plug["slip_speed"])
        sigma = np.array([plug["wall_stress"][plug["slip_speed"] == x].mean() for x in u])
        ax.loglog(sigma, u, "-", color=colour, lw=1, label=f"plug law, phi = {phi:.2f}")
    # Slopes 2 (the EHD film at a fixed load) and 1 (films of rest thickness),
    # offset above the last plug law's ends.
    s = np.array([sigma[-1] / 300, sigma[-1]])
    ax.loglog(s, 5 * u[-1] * (s / s[1]) ** 2, "k:", lw=1, label="slope 2 (EHD film, fixed load)")
    s = np.array([sigma[0], sigma[0] * 1e4])
    ax.loglog(s, 5 * u[0] * (s / s[0]), "k--", lw=0.8, label="slope 1 (Navier)")
    ax.set_xlabel("wall stress sigma_w / E*")
    ax.set_ylabel("slip speed V_s eta_s / (E* R)")
    ax.legend(fontsize=7)
    ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    fig.savefig(prefix + "_law.png", dpi=120)


def profiles(dirs, prefix):
    if h5py is None:
        return
    fig, axes = plt.subplots(1, len(dirs), figsize=(5.2 * len(dirs), 4.2), squeeze=False)
    for d, ax in zip(dirs, axes[0]):
        files = sorted(glob.glob(os.path.join(d, "runs", "*_s*.h5")))
        seed = min(f.rsplit("_s", 1)[1] for f in files)
        for f in [f for f in files if f.endswith("_s" + seed)]:
            with h5py.File(f, "r") as h:
                y, u = h["profile/y_over_gap"][:], h["profile/u_x"][:]
                gap = h["gap"][()]
            rate = float(os.path.basename(f).split("_g")[1].split("_s")[0])
            # u_x relative to the gap's centre, in units of the walls' speed cH/2.
            ax.plot((u - np.interp(0.5, y, u)) / (0.5 * gap), y, ".-", label=f"gamma_app = {rate:g}")
        ax.plot([-1, 1], [0, 1], "k:", lw=1, label="no slip (affine)")
        ax.set_xlabel("u_x / (gamma_app H / 2)")
        ax.set_ylabel("y / H")
        ax.set_title(os.path.basename(os.path.normpath(d)))
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(prefix + "_profiles.png", dpi=120)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    law(sys.argv[2:], sys.argv[1])
    profiles(sys.argv[2:], sys.argv[1])
