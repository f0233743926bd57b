"""The staggered (partitioned) step of the shaft-and-trains march (:mod:`._step`).

Felippa and Park's serial staggered procedure for coupled systems (Felippa, Park and Farhat,
"Partitioned analysis of coupled mechanical systems", Comput. Methods Appl. Mech. Engrg. 190,
2001): within each time step the shaft is advanced first, under a predicted contact load
of every lobe, and every train after it, with the shaft's new lobe motion as a prescribed
part of its cam input. The contact load each train then carries is the one predicted for the
next step. Predictors: the last step's load (``constant``, a first-order splitting error) or
its linear extrapolation from the last two steps (``linear``, second order where the load is
smooth). Repeating a step with the load it produced as the new prediction until the two agree
(``iterations`` > 1, a strongly coupled staggered step) converges to the monolithic step.

Why the step-by-step exchange converges where a revolution-by-revolution exchange does not:
over one step the shaft's answer to a lobe force is dominated by its inertia, a compliance of
about dt^2 / (4 m), so the loop gain contact stiffness times compliance is far below one at
the march's steps (about 1e-2 for the Zeta shaft at 24 steps per degree), while over a
revolution it is the static ratio of contact to shaft stiffness, above one on a soft shaft.
"""
from __future__ import annotations

from numba import njit

#: predictors of the staggered step's contact load, by kernel code
PREDICTORS = {"constant": 0, "linear": 1}


@njit(cache=True)
def predict_loads(w_prev, w_older, predictor, out):
    """Every contact's predicted load at the step's end: the last (``predictor`` 0) or the
    linear extrapolation of the last two (1), never a pull."""
    for j in range(w_prev.size):
        w = w_prev[j] if predictor == 0 else 2.0 * w_prev[j] - w_older[j]
        out[j] = w if w > 0.0 else 0.0


@njit(cache=True)
def add_shaft_loads(z, w_pred, at):
    """The predicted contact loads on every lobe's shaft coordinates (x, y, phi) of the
    per-lobe force vector ``z``: -W times the contact's gradient (``at``: every lobe's
    inputs at the step's end), as the closed contact of the monolithic step pushes the
    shaft."""
    w = z.size // w_pred.size     # coordinates per lobe (5, 6 with lash adjusters)
    for j in range(w_pred.size):
        z[w * j] -= w_pred[j] * at.gx[j]
        z[w * j + 1] -= w_pred[j] * at.gy[j]
        z[w * j + 2] -= w_pred[j] * at.gphi[j]


@njit(cache=True)
def add_shaft_forces(f, w_pred, at, lay):
    """The same loads added to a full force vector ``f``."""
    for j in range(w_pred.size):
        f[lay.ix[j]] -= w_pred[j] * at.gx[j]
        f[lay.iy[j]] -= w_pred[j] * at.gy[j]
        f[lay.iphi[j]] -= w_pred[j] * at.gphi[j]


@njit(cache=True)
def prescribed_inputs(z, zd, at, lay, pre):
    """Every train's cam input with its lobe's shaft motion (displacements ``z``, velocities
    ``zd``) prescribed, into ``pre.b``, ``pre.bd``: b + R (cos a x + sin a y) + l' phi and its
    rate, so that the train's own step sees the shaft only through its input."""
    ix, iy, iphi = lay.ix, lay.iy, lay.iphi
    for j in range(at.b.size):
        pre.b[j] = at.b[j] + at.gx[j] * z[ix[j]] + at.gy[j] * z[iy[j]] + at.gphi[j] * z[iphi[j]]
        pre.bd[j] = (at.bd[j] + at.gx[j] * zd[ix[j]] + at.gy[j] * zd[iy[j]]
                     + at.gphi[j] * zd[iphi[j]])
