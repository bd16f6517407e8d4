#!/usr/bin/python3
"""Stress histories of `micro run` result files: sigma, N1, N2 (units of E*)
and the layering order parameter S_y against strain, one colour per file.

    scripts/plot_timeseries.py OUT.png RUN1.h5 [RUN2.h5 ...]

Needs Debian's python3-h5py and python3-matplotlib (use /usr/bin/python3).
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(out, files):
    fig, axes = plt.subplots(4, 1, figsize=(7, 9), sharex=True)
    for name in files:
        with h5py.File(name, "r") as f:
            ts = f["shear/timeseries"]
            strain = ts["strain"][:]
            s = ts["stress_elastic"][:] + ts["stress_viscous"][:]
            label = f"{name.split('/')[-1]}"
            axes[0].plot(strain, s[:, 1, 0], lw=0.6, label=label)
            axes[1].plot(strain, s[:, 0, 0] - s[:, 1, 1], lw=0.6)
            axes[2].plot(strain, s[:, 1, 1] - s[:, 2, 2], lw=0.6)
            if "layering" in ts:
                axes[3].plot(strain, ts["layering"][:], lw=0.6)
            gamma = f["shear/gamma_tilde"][()]
    for ax, ylabel in zip(axes, [r"$\sigma/E^*$", r"$N_1/E^*$", r"$N_2/E^*$", r"layering $S_y$"]):
        ax.set_ylabel(ylabel)
    axes[3].axhline(50, color="k", ls=":", lw=0.8)  # kLayeredThreshold (micro/analysis/layering.h)
    axes[3].set_yscale("log")
    axes[3].set_xlabel("strain")
    axes[0].set_title(rf"$\tilde\gamma$ = {gamma:.0e}")
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
