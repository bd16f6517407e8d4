#!/usr/bin/python3
"""Figures of the bridge, drawn from the CSV tables `bridge fit` and `bridge rescale` write.

    plot_bridge.py fit LAW.prm [-o DIR]       flow curves with their Herschel-Bulkley fits
                                              (the paper's Fig. 2a), the collapse of sigma, N1
                                              and N2 on the universal laws (Figs. 4a-c) and,
                                              with structure data, the force law (Fig. 3c)
    plot_bridge.py rescale RESCALED.csv [-o DIR]
                                              measured curves on the universal curve (Fig. 5)

`fit` reads LAW_phi.csv, LAW_points.csv and LAW_constants.csv beside LAW.prm;
`rescale` reads RESCALED.csv and RESCALED_curves.csv. PNG files go to DIR
(default: beside the tables). Only the tables are read: every number on a
figure is one that `bridge` computed and wrote, so the figures cannot disagree
with the reports — except the paper's published values (PAPER below), drawn
in grey and labelled "the paper" for comparison.
"""

import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402

from result_table import read_rows  # noqa: E402


def read_table(path):
    """Rows of a bridge CSV table as dicts; '#' lines (provenance) skipped."""
    if not os.path.isfile(path):
        sys.exit(f"plot_bridge: error: table '{path}' does not exist (run bridge first)")
    with open(path, newline="", encoding="utf-8") as f:
        rows, _ = read_rows(f)
    if not rows:
        sys.exit(f"plot_bridge: error: table '{path}' has no rows")
    return rows


def number(row, column):
    return float(row[column])


def has(rows, column):
    return column in rows[0]


def by_phi(rows):
    groups = {}
    for row in rows:
        groups.setdefault(number(row, "phi [1]"), []).append(row)
    return dict(sorted(groups.items()))


def colours(count):
    cmap = plt.get_cmap("viridis")
    return [cmap(i / max(1, count - 1) * 0.9) for i in range(count)]


# Seth et al., Nature Materials 10, 838 (2011): the Herschel-Bulkley exponent
# of every phi (Fig. 2a) and the constants of the universal laws (Figs. 4a-c),
# each with its stated error. Drawn beside ours, never used in a computation.
PAPER_EXPONENT = (0.50, 0.02)
PAPER_CONSTANT = {"sigma": (80.0, 3.0), "N1": (20.0, 2.0), "N2": (26.0, 2.0)}


def log_grid(low, high, points=200):
    a, b = math.log10(low), math.log10(high)
    return [10 ** (a + (b - a) * i / (points - 1)) for i in range(points)]


def constant(constants, name):
    for row in constants:
        if row["constant"] == name:
            return number(row, "value [1]"), number(row, "error [1]")
    return None


def save(fig, directory, name):
    path = os.path.join(directory, name)
    fig.savefig(path, dpi=150, bbox_inches="tight")
    plt.close(fig)
    print(f"written  {path}")


def flow_curves(points, phis, quantity, units, directory, name, title):
    """Fig. 2a: |Q|/E* against gamma~ per phi, with the Herschel-Bulkley fit of each
    (for f_m the force law with exponent 1/2 when the table has it)."""
    groups = by_phi(points)
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    for colour, (phi, rows) in zip(colours(len(groups)), groups.items()):
        x = [number(r, "gamma_tilde [1]") for r in rows]
        y = [abs(number(r, f"{quantity} [{units}]")) for r in rows]
        e = [number(r, f"{quantity}_se [{units}]") for r in rows]
        fit = next(p for p in phis if number(p, "phi [1]") == phi)
        if quantity == "f_m" and "f_y [E*R^2]" in fit:
            # The paper's force law, exponent fixed at 1/2 (Fig. 3c).
            yield_, k, m = number(fit, "f_y [E*R^2]"), number(fit, "k_f [E*R^2]"), 0.5
            label = f"φ = {phi:g}"
        else:
            yield_ = number(fit, f"{quantity}_yield [{units}]")
            k = number(fit, f"{quantity}_consistency [{units}]")
            m = number(fit, f"{quantity}_exponent [1]")
            label = f"φ = {phi:g}, m = {m:.2f}"
        ax.errorbar(x, y, yerr=e, fmt="o", ms=4, color=colour, label=label)
        grid = log_grid(min(x), max(x))
        ax.plot(grid, [abs(yield_ + k * g**m) for g in grid], "-", color=colour, lw=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("γ̃ = γ̇ η_s / E*")
    label = {"sigma": "σ / E*", "N1": "|N1| / E*", "N2": "|N2| / E*", "f_m": "f_m / (E* R²)"}
    ax.set_ylabel(label[quantity])
    if quantity == "sigma":
        title += f"\n(the paper: m = {PAPER_EXPONENT[0]:.2f} ± {PAPER_EXPONENT[1]:.2f} at every φ)"
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=7, frameon=False)
    save(fig, directory, name)


