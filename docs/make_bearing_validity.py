"""Regenerate the short-bearing validity figure and table of docs/bearings.md.

    python docs/make_bearing_validity.py

Film ratio h_min(short) / h_min(finite) at the same Sommerfeld number, over b/d, for several
Sommerfeld numbers (finite: Reynolds solution, Swift-Stieber cavitation, no groove, default
mesh). Writes docs/img/bearing_validity.png and prints the Markdown table.
"""
from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

B_OVER_D = (0.05, 0.1, 0.2, 0.25, 0.3, 0.4, 0.5, 0.7, 1.0)
SOMMERFELD = (1.0, 0.3, 0.1, 0.03, 0.01)


def main() -> None:
    import numpy as np
    from matplotlib.figure import Figure

    from camtrain.bearings.validity import short_film_ratio

    table = np.array([short_film_ratio(ld, SOMMERFELD) for ld in B_OVER_D])
    fig = Figure(figsize=(6.4, 4.2))
    ax = fig.add_subplot()
    for j, s in enumerate(SOMMERFELD):
        ax.plot(B_OVER_D, table[:, j], marker="o", label=f"S = {s:g}")
    ax.axhline(1.05, color="grey", lw=0.8, ls="--")
    ax.set_xlabel("b/d (land length / diameter) [-]")
    ax.set_ylabel("h_min short / h_min finite [-]")
    ax.set_title("How optimistic the short (Ocvirk) bearing is")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.savefig(ROOT / "docs" / "img" / "bearing_validity.png", dpi=110)
    print("| b/d | " + " | ".join(f"S = {s:g}" for s in SOMMERFELD) + " |")
    print("|---" * (len(SOMMERFELD) + 1) + "|")
    for ld, row in zip(B_OVER_D, table, strict=True):
        cells = " | ".join("-" if np.isnan(x) else f"x{x:.2f}" for x in row)
        print(f"| {ld:g} | {cells} |")


if __name__ == "__main__":
    main()
