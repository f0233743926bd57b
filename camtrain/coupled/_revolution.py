"""Compiled revolution of the shaft-and-trains march (numba, cached on disk) for
:mod:`camtrain.coupled.march`: every step's friction from each contact's last load, or its last
load and level-1 squeeze film (:mod:`._film_kernel`), and the drive's hub load, both explicit by
one step; the step itself (:mod:`._step`: Newmark average acceleration, the closed contacts as a
low-rank update, contact changes located inside the step), monolithic or staggered with its
passes (:mod:`._partition`); the film of every contact marched once per accepted step; the grid
samples. The data come as the records of :mod:`.records`. Only the compiled kernels import
numba.

The functions every step runs that take the whole ``System`` (here and in :mod:`._step`) are
inlined into the revolution (``inline="always"``): numba hands a record to a compiled call as its
fields one by one, and at every step that cost the four-train benchmark problem's revolution
about a tenth of its time. The work of a contact change (:func:`._step._split` and its
sub-steps) stays a call: it runs at a change only (276 of 8,640 steps of that problem's
revolution), and inlined it made the code compiled bigger (first call 79 against 66 s CPU)
for no gain in speed.

Why the block products run along rows of transposed matrices with unsigned indices
(:data:`.records.Matrices`, :data:`.records.Stepper`): a row's sum is a chain of dependent
additions, and a signed index is checked for wrapping at every term; the update of all rows
by one column at a time vectorises, and every entry still sums the same terms in the same
order, so the numbers are the same to the bit. The four-train problem's warm revolution went
from 145-155 to 86-88 ms."""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from camtrain.coupled._film_kernel import film_step, table_coefficient
from camtrain.coupled._lowrank import contact_laws
from camtrain.coupled._partition import predict_loads
from camtrain.coupled._step import advance, cam_gap, gap_of
from camtrain.coupled.adjuster_step import sample_chambers
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


@njit(cache=True, inline="always")
def _step_friction(s, lob, fric, st, work, at):
    """Every lobe's friction from its last load (explicit: constant over the step) into
    ``work`` (fr, tang, arm), its inputs at the step's end into ``at``; returns the summed
    lobe torque W l' + mu W r of the last step."""
    w_prev, ratio, arm = st.w_prev, lob.ratio, lob.arm
    torque = 0.0
    for j in range(w_prev.size):
        if fric.film:
            mu = _film_coefficient(fric.film_table, fric.col[j, s], fric.unit[j, s],
                                   fric.exponent, ratio[j, s] * w_prev[j], st.film[j],
                                   fric.ln_first, fric.ln_step, fric.ln_r0, fric.d_ln_r) \
                + fric.corr[j, s]
        else:
            mu = _coefficient(fric.table, j, s, fric.ln_first, fric.ln_step, w_prev[j]) \
                + fric.corr[j, s]
        work.fr[j] = mu * ratio[j, s] * w_prev[j]
        torque += w_prev[j] * lob.gphi[j, s] + work.fr[j] * arm[j, s]
        sgn = 1.0 if arm[j, s] >= 0 else -1.0
        work.tang[j] = -lob.turn * work.fr[j] * sgn
        work.arm[j] = arm[j, s]
        at.b[j], at.bd[j], at.gx[j], at.gy[j], at.gphi[j] = lob.b[j, s], lob.bd[j, s], \
            lob.gx[j, s], lob.gy[j, s], lob.gphi[j, s]
    return torque


@njit(cache=True, inline="always")
def _passes(s, sys, lob, scheme, st, work, at, pre, torque, laws):
    """Step s: once (monolithic), or staggered passes until the load a pass produces agrees
    with its prediction within ``scheme.step_tol`` of the largest load (at least 1 N), each
    pass again from the step's start with the load the last one produced. Returns the contact
    changes located, the steps cut short, the missed steps."""
    stagger, iterations = scheme.stagger, scheme.iterations
    q, v, acc, act_c, act_s = st.q, st.v, st.acc, st.act_c, st.act_s
    lay, uni = sys.lay, sys.uni
    kc, cc, offc = uni.k[0], uni.c[0], uni.off[0]
    if stagger:     # the step's start, for its further passes
        for i in range(q.size):
            work.q_s[i], work.v_s[i], work.acc_s[i] = q[i], v[i], acc[i]
        for j in range(act_c.size):
            work.c_s[j], work.s_s[j] = act_c[j], act_s[j]
        work.hp_s[:] = st.hp
        predict_loads(st.w_prev, st.w_older, scheme.predictor, work.w_pred)
    missed = 0
    located, over = 0, 0
    for it in range(iterations if stagger else 1):
        if it > 0:      # again from the step's start, with the load it produced
            for i in range(q.size):
                q[i], v[i], acc[i] = work.q_s[i], work.v_s[i], work.acc_s[i]
            for j in range(act_c.size):
                act_c[j], act_s[j] = work.c_s[j], work.s_s[j]
                work.w_pred[j] = work.w_end[j]
            st.hp[:] = work.hp_s
        located, over = advance(s, sys, st, work, at, pre, lob, torque, stagger, it == 0, laws)
        if not stagger or iterations == 1:
            break
        gap, top = 0.0, 1.0
        for j in range(act_c.size):
            w = 0.0
            if act_c[j]:
                d, dd = cam_gap(q, v, j, lay.ix, lay.iy, lay.iphi, lay.ifol, offc, at.b[j],
                                at.bd[j], at.gx[j], at.gy[j], at.gphi[j])
                w = max(kc * d + cc * dd, 0.0)
            work.w_end[j] = w
            gap = max(gap, abs(w - work.w_pred[j]))
            top = max(top, w)
        if gap <= scheme.step_tol * top:
            break
        if it == iterations - 1:
            missed += 1
    return located, over, missed