def follow_data(ax, values):
    """Log axis limits from the positive data: a plateau line below zero would
    otherwise pull the axis down towards -inf."""
    shown = [v for v in values if v > 0]
    if shown:
        ax.set_ylim(min(shown) / 2, max(shown) * 2)


def collapse(points, phis, constants, directory, name):
    """Figs. 4a-c: sigma/sigma_y, N1/sigma_y and -N2/sigma_y against gamma~/gamma_y^2,
    all phi; sigma on 1 + k x^(1/2), the normal stresses on each phi's own
    plateau N_y/sigma_y + k' x^(1/2) (bridge/fit/universal_law.h)."""
    # A quantity whose universal fit failed has a NaN constant (or none): no panel.
    panels = [(q, c) for q, c in (("sigma", "k"), ("N1", "k_N1"), ("N2", "k_N2"))
              if has(points, f"{q}_ratio [1]") and constant(constants, c) is not None
              and math.isfinite(constant(constants, c)[0])]
    fig, axes = plt.subplots(1, len(panels), figsize=(4.2 * len(panels), 4), squeeze=False)
    groups = by_phi(points)
    plateau_rows = {number(r, "phi [1]"): r for r in phis}
    x_all = [number(r, "collapse_rate [1]") for r in points]
    grid = log_grid(min(x_all), max(x_all))
    symbol = {"sigma": "σ/σ_y", "N1": "N1/σ_y", "N2": "−N2/σ_y"}
    letter = {"sigma": "k", "N1": "k′", "N2": "k″"}
    sign = {"sigma": 1, "N1": 1, "N2": -1}
    for ax, (quantity, name_k) in zip(axes[0], panels):
        k, error = constant(constants, name_k)
        for colour, (phi, rows) in zip(colours(len(groups)), groups.items()):
            ax.plot([number(r, "collapse_rate [1]") for r in rows],
                    [number(r, f"{quantity}_ratio [1]") for r in rows], "o", ms=4, color=colour,
                    label=f"φ = {phi:g}")
            if quantity != "sigma":
                row = plateau_rows[phi]
                plateau = sign[quantity] * number(row, f"{quantity}_universal_yield [E*]") \
                    / number(row, "sigma_universal_yield [E*]")
                ax.plot(grid, [plateau + k * math.sqrt(x) for x in grid], "-", color=colour,
                        lw=0.8)
        paper, paper_error = PAPER_CONSTANT[quantity]
        if quantity == "sigma":
            ax.plot(grid, [1 + k * math.sqrt(x) for x in grid], "k-", lw=1,
                    label=f"1 + k x^½, k = {k:.3g} ± {error:.2g}")
            ax.plot(grid, [1 + paper * math.sqrt(x) for x in grid], "-", color="0.6", lw=2,
                    alpha=0.6, label=f"the paper: k = {paper:g} ± {paper_error:g}")
        else:
            ax.plot(grid, [paper * math.sqrt(x) for x in grid], "--", color="0.6", lw=2,
                    alpha=0.6, label=f"the paper: {letter[quantity]} = {paper:g} ± {paper_error:g}")
        if quantity != "sigma":
            ax.plot(grid, [k * math.sqrt(x) for x in grid], "k--", lw=1,
                    label=f"{letter[quantity]} x^½, {letter[quantity]} = {k:.3g} ± {error:.2g} "
                          "(thin: φ's plateau + it)")
            follow_data(ax, [number(r, f"{quantity}_ratio [1]") for r in points])
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("γ̃ / γ_y²")
        ax.set_ylabel(symbol[quantity])
        ax.legend(fontsize=7, frameon=False)
    save(fig, directory, name)


def fit_figures(law, directory):
    stem = os.path.splitext(law)[0]
    phis = read_table(stem + "_phi.csv")
    points = read_table(stem + "_points.csv")
    constants = read_table(stem + "_constants.csv")
    base = os.path.basename(stem)
    flow_curves(points, phis, "sigma", "E*", directory, f"{base}_flow_curves.png",
                "flow curves and Herschel–Bulkley fits (cf. Seth et al. 2011, Fig. 2a)")
    collapse(points, phis, constants, directory, f"{base}_collapse.png")
    for quantity in ("N1", "N2"):
        if has(points, f"{quantity} [E*]"):
            flow_curves(points, phis, quantity, "E*", directory, f"{base}_{quantity}.png",
                        f"{quantity} and its Herschel–Bulkley fits")
    if has(points, "f_m [E*R^2]"):
        flow_curves(points, phis, "f_m", "E*R^2", directory, f"{base}_force.png",
                    "force at maximum accumulation and f_y + k_f γ̃^½ (cf. Fig. 3c)")


