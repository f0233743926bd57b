"""Compiled revolution of the shaft-and-trains march (numba, cached on disk) for
:mod:`camtrain.dynamics.monolithic`: every step's friction from each contact's last load, or
its last load and level-1 squeeze film (:mod:`._coupled_film_kernel`), and the drive's hub
load, both explicit by one step; the step itself (:mod:`._coupled_step`: Newmark average
acceleration, the closed contacts as a low-rank update, contact changes located inside the
step), monolithic or staggered with its passes (:mod:`._coupled_partition`); the film of every
contact marched once per accepted step; the grid samples. Only the compiled kernels import
numba."""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from camtrain.dynamics._coupled_film_kernel import film_step, table_coefficient
from camtrain.dynamics._coupled_lowrank import basis_rows
from camtrain.dynamics._coupled_partition import predict_loads
from camtrain.dynamics._coupled_step import advance, cam_gap
from camtrain.numerics.compile_notice import announce


@njit(cache=True)
def _coefficient(table, j, s, ln_first, ln_step, w):
    """Friction coefficient of lobe j at step s under the load w [N]: linear in ln w between
    the table's load levels (first level e^ln_first, ratio e^ln_step), held beyond them."""
    levels = table.shape[1]
    if levels == 1 or w <= 0.0:
        return table[j, 0, s]
    x = (np.log(w) - ln_first) / ln_step
    if x <= 0.0:
        return table[j, 0, s]
    if x >= levels - 1:
        return table[j, levels - 1, s]
    i = int(x)
    t = x - i
    return (1.0 - t) * table[j, i, s] + t * table[j, i + 1, s]


@njit(cache=True)
def _film_coefficient(table, col, unit_film, exponent, w, h, ln_first, ln_step, ln_r0, d_ln_r):
    """Friction coefficient under the cam-level load ``w`` [N] with the film ``h`` [m]: from
    the table over film ratios h/F and loads (F = ``unit_film`` w^``exponent`` the steady
    film), ``col`` the fractional grid column of the angle."""
    if w <= 0.0:
        return 0.0
    F = unit_film * w ** exponent
    ln_r = math.log(h / F) if 0.0 < F < math.inf else 0.0
    return table_coefficient(table, col, math.log(w), ln_r, ln_first, ln_step, ln_r0, d_ln_r)


