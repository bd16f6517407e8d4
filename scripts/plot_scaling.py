#!/usr/bin/env python3
"""Time per particle-step against N (docs/validation.md, "Scaling with N"):
softglass and LAMMPS from one run of bench/lammps_scaling.sh (the two codes in
turn at each N, one core), and softglass alone up to 1e6 from runs of
bench/scaling.sh (one thread and two; the median of the runs given, with
their range as error bars).

    /usr/bin/python3 scripts/plot_scaling.py OUT.png LAMMPS_SCALING_OUT [SCALING_OUT ...]

reads the benches' printed tables (their standard output, saved to files)."""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def read_peer(path):
    """N, softglass ns, LAMMPS ns per particle-step from lammps_scaling.sh."""
    rows = [line.split() for line in open(path)]
    rows = [r for r in rows if len(r) == 4 and r[0].isdigit()]
    if not rows:
        sys.exit(f"{path}: no table of bench/lammps_scaling.sh in it")
    return np.array([[float(x) for x in r[:3]] for r in rows])


def read_scaling(paths):
    """{threads: {N: [ns per particle-step, one per run]}} from scaling.sh."""
    runs = {}
    for path in paths:
        rows = [line.split() for line in open(path)]
        rows = [r for r in rows if len(r) == 6 and r[0].isdigit()]
        if not rows:
            sys.exit(f"{path}: no table of bench/scaling.sh in it")
        for n, threads, ns, *_ in rows:
            runs.setdefault(int(threads), {}).setdefault(int(n), []).append(float(ns))
    return runs


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out, peer_path, scaling_paths = sys.argv[1], sys.argv[2], sys.argv[3:]
    peer = read_peer(peer_path)
    fig, ax = plt.subplots(figsize=(6.2, 4.6))
    ax.loglog(peer[:, 0], peer[:, 2], "s-", color="tab:red", label="LAMMPS (lammps_scaling.sh)")
    ax.loglog(peer[:, 0], peer[:, 1], "o-", color="tab:blue", label="softglass (lammps_scaling.sh)")
    for (threads, by_n), style in zip(sorted(read_scaling(scaling_paths).items()), ("^--", "v:")):
        n = np.array(sorted(by_n))
        median = np.array([np.median(by_n[k]) for k in n])
        spread = np.array([[median[i] - min(by_n[k]), max(by_n[k]) - median[i]] for i, k in enumerate(n)]).T
        ax.errorbar(n, median, yerr=spread, fmt=style, color="tab:blue", alpha=0.6, capsize=3,
                    label=f"softglass, {threads} thread{'s' if threads > 1 else ''} (scaling.sh, "
                          f"median of {len(by_n[n[0]])})")
    ax.set_xlabel("particles N")
    ax.set_ylabel("ns per particle-step")
    ax.set_title("Hertz, phi = 0.80, no drag")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


if __name__ == "__main__":
    main()