def rescale_figure(table, directory):
    """Fig. 5: tau/tau_y on 1 + k x^(1/2) and, for curves with N1, N1/tau_y on
    each curve's N1_y/tau_y + k' x^(1/2) (Figs. 5b, d)."""
    points = read_table(table)
    curves = read_table(os.path.splitext(table)[0] + "_curves.csv")
    k = number(curves[0], "k [1]")
    k_n1 = number(curves[0], "k_N1 [1]")
    normal = has(points, "N1_ratio [1]")
    fig, axes = plt.subplots(1, 2 if normal else 1, figsize=(5.5 * (2 if normal else 1), 4.2),
                             squeeze=False)
    labels = list(dict.fromkeys(r["curve"] for r in points))
    x_all = [number(r, "collapse_rate [1]") for r in points]
    grid = log_grid(min(x_all), max(x_all))
    for colour, label in zip(colours(len(labels)), labels):
        rows = [r for r in points if r["curve"] == label]
        fit = next(c for c in curves if c["curve"] == label)
        used = [r for r in rows if number(r, "used [1]") > 0]
        unused = [r for r in rows if number(r, "used [1]") == 0]
        panels = [("stress_ratio [1]", f"{label}: E* = {number(fit, 'E* [Pa]'):.3g} Pa, "
                                       f"rms {100 * number(fit, 'rms_residual [1]'):.1f} %")]
        # A curve without an N1 law has zeros in the N1 columns (bridge/output/tables.h).
        has_n1 = normal and any(number(r, "N1 [Pa]") != 0 for r in rows)
        if has_n1:
            panels.append(("N1_ratio [1]", label))
            plateau = number(fit, "N1_y [Pa]") / number(fit, "tau_y [Pa]")
            axes[0][1].plot(grid, [plateau + k_n1 * math.sqrt(x) for x in grid], "-",
                            color=colour, lw=0.8)
        for ax, (column, legend) in zip(axes[0], panels):
            ax.plot([number(r, "collapse_rate [1]") for r in used],
                    [number(r, column) for r in used], "o", ms=4, color=colour, label=legend)
            if unused:
                ax.plot([number(r, "collapse_rate [1]") for r in unused],
                        [number(r, column) for r in unused], "o", ms=4, mfc="none",
                        color=colour)
    axes[0][0].plot(grid, [1 + k * math.sqrt(x) for x in grid], "k-", lw=1,
                    label=f"1 + {k:.3g} x^½")
    axes[0][0].set_ylabel("τ / τ_y")
    if normal:
        axes[0][1].plot(grid, [k_n1 * math.sqrt(x) for x in grid], "k--", lw=1,
                        label=f"{k_n1:.3g} x^½ (thin: each curve's N1_y/τ_y + it)")
        axes[0][1].set_ylabel("N1 / τ_y")
        follow_data(axes[0][1], [number(r, "N1_ratio [1]") for r in points])
    for ax in axes[0]:
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("γ̇ η_s / (E* γ_y²)")
        ax.legend(fontsize=6, frameon=False)
    axes[0][0].set_title("measured curves on the universal law (cf. Seth et al. 2011, Fig. 5); "
                         "open: outside the fitted window", fontsize=8)
    save(fig, directory, os.path.splitext(os.path.basename(table))[0] + "_universal.png")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    fit = sub.add_parser("fit", help="figures of a `bridge fit` result")
    fit.add_argument("law", help="the law file; its tables are read from beside it")
    fit.add_argument("-o", "--output", help="directory for the PNG files")
    rescale = sub.add_parser("rescale", help="figure of a `bridge rescale` result")
    rescale.add_argument("table", help="the rescaled points table")
    rescale.add_argument("-o", "--output", help="directory for the PNG files")
    args = parser.parse_args()
    source = args.law if args.command == "fit" else args.table
    directory = args.output or os.path.dirname(os.path.abspath(source))
    os.makedirs(directory, exist_ok=True)
    if args.command == "fit":
        fit_figures(args.law, directory)
    else:
        rescale_figure(args.table, directory)


if __name__ == "__main__":
    main()
