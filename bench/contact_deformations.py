#!/usr/bin/env python3
"""Contact deformations ε = h/R_c in the final configuration of sheared runs.

Usage: contact_deformations.py RUN.h5 [RUN.h5 ...]
Prints, per run file (docs/output.md), the contacts per particle, the mean ε,
the fractions of contacts beyond ε = 0.1 and 0.2 (the Hertz and the first
stiffened branch of seth2011 end there, docs/physics.md, "Elastic force") and the 95th
percentile. Pairs are found by brute force through the Lees–Edwards minimum
image, which is enough for the N ≤ 1000 of the benches.
"""
import sys

import h5py
import numpy as np


def deformations(path):
    with h5py.File(path, "r") as f:
        c = f["shear/configuration"]
        x = c["position"][()]
        radius = c["radius"][()]
        side = float(np.ravel(c["side"][()])[0])
        strain = float(np.ravel(c["strain"][()])[0])
    eps = []
    for i in range(len(radius) - 1):
        d = x[i] - x[i + 1:]
        images = np.round(d[:, 1] / side)  # across the gradient boundary: shift by the strain
        d[:, 0] -= images * strain * side
        d[:, 1] -= images * side
        for k in (0, 2):
            d[:, k] -= np.round(d[:, k] / side) * side
        distance = np.linalg.norm(d, axis=1)
        sum_radii = radius[i] + radius[i + 1:]
        overlap = sum_radii - distance
        touching = overlap > 0
        contact_radius = radius[i] * radius[i + 1:][touching] / sum_radii[touching]
        eps.extend(overlap[touching] / contact_radius)
    return np.array(eps), len(radius)


def main(paths):
    if not paths:
        sys.exit(__doc__)
    print("%-48s %8s %7s %7s %7s %7s" % ("run", "Z", "mean e", ">0.1", ">0.2", "p95"))
    for path in paths:
        eps, n = deformations(path)
        print("%-48s %8.2f %7.3f %7.2f %7.2f %7.3f" % (
            path.split("/")[-1], 2 * len(eps) / n, eps.mean(), (eps > 0.1).mean(),
            (eps > 0.2).mean(), np.percentile(eps, 95)))


if __name__ == "__main__":
    main(sys.argv[1:])