@njit(cache=True)
def revolution(q, v, acc, act_c, act_s, w_prev, x_f0, P, Q, blocks, ainv_basis, K, C, M, Minv,
               f0, b, bd, gx, gy, gphi, fric_tab, fric_corr, ln_first, ln_step, arm, ratio, cosa,
               sina, turn, kc, cc, ks, cs, offc, offs, a0, a1, dt, ix, iy, iphi, ifol, ival,
               valve_dof, substeps, out_load, out_acc, film_on, squeeze_on, film_h, film_a, film_e,
               film_speed, film_tab, film_col, ln_r0, d_ln_r, out_film, hub_basis, hub_x, hub_y,
               hub_cos, hub_sin, hub_radius, stagger, predictor, iterations, step_tol, w_older,
               drive_u, drive_j, drive_acc):
    """March one revolution (steps = b.shape[1]); write the grid samples (every ``substeps``
    steps) into ``out_load``/``out_acc`` (n_lobes x grid). Friction: the coefficient of lobe j
    at step s under load w from ``fric_tab`` (n_lobes, levels, steps) by :func:`_coefficient`
    plus ``fric_corr`` (n_lobes, steps), times the last step's load. State arrays (q, v, acc, the contact
    states act_c/act_s, the last loads w_prev) are updated in place. ``P`` = A^-1 M and
    ``Q`` = A^-1 C are block diagonal (shaft planes, twist, each train): ``blocks`` holds the
    block boundaries, so only the diagonal blocks are multiplied.

    Level-1 squeeze film (``film_on``): ``film_h`` (n_lobes) is every contact's film [m], carried
    from step to step and updated once per accepted step by :func:`film_step` (implicit Euler
    of Teodorescu's eq. 5 as a relaxation law) towards the steady film F = ``film_a`` (W R)^
    ``film_e`` of the step's end load (``squeeze_on`` False: h = F, the quasi-steady limit),
    with the entrainment speed ``film_speed`` (n_lobes, steps). The friction coefficient is
    then read from ``film_tab`` (film ratios h/F, load levels, grid angles of the lobe's own
    frame; ``film_col`` (n_lobes, steps) the fractional column of each step) at the last load
    and film, plus ``fric_corr``; the film at the grid samples goes to ``out_film``.

    Drive hub load (``hub_x`` >= 0: the drive station's bending coordinates): the belt's
    tight-minus-slack part |T| / ``hub_radius`` along (``hub_cos``, ``hub_sin``), T the summed
    lobe torque W l' + mu W r of the last step (explicit by one step, as the friction; the
    preload part is constant and sits in ``f0``); ``hub_basis`` holds A^-1 at those two
    coordinates.

    Drive speed oscillation: ``drive_acc`` (steps) the drive's angular acceleration at every
    step's end (zeros at constant speed), ``drive_j``, ``drive_u`` as in :func:`advance`; the
    inputs b ... are then those of the oscillating drive angle.

    Staggered (``stagger``; :mod:`._coupled_partition`): every step advances the shaft under
    each contact's predicted load (``predictor`` 0: the last step's, 1: extrapolated from the
    last two, ``w_older`` the one before ``w_prev``) and then every train with the shaft's new
    lobe motion as prescribed input; up to ``iterations`` passes of a step, each predicting the
    load the last produced, until they agree within ``step_tol`` of the largest load (at least
    1 N).

    Returns the contact changes located in the revolution, the steps that had more than
    MAX_SWITCHES and the staggered steps whose passes did not agree within ``iterations``."""
    n = q.size
    lobes = ix.size
    steps = b.shape[1]
    grid = out_load.shape[1]
    rhs_w = np.empty(n)
    rhs_c = np.empty(n)
    base = np.empty(n)
    x = np.empty(n)
    v1 = np.empty(n)
    a1v = np.empty(n)
    fric = np.zeros(n)
    fr_j = np.zeros(lobes)
    tang_j = np.zeros(lobes)
    arm_j = np.zeros(lobes)
    bj = np.empty(lobes)
    bdj = np.empty(lobes)
    gxj = np.empty(lobes)
    gyj = np.empty(lobes)
    gphij = np.empty(lobes)
    b0 = np.empty(lobes)
    bd0 = np.empty(lobes)
    switches_total = 0
    cut = 0
    missed = 0
    G = basis_rows(ainv_basis, ix, iy, iphi, ifol, ival)
    zf = np.zeros(5 * lobes)
    hub = np.zeros(2)
    w_pred = np.zeros(lobes)
    w_end = np.zeros(lobes)
    be = np.empty(lobes)
    bde = np.empty(lobes)
    zero = np.zeros(lobes)
    q_s, v_s, acc_s = np.empty(n), np.empty(n), np.empty(n)
    c_s = np.empty(lobes, dtype=np.bool_)
    s_s = np.empty(lobes, dtype=np.bool_)
    for s in range(steps):
        # friction of every lobe from its last load (explicit): constant over the step
        torque = 0.0
        for j in range(lobes):
            if film_on:
                mu = _film_coefficient(film_tab, film_col[j, s], film_a[j, s], film_e,
                                       ratio[j, s] * w_prev[j], film_h[j], ln_first, ln_step, ln_r0,
                                       d_ln_r) + fric_corr[j, s]
            else:
                mu = _coefficient(fric_tab, j, s, ln_first, ln_step, w_prev[j]) + fric_corr[j, s]
            fr_j[j] = mu * ratio[j, s] * w_prev[j]
            torque += w_prev[j] * gphi[j, s] + fr_j[j] * arm[j, s]
            sgn = 1.0 if arm[j, s] >= 0 else -1.0
            tang_j[j] = -turn * fr_j[j] * sgn
            arm_j[j] = arm[j, s]
            bj[j], bdj[j], gxj[j], gyj[j], gphij[j] = b[j, s], bd[j, s], gx[j, s], gy[j, s], \
                gphi[j, s]
        if stagger:
            for i in range(n):
                q_s[i], v_s[i], acc_s[i] = q[i], v[i], acc[i]
            for j in range(lobes):
                c_s[j], s_s[j] = act_c[j], act_s[j]
            predict_loads(w_prev, w_older, predictor, w_pred)
        for it in range(iterations if stagger else 1):
            if it > 0:      # again from the step's start, with the load it produced
                for i in range(n):
                    q[i], v[i], acc[i] = q_s[i], v_s[i], acc_s[i]
                for j in range(lobes):
                    act_c[j], act_s[j] = c_s[j], s_s[j]
                    w_pred[j] = w_end[j]
            located, over = advance(
                s, q, v, acc, act_c, act_s, x_f0, P, Q, blocks, ainv_basis, G, K, C, M, Minv, f0,
                b, bd, gx, gy, gphi, kc, cc, ks, cs, offc, offs, a0, a1, dt, ix, iy, iphi, ifol,
                ival, fr_j, tang_j, arm_j, cosa, sina, bj, bdj, gxj, gyj, gphij, b0, bd0, zf,
                fric, hub, torque, hub_basis, hub_x, hub_y, hub_cos, hub_sin, hub_radius, stagger,
                w_pred, rhs_w, rhs_c, base, x, v1, a1v, be, bde, zero, it == 0, drive_u,
                drive_j, drive_acc[s])
            if not stagger or iterations == 1:
                break
            gap, top = 0.0, 1.0
            for j in range(lobes):
                w = 0.0
                if act_c[j]:
                    d, dd = cam_gap(q, v, bj[j], bdj[j], gxj[j], gyj[j], gphij[j], offc, ix, iy,
                                     iphi, ifol, j)
                    w = max(kc * d + cc * dd, 0.0)
                w_end[j] = w
                gap = max(gap, abs(w - w_pred[j]))
                top = max(top, w)
            if gap <= step_tol * top:
                break
            if it == iterations - 1:
                missed += 1
        switches_total += located
        cut += over
        for j in range(lobes):
            w_older[j] = w_prev[j]
        # the loads at the step's end
        for j in range(lobes):
            w = 0.0
            if act_c[j]:
                d, dd = cam_gap(q, v, bj[j], bdj[j], gxj[j], gyj[j], gphij[j], offc, ix, iy,
                                 iphi, ifol, j)
                w = kc * d + cc * dd
            w_prev[j] = w if w > 0.0 else 0.0
            if film_on:     # the film of the accepted step, at its end load and speed
                wc = ratio[j, s] * w_prev[j]
                F = film_a[j, s] * wc ** film_e if wc > 0.0 else math.inf
                if squeeze_on:
                    film_h[j] = film_step(film_h[j], F, film_speed[j, s], dt)
                elif 0.0 < F < math.inf:
                    film_h[j] = F
        if (s + 1) % substeps == 0:
            g = ((s + 1) // substeps) % grid
            for j in range(lobes):
                out_load[j, g] = w_prev[j]
                out_acc[j, g] = acc[valve_dof[j]]
                if film_on:
                    out_film[j, g] = film_h[j]
    return switches_total, cut, missed


announce("shaft-and-trains", (revolution,))
