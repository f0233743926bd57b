"""Regenerate the cost-against-points figure of docs/ehl.md ("Cost").

    python docs/make_ehl_cost.py            # about two minutes of CPU

Measures the CPU time (``time.process_time``, the solvers on one BLAS thread, the least of
``REPEATS`` runs) of the steady line contact at case A on 256 ... 65,536 points, and of 80
steps of the elastic film's march through the Göçmen cam's opening flank and first
entrainment reversal (matrix-free Newton directions at every size) on 128 ... 4,096 points;
fits the exponent k of cost ~ n^k to each; draws both on log-log axes with the reference slopes
n, n log n and n^2 through the 1,024-point measurement, writes docs/img/ehl_cost.png and prints
the table the page quotes.
"""
from __future__ import annotations

import sys
import time
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
IMG = ROOT / "docs" / "img"
sys.path.insert(0, str(ROOT))

STEADY_POINTS = (256, 512, 1024, 2048, 4096, 8192, 16384, 32768, 65536)
MARCH_POINTS = (128, 256, 512, 1024, 2048, 4096)
REPEATS = 3


def least_cpu(run, repeats: int) -> float:
    """The least CPU time [s] of ``repeats`` calls (the machine's load only adds time)."""
    best = float("inf")
    for _ in range(repeats):
        start = time.process_time()
        run()
        best = min(best, time.process_time() - start)
    return best


def steady_costs(points=STEADY_POINTS) -> list[float]:
    """CPU of the steady solve at case A (benchmarks/test_bench_ehl.py) per size."""
    from camtrain.lubrication.ehl_line import EHLResolution, LineContact, solve_ehl_line
    from camtrain.lubrication.ehl_oil import Oil

    case_a = LineContact(2e5, 0.02, 2.26e11, 1.0, 1.0, Oil(0.04, 2e-8))
    solve_ehl_line(case_a, EHLResolution(nodes=256))          # imports and caches
    return [least_cpu(lambda n=n: solve_ehl_line(case_a, EHLResolution(nodes=n)),
                      REPEATS if n <= 16384 else 1) for n in points]


def march_costs(points=MARCH_POINTS) -> list[float]:
    """CPU of 80 march steps (-52 .. -12 deg of the Göçmen cam) per size, one run each."""
    from camtrain.lubrication.ehl_transient import CycleResolution, march_ehl_cycle
    from tests.lubrication.test_ehl_transient import goecmen_cycle

    full = goecmen_cycle(720)
    window = slice(256, 336)
    part = replace(full, **{k: getattr(full, k)[window] for k in ("t", "w", "R", "u", "u_s")})
    return [least_cpu(lambda n=n: march_ehl_cycle(
        part, CycleResolution(nodes=n, linear_solver="krylov")), 1) for n in points]


def exponent(points, costs) -> float:
    """k of the least-squares line through (log n, log cost)."""
    import numpy as np

    return float(np.polyfit(np.log(points), np.log(costs), 1)[0])


def draw(series, path: Path) -> None:
    """series: (label, points, costs) each; reference slopes through each one's 1,024 point."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for (label, points, costs), marker in zip(series, "os", strict=True):
        top = list(points).index(1024)
        ax.loglog(points, costs, marker + "-", lw=1.6,
                  label=f"{label}: n^{exponent(points, costs):.2f} fitted "
                        f"(n^{exponent(points[top:], costs[top:]):.2f} from 1,024)")
        n = np.geomspace(points[0], points[-1], 50)
        c0 = costs[list(points).index(1024)]
        for shape, style, name in ((n / 1024, ":", "n"),
                                   (n * np.log(n) / (1024 * np.log(1024)), "--", "n log n"),
                                   ((n / 1024) ** 2, "-.", "n²")):
            ax.loglog(n, c0 * shape, style, color="grey", lw=0.9,
                      label=name if marker == "o" else None)
    ax.set_xlabel("grid points n")
    ax.set_ylabel("CPU time [s] (one BLAS thread, least of runs)")
    ax.set_title("Elastic line contact: cost against points")
    ax.set_ylim(min(min(c) for _, _, c in series) / 30, max(max(c) for _, _, c in series) * 3)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="lower right")      # below the steady line: the free corner
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main() -> None:
    steady = steady_costs()
    march = march_costs()
    for label, points, costs in (("steady, case A", STEADY_POINTS, steady),
                                 ("march, 80 steps", MARCH_POINTS, march)):
        print(label)
        for n, c in zip(points, costs, strict=True):
            print(f"  {n:6d} points  {c:8.4f} s")
        print(f"  fitted n^{exponent(points, costs):.2f}; from 1024 up "
              f"n^{exponent(points[points.index(1024):], costs[points.index(1024):]):.2f}")
    draw([("steady line contact, case A", STEADY_POINTS, steady),
          ("cycle march, 80 steps", MARCH_POINTS, march)], IMG / "ehl_cost.png")
    print(f"wrote {IMG / 'ehl_cost.png'}")


if __name__ == "__main__":
    main()
