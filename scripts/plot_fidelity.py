#!/usr/bin/python3
"""Figures of the model-fidelity study (docs/fidelity.md), drawn from the tables
bench/model_sensitivity.py writes into its output folder.

    plot_fidelity.py STUDY_DIR [-o DIR] [--variants a,b,...]

Reads STUDY_DIR/summary.csv (the flow-curve variants) and, when present,
STUDY_DIR/static.csv (G0 of relaxed packings). Writes DIR/fidelity_exponent.png
(the Herschel-Bulkley exponent m against phi per variant, the paper's
0.50 +- 0.02 as a band), DIR/fidelity_tradeoff.png (m against the elastic to
viscous stress ratio, per variant and phi, with the paper's targets) and
DIR/fidelity_modulus.png (G0 against compressed emulsions, Mason et al. 1995,
per contact law). DIR defaults to STUDY_DIR.
"""

import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402


def read_rows(path):
    if not os.path.isfile(path):
        sys.exit(f"plot_fidelity: error: '{path}' does not exist (run bench/model_sensitivity.py)")
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_fidelity: error: '{path}' has no rows")
    return rows


def by_variant(rows, wanted):
    """{variant: rows sorted by phi}, in the order first seen (or of `wanted`)."""
    groups = {}
    for r in rows:
        groups.setdefault(r["variant"], []).append(r)
    names = wanted if wanted else list(groups)
    missing = [n for n in names if n not in groups]
    if missing:
        sys.exit(f"plot_fidelity: error: no rows for variant(s) {', '.join(missing)}")
    return {n: sorted(groups[n], key=lambda r: float(r["phi"])) for n in names}


def save(fig, ax, ylabel, title, path, xlabel="φ", **legend):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(fontsize=7, **legend)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def plot_exponent(groups, path):
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.axhspan(0.48, 0.52, color="0.85", label="paper: 0.50 ± 0.02")
    for name, rows in groups.items():
        ax.errorbar([float(r["phi"]) for r in rows], [float(r["m"]) for r in rows],
                    yerr=[float(r["m_se"]) for r in rows], marker="o", capsize=3, label=name)
    save(fig, ax, "Herschel–Bulkley exponent m of σ", "N = 250, 2 packings, γ̃ = 1e-9 … 1e-4",
         path)


def plot_tradeoff(groups, path):
    """m against sigma_e/sigma_v: the paper asks for both m = 0.50 and a ratio >= 100."""
    fig, ax = plt.subplots(figsize=(8.5, 4.5))
    ax.fill_between([100, 2000], 0.47, 0.53, color="0.85", label="paper: m = 0.50 ± 0.03, σe/σv ≥ 100")
    markers = "osD^v<>"
    for k, (name, rows) in enumerate(groups.items()):
        rows = [r for r in rows if r["ev_ratio"] not in ("", "nan")]
        if rows:
            ax.plot([float(r["ev_ratio"]) for r in rows], [float(r["m"]) for r in rows],
                    marker=markers[k % len(markers)], label=name)
    ax.set_xscale("log")
    ax.set_xlim(1, 2000)
    save(fig, ax, "Herschel–Bulkley exponent m of σ",
         "N = 250: exponent against the viscous share of the stress", path,
         xlabel="σe/σv (smallest over γ̃ ≤ 1e-5); points: φ = 0.75, 0.85, 0.90",
         loc="center left", bbox_to_anchor=(1.01, 0.5))


def plot_modulus(groups, path):
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.axhspan(1 / 1.5, 1.5, color="0.85", label="within a factor 1.5")
    for name, rows in groups.items():
        ax.plot([float(r["phi"]) for r in rows], [float(r["G0_mason"]) for r in rows],
                marker="o", label=name)
    ax.set_yscale("log")
    save(fig, ax, "G0 / (compressed emulsions, Mason et al. 1995)", "relaxed packings, N = 1000",
         path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("study")
    parser.add_argument("-o", "--output")
    parser.add_argument("--variants", help="comma-separated; default: all in summary.csv")
    args = parser.parse_args()
    out = args.output or args.study
    os.makedirs(out, exist_ok=True)
    wanted = [v.strip() for v in args.variants.split(",")] if args.variants else None
    summary = read_rows(os.path.join(args.study, "summary.csv"))
    plot_exponent(by_variant(summary, wanted), os.path.join(out, "fidelity_exponent.png"))
    plot_tradeoff(by_variant(summary, None), os.path.join(out, "fidelity_tradeoff.png"))
    static = os.path.join(args.study, "static.csv")
    if os.path.isfile(static):
        plot_modulus(by_variant(read_rows(static), None), os.path.join(out, "fidelity_modulus.png"))


if __name__ == "__main__":
    main()
