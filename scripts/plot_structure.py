#!/usr/bin/python3
"""Structure of sheared runs (the /structure group written by `micro run` and
`micro analyze`): g(r, theta) maps in the flow-gradient plane (like the paper's
Fig. 3a), g_{2,-2}(r) at the runs' shear rates (Fig. 3b), and a table of r_m,
f_m Sigma_m and the elastic shear stress.

    scripts/plot_structure.py OUT_PREFIX RUN1.h5 [RUN2.h5 ...]

writes OUT_PREFIX_map.png, OUT_PREFIX_g2m2.png and prints the table.
Needs Debian's python3-h5py and python3-matplotlib (use /usr/bin/python3).
"""
import sys

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(name):
    with h5py.File(name, "r") as f:
        s = f["structure"]
        return {
            "gamma": f["shear/gamma_tilde"][()],
            "r": s["r"][:],
            "g": s["g"][:],
            "g_error": s["g_error"][:],
            "map_r": s["map_r"][:],
            "map_theta": s["map_theta"][:],
            "map": s["map"][:],
            "slab": s.attrs["slab_half_width"],
            **{k: s[k][:] for k in ("r_m", "f_m", "sigma_m", "fm_sigma_m", "sigma_virial",
                                    "sigma_rebuilt", "sigma_law")},
        }


def main(prefix, files):
    runs = sorted((load(n) for n in files), key=lambda d: d["gamma"])

    fig, axes = plt.subplots(1, len(runs), subplot_kw={"projection": "polar"},
                             figsize=(4.6 * len(runs), 4.4), gridspec_kw={"wspace": 0.45})
    axes = np.atleast_1d(axes)
    vmax = max(d["map"].max() for d in runs)
    for ax, d in zip(axes, runs):
        theta = np.append(d["map_theta"] - 0.5 * (d["map_theta"][1] - d["map_theta"][0]), 2 * np.pi)
        dr = d["map_r"][1] - d["map_r"][0]
        r = np.append(d["map_r"] - 0.5 * dr, d["map_r"][-1] + 0.5 * dr)
        ax.grid(False)
        mesh = ax.pcolormesh(theta, r, d["map"], cmap="jet", vmin=0, vmax=vmax, shading="flat")
        ax.set_title(rf"$\tilde\gamma$ = {d['gamma']:.0e}", pad=12)
        ax.set_rlim(0, r[-1])
        ax.set_xticks(np.radians([0, 45, 90, 135, 180, 225, 270, 315]))
        ax.set_yticklabels([])
        ax.tick_params(axis="x", pad=1, labelsize=9)
    fig.colorbar(mesh, ax=list(axes), shrink=0.8, label=r"$g(r,\theta)$")
    fig.suptitle(rf"flow–gradient plane ($|z| < {runs[0]['slab']}R$), $\theta$ from the flow axis")
    fig.savefig(prefix + "_map.png", dpi=110)

    fig, ax = plt.subplots(figsize=(6, 4))
    for d in runs:
        ax.errorbar(d["r"], d["g"][1], yerr=d["g_error"][1], lw=1, elinewidth=0.5,
                    label=rf"$\tilde\gamma$ = {d['gamma']:.0e}, $r_m$ = {d['r_m'][0]:.3f}")
    ax.axhline(0, color="k", lw=0.5)
    ax.set_xlim(1.2, 3.0)
    ax.set_xlabel(r"$r/R$")
    ax.set_ylabel(r"$g_{2,-2}(r)$")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(prefix + "_g2m2.png", dpi=110)

    print("| gamma~ | r_m [R] | f_m [E* R^2] | Sigma_m [1/R^2] | f_m Sigma_m [E*] | sigma^e virial [E*] "
          "| rebuilt | from g_2,-2 with f(r) |")
    print("|---|---|---|---|---|---|---|---|")
    for d in runs:
        v = lambda k: d[k]  # noqa: E731
        print(f"| {d['gamma']:.0e} | {v('r_m')[0]:.4f} ± {v('r_m')[1]:.4f} | {v('f_m')[0]:.3e} | "
              f"{v('sigma_m')[0]:.3e} | {v('fm_sigma_m')[0]:.3e} ± {v('fm_sigma_m')[1]:.1e} | "
              f"{v('sigma_virial')[0]:.4e} ± {v('sigma_virial')[1]:.1e} | {v('sigma_rebuilt')[0]:.4e} | "
              f"{v('sigma_law')[0]:.4e} |")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
