"""Regenerate the convergence figures of docs/dynamics.md (the limits of the elastic train).

    python docs/make_dynamics_figures.py

Writes docs/img/dynamics_sdof_period.png (Newmark's period error of a single-mass train against
the step), docs/img/dynamics_surge.png (the spring chain's first surge mode and end mass against
the number of elements) and docs/img/dynamics_stiff_limit.png (the stiff train's load against the
rigid train's, Zeta intake at 1500 rpm, and the window after the contact edge at x 1e3, 1e4,
1e5), and prints the numbers the page quotes.
"""
from __future__ import annotations

import math
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
IMG = ROOT / "docs" / "img"
sys.path.insert(0, str(ROOT))

ZETA_RATE, ZETA_SPRING_MASS = 37634.0, 0.035


def _period(u, dt):
    import numpy as np

    s = np.sign(u)
    i = np.nonzero((s[:-1] < 0) & (s[1:] >= 0))[0]
    t = (i + u[i] / (u[i] - u[i + 1])) * dt
    return float((t[-1] - t[0]) / (t.size - 1))


def _finish(fig, ax, xlabel, ylabel, title, name):
    """Label a log-log convergence plot, add its legend and grid, and write it to docs/img."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, which="both")
    fig.savefig(IMG / name, dpi=110)


def sdof_figure():
    import numpy as np
    from matplotlib.figure import Figure

    from camtrain.dynamics import CAM, assemble_train
    from camtrain.dynamics.integrators import bilateral, free_vibration

    model = bilateral(assemble_train(valve_mass=0.1, contact_stiffness=2e8, links={"stem": 5e7},
                                     seat_stiffness=1e8, spring_rate=4e4, spring_preload=200.0,
                                     damping_ratio=0.0, spring_damping_ratio=0.0),
                      contacts=(CAM,))
    exact = 2 * math.pi / math.sqrt(model.stiffness[0, 0] / 0.1)
    per = np.array([8, 12, 16, 24, 32, 48, 58, 64, 96, 128, 192, 256])
    err = {}
    for name in ("newmark", "central_difference"):
        err[name] = np.array([abs(_period(free_vibration(model, [1e-4], exact / p, 40 * p, name)[0],
                                          exact / p) / exact - 1) for p in per])
    fig = Figure(figsize=(6.4, 4.2))
    ax = fig.add_subplot()
    ax.loglog(per, 100 * err["newmark"], "o", label="newmark (average acceleration)")
    ax.loglog(per, 100 * err["central_difference"], "s", mfc="none",
              label="central difference (Teodorescu eq. 17)")
    ax.loglog(per, 100 * (2 * np.pi / per) ** 2 / 12, "-", lw=0.8, label="(ω Δt)²/12")
    ax.axhline(0.1, color="grey", ls="--", lw=0.8)
    ax.axvline(2 * math.pi / math.sqrt(12e-3), color="grey", ls=":", lw=0.8)
    ax.text(60, 0.12, "0.1 % from 57.4 steps per period", fontsize=8)
    _finish(fig, ax, "steps per natural period T/Δt [-]", "period error [%]",
            "Single-mass train: period against the step (k_e by the series rule)",
            "dynamics_sdof_period.png")
    slope = np.polyfit(np.log(1.0 / per), np.log(err["newmark"]), 1)[0]
    at58 = 100 * err["newmark"][list(per).index(58)]
    print(f"SDOF: newmark period error slope {slope:.3f}; at T/58 {at58:.3g} %")


def surge_figure():
    import numpy as np
    from matplotlib.figure import Figure

    from camtrain.dynamics import assemble_train, chain_end_mass, surge_frequency

    ns = np.array([2, 4, 8, 16, 32, 64])
    f1 = surge_frequency(ZETA_RATE, ZETA_SPRING_MASS)
    modes = []
    for n in ns:
        model = assemble_train(valve_mass=1.0, contact_stiffness=1e8, seat_stiffness=1e8,
                               spring_rate=ZETA_RATE, spring_preload=200.0,
                               spring_mass=ZETA_SPRING_MASS, spring_elements=int(n))
        idx = list(model.chain)
        k = model.stiffness[np.ix_(idx, idx)]
        s = 1 / np.sqrt(model.mass[idx])
        modes.append(math.sqrt(np.linalg.eigvalsh(k * s[:, None] * s[None, :])[0]) / (2 * math.pi))
    modes = np.array(modes)
    end = np.array([chain_end_mass(ZETA_SPRING_MASS, int(n)) for n in ns]) / (ZETA_SPRING_MASS / 3)
    fig = Figure(figsize=(6.4, 4.2))
    ax = fig.add_subplot()
    ax.loglog(ns, 100 * np.abs(modes / f1 - 1), "o-", label=f"first surge mode (→ {f1:.1f} Hz)")
    ax.loglog(ns, 100 * np.abs(end - 1), "s-", label="equivalent end mass (→ m_s/3)")
    ax.loglog(ns, 100 * np.abs(modes[2] / f1 - 1) * (8.0 / ns) ** 2, ":", color="grey",
              label="N⁻²")
    ax.axhline(1.0, color="grey", ls="--", lw=0.8)
    _finish(fig, ax, "spring elements N [-]", "error against the continuum [%]",
            "Zeta valve spring as an N-mass chain", "dynamics_surge.png")
    print("surge: " + ", ".join(f"N={n}: {m:.2f} Hz ({100 * (m / f1 - 1):+.2f} %)"
                                for n, m in zip(ns, modes, strict=True)))


def stiff_limit_figure():
    import numpy as np
    from matplotlib.figure import Figure

    from camtrain.assemble.dynamics import rigid_load, setup
    from camtrain.dynamics import march
    from camtrain.loads import contact_mask
    from tests.dynamics.conftest import SINGLE_RATE, deck_of, kinematics_of, zeta_raw

    fig = Figure(figsize=(10.0, 4.2))
    ax1, ax2 = fig.subplots(1, 2)
    deck = deck_of(zeta_raw({"dynamics": SINGLE_RATE}))
    kin = kinematics_of(deck)
    rigid = rigid_load(deck, kin)
    s = setup(deck, kin, stiffness_scale=1e3)
    dyn = march(s.model, s.cam, s.base, s.settings).contact_force[0] * kin.rocker_ratio
    deg = np.degrees(kin.theta)
    ax1.plot(deg, rigid, lw=2.5, color="0.75", label="rigid train")
    ax1.plot(deg, dyn, lw=0.9, label="elastic train, stiffnesses × 10³")
    ax1.set_xlim(-90, 90)
    ax1.set_xlabel("cam angle [deg]")
    ax1.set_ylabel("contact load [N]")
    ax1.set_title("Zeta intake, 1500 rpm: stiff limit")
    ax1.legend(fontsize=8)
    ax1.grid(alpha=0.3)
    raw = zeta_raw({"dynamics": SINGLE_RATE})
    raw.setdefault("solver", {})["angle_points"] = 7200
    fine = deck_of(raw)
    kin = kinematics_of(fine)
    rigid = rigid_load(fine, kin)
    edge = np.nonzero(np.diff(contact_mask(kin.valve_lift).astype(int)))[0][0]
    after = np.degrees(np.angle(np.exp(1j * (kin.theta - kin.theta[edge]))))
    near = (after > -0.3) & (after < 3.0)
    for scale in (1e3, 1e4, 1e5):
        s = setup(fine, kin, stiffness_scale=scale, overrides={"cycles_max": 2})
        load = march(s.model, s.cam, s.base, s.settings).contact_force[0] * kin.rocker_ratio
        err = 100 * np.abs(load - rigid) / np.max(rigid)
        ax2.semilogy(after[near], np.maximum(err[near], 1e-4), lw=0.9,
                     label=f"× {scale:.0e}".replace("e+0", "e"))
        big = near & (err > 0.5)
        print(f"stiff limit x{scale:g}: error > 0.5 % until {np.max(after[big]):.2f} deg "
              "after the opening edge")
    ax2.axhline(0.5, color="grey", ls="--", lw=0.8)
    ax2.set_ylim(1e-3, 300)
    ax2.set_xlabel("cam angle after the opening edge [deg] (0.05° grid)")
    ax2.set_ylabel("|W − W_rigid| / max W_rigid [%]")
    ax2.set_title("Impact at the window entry: window ~ k^−½")
    ax2.legend(fontsize=8)
    ax2.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(IMG / "dynamics_stiff_limit.png", dpi=110)


def main() -> None:
    sdof_figure()
    surge_figure()
    stiff_limit_figure()


if __name__ == "__main__":
    main()