@njit(cache=True, inline="always")
def _end_of_step(s, sys, lob, fric, st, at, dof, laws):
    """The loads at the accepted step's end (never a pull) and every contact's film, marched
    at its end load and speed (``dof`` every lobe's state indices, ``laws`` the contact laws
    as numbers)."""
    dt = sys.step.dt
    kc, cc, offc = laws[0], laws[1], laws[2]
    q, v = st.q, st.v
    for j in range(st.w_prev.size):
        st.w_older[j] = st.w_prev[j]
    for j in range(st.w_prev.size):
        w = 0.0
        if st.act_c[j]:
            ix, iy, iphi, ifol = dof[j, 0], dof[j, 1], dof[j, 2], dof[j, 3]
            gx, gy, gphi = at.gx[j], at.gy[j], at.gphi[j]
            d = gap_of(at.b[j] + offc, gx, gy, gphi, q[ix], q[iy], q[iphi], q[ifol])
            dd = gap_of(at.bd[j], gx, gy, gphi, v[ix], v[iy], v[iphi], v[ifol])
            w = kc * d + cc * dd
        st.w_prev[j] = w if w > 0.0 else 0.0
        if fric.film:     # the film of the accepted step, at its end load and speed
            wc = lob.ratio[j, s] * st.w_prev[j]
            F = fric.unit[j, s] * wc ** fric.exponent if wc > 0.0 else math.inf
            if fric.squeeze:
                st.film[j] = film_step(st.film[j], F, fric.speed[j, s], dt)
            elif 0.0 < F < math.inf:
                st.film[j] = F


@njit(cache=True)
def revolution(sys, lob, fric, scheme, st, out, work, at, pre):
    """March one revolution (steps = lob.b.shape[1]); write the grid samples (every
    ``scheme.substeps`` steps) into ``out`` (lobes x grid). Friction: the coefficient of lobe
    j at step s under load w from ``fric.table`` (lobes, levels, steps) by
    :func:`_coefficient` plus ``fric.corr`` (lobes, steps), times the last step's load; the
    state ``st`` is updated in place. ``P`` = A^-1 M and ``Q`` = A^-1 C are block diagonal
    (shaft planes, twist, each train): ``sys.lay.blocks`` holds the block boundaries, so only
    the diagonal blocks are multiplied.

    Level-1 squeeze film (``fric.film``): ``st.film`` (lobes) is every contact's film [m],
    carried from step to step and updated once per accepted step by :func:`film_step`
    (implicit Euler of Teodorescu's eq. 5 as a relaxation law) towards the steady film F =
    ``fric.unit`` (W R)^``fric.exponent`` of the step's end load (``fric.squeeze`` False:
    h = F, the quasi-steady limit), with the entrainment speed ``fric.speed``. The friction
    coefficient is then read from ``fric.film_table`` (film ratios h/F, load levels, grid
    angles of the lobe's own frame; ``fric.col`` the fractional column of each step) at the
    last load and film, plus ``fric.corr``; the film at the grid samples goes to ``out.film``.

    Drive hub load (``sys.drive.x`` >= 0: the drive station's bending coordinates): the
    belt's tight-minus-slack part |T| / radius along (cos, sin), T the summed lobe torque of
    the last step (explicit by one step, as the friction; the preload part is constant and
    sits in f0). Drive speed oscillation: ``lob.drive_acc`` the drive's angular acceleration
    at every step's end (zeros at constant speed); the inputs are then those of the
    oscillating drive angle.

    Staggered (``scheme.stagger``; :mod:`._partition`): every step advances the shaft under
    each contact's predicted load (``scheme.predictor`` 0: the last step's, 1: extrapolated
    from the last two) and then every train with the shaft's new lobe motion as prescribed
    input; up to ``scheme.iterations`` passes of a step, each predicting the load the last
    produced, until they agree within ``scheme.step_tol`` of the largest load (at least 1 N).

    Returns the contact changes located in the revolution, the steps that had more than
    MAX_SWITCHES and the staggered steps whose passes did not agree within the passes."""
    grid = out.load.shape[1]
    substeps = scheme.substeps
    switches_total, cut, missed = 0, 0, 0
    laws, dof = contact_laws(sys.uni), work.upd.dof
    for s in range(lob.b.shape[1]):
        torque = _step_friction(s, lob, fric, st, work, at)
        located, over, miss = _passes(s, sys, lob, scheme, st, work, at, pre, torque, laws)
        switches_total += located
        cut += over
        missed += miss
        _end_of_step(s, sys, lob, fric, st, at, dof, laws)
        if (s + 1) % substeps == 0:
            g = ((s + 1) // substeps) % grid
            for j in range(st.w_prev.size):
                out.load[j, g] = st.w_prev[j]
                out.acc[j, g] = st.acc[sys.lay.valve[j]]
                if fric.film:
                    out.film[j, g] = st.film[j]
            if sys.hla.on:
                sample_chambers(sys.hla, st.hp, st.q, sys.lay.ifol, sys.lay.ipl, out.hla, g)
    return switches_total, cut, missed


announce("shaft-and-trains", (revolution,))
