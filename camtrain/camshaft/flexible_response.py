"""Periodic response of the elastic camshaft to the lobe loads: bearing reactions, cam-centre
deflections, twist per station; the bearing splits as named limits; the camstar.

The lobe loads repeat every camshaft revolution, so the periodic steady state of the linear
shaft is found exactly, order by order (harmonic balance of a linear system): for every order k
of the load spectrum, (K + i k w C - (k w)^2 M) X_k = F_k, with w the mean camshaft speed. No
start-up transient and no time step: the resolution knobs are the angle grid (the highest order
resolved) and the stations (:func:`camtrain.camshaft.flexible.stations`).

Bearing splits (``split``):

* ``"elastic"``: the shaft of :func:`beam_shaft` with its bearing springs, inertia and damping.
* ``"determinate"``: hinges at the interior bearings, rigid supports, static - the chain of
  simply supported bays of Ball (1988) §6.3 and Yang (1992) Fig. 3.6 (equals
  :func:`camtrain.camshaft.split_beam_loads`, both overhang rules).
* ``"equal_share"``: a rigid shaft that can only translate on equal bearings - each of the n
  bearings carries sum(F)/n (Teodorescu et al. 2005, rigid-shaft result). This is not beam
  statics: a rigid beam on equal springs also pitches unless the load moment vanishes.

Torsion (Teodorescu §2.6): the drive node turns with the drive, psi_0 = theta; optionally with
Williams' (2013, App A6, eqs A6.5-A6.7) speed oscillation d theta/dt = w + w_hat sin(q w t), which
enters as the base acceleration w_hat q w cos(q theta) of every other node. Centrifugal pendulum
dampers (Williams ch 10) sit at a node as the order-dependent effective inertia of eq. 10.57,
I_E(k) = m (R + r)^2 / (1 - (r/R) k^2) per pendulum, with an optional damping ratio.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camtrain.errors import field_error

from .flexible import BeamShaft, ShaftSection, TorsionShaft, beam_shaft

__all__ = ["camstar", "BendingResponse", "bending_response", "bearing_split", "lobe_receptance",
           "PendulumDamper", "torsion_response", "drive_acceleration"]


def camstar(phases, orders) -> np.ndarray:
    """Teodorescu et al. (2005) Sec. 4, Fig. 11: C_k = |sum_j exp(i k gamma_j)| for each order k.

    For an in-line four firing 1-3-4-2 (gamma = 0, pi/2, 3 pi/2, pi) C_k = 4 when 4 divides k and
    0 otherwise: only the orders 4, 8, 12 ... of one train survive in the summed load."""
    g = np.asarray(phases, dtype=float).ravel()
    k = np.asarray(orders, dtype=float)
    return np.abs(np.exp(1j * k[..., None] * g).sum(axis=-1))


@dataclass(frozen=True)
class BendingResponse:
    """Bending of both planes over one revolution: ``deflection_x/_y`` at every node
    (n_nodes, n_angles) [m], ``bearing_x/_y`` the loads on the bearings (n_bearings, n_angles)
    [N] (the force the shaft puts on each bearing; they sum to the applied forces in statics)."""

    deflection_x: np.ndarray
    deflection_y: np.ndarray
    bearing_x: np.ndarray
    bearing_y: np.ndarray


def _harmonic_solve(Kf, Mf, Cf, F_free, omega):
    """Periodic solution of M x'' + C x' + K x = F(theta), theta = omega t, F on a uniform
    grid over one revolution along the last axis. Returns x on the same grid.

    The shaft's matrices are banded (each element couples only its two nodes), so every order
    is a banded solve (LAPACK gbsv): O(n b^2) instead of O(n^3) per order."""
    n = F_free.shape[-1]
    Fk = np.fft.rfft(F_free, axis=-1)
    X = np.empty_like(Fk)
    pattern = (np.abs(Kf) + np.abs(Mf) + np.abs(Cf)) != 0
    rows, cols = np.nonzero(pattern)
    band = int(np.max(np.abs(rows - cols))) if rows.size else 0
    size = Kf.shape[0]
    if 4 * band < size:
        from scipy.linalg import solve_banded

        diag = np.arange(-band, band + 1)
        # banded storage ab[band + i - j, j] = A[i, j] for K, M and C once
        def banded(A):
            ab = np.zeros((2 * band + 1, size), dtype=A.dtype)
            for d in diag:
                ab[band - d, max(0, d):size + min(0, d)] = np.diagonal(A, d)
            return ab

        kb, mb, cb = banded(Kf), banded(Mf), banded(Cf)
        for k in range(Fk.shape[-1]):
            w = k * omega
            X[:, k] = solve_banded((band, band), kb - (w * w) * mb + 1j * w * cb, Fk[:, k],
                                   check_finite=False)
        return np.fft.irfft(X, n=n, axis=-1), X
    for k in range(Fk.shape[-1]):
        w = k * omega
        Z = Kf - (w * w) * Mf + 1j * w * Cf
        X[:, k] = np.linalg.solve(Z, Fk[:, k])
    return np.fft.irfft(X, n=n, axis=-1), X


def _plane(shaft: BeamShaft, forces, omega, quasi_static):
    """Deflections at the nodes and bearing loads of one plane for nodal forces (n_nodes, n)."""
    st = shaft.stations
    ndof = shaft.K_full.shape[0]
    n = forces.shape[-1]
    F = np.zeros((ndof, n))
    np.add.at(F, shaft.v_index, forces)
    w = 0.0 if quasi_static else omega
    if quasi_static:
        x_free = np.linalg.solve(shaft.K, F[shaft.free])
        Xk = None
    else:
        x_free, Xk = _harmonic_solve(shaft.K, shaft.M, shaft.C, F[shaft.free], w)
    x = np.zeros((ndof, n))
    x[shaft.free] = x_free
    v_nodes = x[shaft.v_index]
    bearing = np.empty((st.bearing_nodes.size, n))
    for j, node in enumerate(st.bearing_nodes):
        dof = shaft.v_index[node]
        if math.isinf(shaft.bearing_k[j]):
            # constraint force on the shaft = residual of the node's equation; load = its opposite
            if quasi_static:
                r = shaft.K_full[dof] @ x - F[dof]
            else:
                Xfull = np.zeros((ndof, Xk.shape[-1]), dtype=complex)
                Xfull[shaft.free] = Xk
                k = np.arange(Xk.shape[-1]) * w
                row = (shaft.K_full[dof][:, None] - (k * k)[None, :] * shaft.M_full[dof][:, None]
                       + 1j * k[None, :] * shaft.C_full[dof][:, None])
                rk = np.sum(row * Xfull, axis=0) - np.fft.rfft(F[dof])
                r = np.fft.irfft(rk, n=n)
            # r = K x - F is the support's force on the shaft; the shaft loads the bearing with -r
            bearing[j] = -r
        else:
            vel = 0.0 if quasi_static else _derivative(x[dof], omega)
            bearing[j] = shaft.bearing_k[j] * x[dof] + shaft.bearing_c[j] * vel
    return v_nodes, bearing


def _derivative(y, omega):
    """Time derivative of a periodic curve on the uniform angle grid (spectral)."""
    n = y.shape[-1]
    Y = np.fft.rfft(y, axis=-1)
    k = np.arange(Y.shape[-1])
    D = 1j * k * omega * Y
    if n % 2 == 0:
        D[..., -1] = 0.0
    return np.fft.irfft(D, n=n, axis=-1)


def _nodal(shaft_nodes: int, force_nodes, f):
    f = np.atleast_2d(np.asarray(f, dtype=float))
    out = np.zeros((shaft_nodes, f.shape[-1]))
    np.add.at(out, np.asarray(force_nodes), f)
    return out


def bending_response(shaft: BeamShaft, force_x, force_y, omega: float = 0.0,
                     quasi_static: bool = False) -> BendingResponse:
    """Deflections and bearing loads of the shaft under the forces at ``stations.force_nodes``.

    Args:
        shaft: bending model (:func:`camtrain.camshaft.flexible.beam_shaft`).
        force_x, force_y: forces on the shaft, (n_forces, n_angles) on the uniform grid of one
            revolution [N] (as :func:`camtrain.camshaft.lobe_force`).
        omega: mean camshaft speed [rad/s] (sets the frequency of order k: k omega).
        quasi_static: drop inertia and damping (static shaft at every angle).
    """
    st = shaft.stations
    n_nodes = st.positions.size
    fx = _nodal(n_nodes, st.force_nodes, force_x)
    fy = _nodal(n_nodes, st.force_nodes, force_y)
    vx, bx = _plane(shaft, fx, omega, quasi_static)
    vy, by = _plane(shaft, fy, omega, quasi_static)
    return BendingResponse(vx, vy, bx, by)


def bearing_split(split: str, bearing_positions, force_positions, force_x, force_y,
                  overhang: str = "nearest", shaft: BeamShaft | None = None,
                  omega: float = 0.0) -> BendingResponse:
    """Bearing loads by a named split: ``elastic`` (needs ``shaft``), ``determinate`` or
    ``equal_share`` (see the module notes). Deflections are zero for ``equal_share`` (a rigid
    shaft on rigid bearings) and those of the hinged rigid-support shaft for ``determinate``."""
    fx = np.atleast_2d(np.asarray(force_x, dtype=float))
    fy = np.atleast_2d(np.asarray(force_y, dtype=float))
    if split == "elastic":
        if shaft is None:
            raise field_error("camshaft.flexibility.bearing_split", "elastic needs a shaft model")
        return bending_response(shaft, fx, fy, omega)
    nb = np.asarray(bearing_positions).size
    if split == "equal_share":
        # rigid shaft constrained to translate on n equal springs k: v = sum F/(n k); R = k v
        k = 1.0
        bx = np.broadcast_to(k * (fx.sum(axis=0) / (nb * k)), (nb, fx.shape[-1])).copy()
        by = np.broadcast_to(k * (fy.sum(axis=0) / (nb * k)), (nb, fy.shape[-1])).copy()
        zero = np.zeros((nb, fx.shape[-1]))
        return BendingResponse(zero, zero.copy(), bx, by)
    if split != "determinate":
        raise field_error("camshaft.flexibility.bearing_split", "unknown split", split,
                          "elastic, determinate or equal_share")
    if overhang not in ("nearest", "lever"):
        raise field_error("overhang", "unknown overhang rule", overhang, "nearest or lever")
    from .flexible import stations

    st = stations(bearing_positions, force_positions)
    b = st.bearing_nodes
    if overhang == "nearest":
        hinges = tuple(b)
    else:  # the end bays continue over the end bearings to the overhangs
        hinges = tuple(b[1:-1]) if b.size > 2 else ()
    rigid = beam_shaft(st, ShaftSection(1.0, 1.0, 1.0, 1.0), math.inf, hinges=hinges,
                       clamp_overhang=(overhang == "nearest"))
    return bending_response(rigid, fx, fy, quasi_static=True)


@dataclass(frozen=True)
class PendulumDamper:
    """``count`` centrifugal pendulums of mass ``mass`` [kg] on pivot radius ``pivot_radius``
    R [m] with effective length ``length`` r [m] (tuned order sqrt(R/r), Williams eq. 10.59) at
    station ``node``; ``damping_ratio`` of the pendulum's own swing (0 = the source's theory)."""

    node: int
    mass: float
    pivot_radius: float
    length: float
    count: int = 1
    damping_ratio: float = 0.0

    def effective_inertia(self, orders) -> np.ndarray:
        """Williams eq. 10.57 at each order k, with the swing damping: complex [kg m^2]."""
        k = np.asarray(orders, dtype=float)
        nt2 = self.pivot_radius / self.length
        rho = k * k / nt2
        denom = 1.0 - rho + 2j * self.damping_ratio * np.sqrt(rho)
        return self.count * self.mass * (self.pivot_radius + self.length) ** 2 / denom


def drive_acceleration(theta, omega: float, amplitude: float = 0.0, order: int = 0):
    """Angular acceleration of the drive [rad/s^2] for Williams' (2013) eq. A6.5 speed
    d theta/dt = omega + amplitude sin(order omega t), on the mean-angle grid theta = omega t:
    amplitude * order * omega * cos(order theta) ([FIX] omega Omega, reference notes)."""
    th = np.asarray(theta, dtype=float)
    return amplitude * order * omega * np.cos(order * th)


def torsion_response(shaft: TorsionShaft, torques, omega: float, dampers=(),
                     drive_accel=None) -> np.ndarray:
    """Twist phi_i = psi_i - psi_drive [rad] of every node over one revolution (n_nodes, n).

    Args:
        shaft: torsion model (:func:`camtrain.camshaft.flexible.torsion_shaft`).
        torques: load torque on the shaft at every force station (n_forces, n_angles) [N m],
            positive in the sense of rotation; a lobe's resisting torque T enters as -T.
        omega: mean camshaft speed [rad/s].
        dampers: :class:`PendulumDamper` s.
        drive_accel: drive angular acceleration over the revolution [rad/s^2]
            (:func:`drive_acceleration`), None = constant speed.
    """
    st = shaft.stations
    n_nodes = st.positions.size
    T = _nodal(n_nodes, st.force_nodes, torques)[shaft.free]
    n = T.shape[-1]
    Jdiag = np.diag(shaft.J)
    if drive_accel is not None:
        T = T - Jdiag[:, None] * np.asarray(drive_accel, dtype=float)[None, :]
    Tk = np.fft.rfft(T, axis=-1)
    orders = np.arange(Tk.shape[-1])
    where = {int(node): i for i, node in enumerate(shaft.free)}
    extra = np.zeros((shaft.free.size, orders.size), dtype=complex)
    for d in dampers:
        if int(d.node) not in where:
            if int(d.node) == shaft.drive_node:
                continue  # on the prescribed drive node a damper changes nothing
            raise field_error("camshaft.damper.node", "no such station", d.node)
        extra[where[int(d.node)]] += d.effective_inertia(orders)
    # every order at once (one batched solve; the chain is small)
    w = orders * omega
    Z = (shaft.K[None] - (w * w)[:, None, None] * shaft.J[None]
         + 1j * w[:, None, None] * shaft.C[None]).astype(complex)
    idx = np.arange(shaft.free.size)
    Z[:, idx, idx] -= (w * w)[:, None] * extra.T
    X = np.linalg.solve(Z, Tk.T[:, :, None])[:, :, 0].T
    phi = np.zeros((n_nodes, n))
    phi[shaft.free] = np.fft.irfft(X, n=n, axis=-1)
    return phi


def lobe_receptance(shaft: BeamShaft, nodes, omega: float, orders) -> np.ndarray:
    """Receptance of one bending plane between force stations: H[k, i, j] [m/N] is the
    deflection of node ``nodes[i]`` at order k under a unit harmonic force at ``nodes[j]``
    (the shaft's dynamic compliance, (K + i k w C - (k w)^2 M)^-1 restricted to those nodes).
    The waveform coupling uses it for its interface Jacobian."""
    from scipy.linalg import solve_banded

    where = {int(dof): i for i, dof in enumerate(shaft.free)}
    rows = np.array([where[int(shaft.v_index[int(n)])] for n in nodes])
    K, M, C = shaft.K, shaft.M, shaft.C
    size = K.shape[0]
    pattern = (np.abs(K) + np.abs(M) + np.abs(C)) != 0
    r, c = np.nonzero(pattern)
    band = int(np.max(np.abs(r - c))) if r.size else 0
    ab = np.zeros((3, 2 * band + 1, size))
    for d in range(-band, band + 1):
        for m, A in enumerate((K, M, C)):
            ab[m, band - d, max(0, d):size + min(0, d)] = np.diagonal(A, d)
    unit = np.zeros((size, rows.size))
    unit[rows, np.arange(rows.size)] = 1.0
    orders = np.asarray(orders)
    H = np.empty((orders.size, rows.size, rows.size), dtype=complex)
    for i, k in enumerate(orders):
        w = float(k) * omega
        X = solve_banded((band, band), ab[0] - (w * w) * ab[1] + 1j * w * ab[2], unit,
                         check_finite=False)
        H[i] = X[rows]
    return H
