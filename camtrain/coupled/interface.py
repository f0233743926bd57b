"""The interface Jacobian of the waveform shaft/train coupling, from the linear parts of both.

One pass of the waveform iteration (:mod:`camtrain.coupled.relaxation`) maps the lobes' motion
x to the shaft's motion under the trains' loads, H(x). Where a lobe sits on a lightly damped
shaft mode, H amplifies the motion there by the contact stiffness times the shaft's dynamic
compliance, far above 1 (the Zeta shaft at ten times the assumed stiffness: the lobes' local
bending mode near order 304, 7.6 kHz at 1500 rpm, with a linear gain up to 58), and the plain
iteration, Aitken's and a quasi-Newton started from nothing all diverge once the exchange grid
resolves that mode.

Both halves are linear apart from the contacts, so the pass's Jacobian is known in advance for a
closed cam contact and an open seat (the valve in flight): order by order, J_k = -S_k G_k with
S_k the shaft's receptance between the lobes along their follower axes, G_k = diag(R^2 g_k)
each train's dynamic contact stiffness (load per unit cam-input displacement, R the rocker
ratio), and the minus sign because the load pushes the lobe away from its follower. The update
x + (I - J)^-1 (H(x) - x) is then a Newton step of the linear problem (an interface Newton
preconditioner of a partitioned solver: Degroote 2013, "Partitioned simulation of
fluid-structure interaction", Arch. Comput. Methods Eng. 20, §4); the quasi-Newton or Aitken
passes run on the preconditioned residual and learn what the linear model leaves out (contact
opening, the valve on its seat, the twist and friction, kept out of J).
"""
from __future__ import annotations

import numpy as np

from camtrain.dynamics.train import CAM, TrainModel

__all__ = ["contact_stiffness", "interface_newton"]


def contact_stiffness(model: TrainModel, omega: float, orders) -> np.ndarray:
    """Dynamic stiffness g_k [N/m] of the train at its cam contact: the contact force per unit
    harmonic cam-input displacement at order k (frequency k omega), cam contact closed, seat
    open. g = z (1 - z [Z^-1]_ff), z = k_c + i w c_c, Z the train's dynamic stiffness with the
    cam contact closed (f the follower node)."""
    orders = np.asarray(orders, dtype=float)
    i = int(model.uni_node[CAM])
    kc, cc = float(model.uni_k[CAM]), float(model.uni_c[CAM])
    K = model.stiffness.copy()
    C = model.damping.copy()
    K[i, i] += kc
    C[i, i] += cc
    w = orders * omega
    Z = (K[None] - (w * w)[:, None, None] * np.diag(model.mass)[None]
         + 1j * w[:, None, None] * C[None])
    unit = np.zeros(model.size)
    unit[i] = 1.0
    col = np.linalg.solve(Z, np.broadcast_to(unit, (w.size, model.size))[..., None])[:, i, 0]
    z = kc + 1j * w * cc
    return z * (1.0 - z * col)


def interface_newton(jacobian: np.ndarray, rows: slice | np.ndarray):
    """The preconditioner r -> (I - J)^-1 r of the module notes, applied order by order to the
    rows ``rows`` of a residual sampled on the uniform grid of one revolution (the other rows
    pass unchanged). ``jacobian``: (n_orders, m, m) complex, the pass's Jacobian J_k on those
    rows, n_orders = grid // 2 + 1."""
    m = jacobian.shape[-1]
    inverse = np.linalg.inv(np.eye(m)[None] - jacobian)

    def apply(residual: np.ndarray) -> np.ndarray:
        out = np.array(residual, dtype=float, copy=True)
        block = out[rows]
        n = block.shape[-1]
        R = np.fft.rfft(block, axis=-1)
        out[rows] = np.fft.irfft(np.einsum("kij,jk->ik", inverse, R), n=n, axis=-1)
        return out

    return apply
