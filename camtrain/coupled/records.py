"""Typed records of the compiled shaft-and-trains march (:mod:`._revolution`, :mod:`._step`),
grouped by lifetime (named tuples: see :mod:`camtrain.dynamics.records` for why, and the
records the single train's march shares with this one).

Set once per march:

* :data:`System` = (:data:`Layout`, :data:`Matrices`, :data:`Stepper`, :data:`Drive`,
  :class:`~camtrain.dynamics.records.Unilateral`): where every lobe's coordinates sit, the
  linear part's matrices, the full step's factorised parts, the drive's hub load and inertia
  load, the contact laws of every train (cam, seat).
* :data:`Lobes`: every lobe's inputs at every step of a revolution.
* :data:`Scheme`: monolithic or staggered, its predictor and passes.

Set once per revolution: :data:`Friction` (the tables and their correction).
Carried from step to step: :data:`State`. Written: :data:`Samples`.
Workspace of one revolution: :data:`Work` (with the contact update's :data:`Update`) and two
:data:`LobeAt` (every lobe's inputs at an instant of the step, and the staggered step's
prescribed inputs).

A new term of the march is a new field of the record of its lifetime.
"""
from __future__ import annotations

from collections import namedtuple

import numpy as np

#: state indices of every lobe's shaft coordinates (ix, iy, iphi), follower (ifol), seat
#: (ival), valve (valve), the block boundaries of the block-diagonal linear part and every
#: lobe's lash-adjuster plunger (ipl; empty without adjusters)
Layout = namedtuple("Layout", "ix iy iphi ifol ival valve blocks ipl")

#: the linear part: K, C, M transposed (KT, CT, MT), the block-diagonal inverse of M (Minv)
#: and its transpose (MinvT), the constant forces f0. The step's block products run along
#: rows of the transposes (contiguous, so the compiler vectorises them); every entry of a
#: product sums its terms in the same order as a row of the matrix would
Matrices = namedtuple("Matrices", "KT CT MT Minv MinvT f0")

#: the full Newmark step: dt, a0 = 4/dt^2, a1 = 2/dt, A^-1 f0, P = A^-1 M and Q = A^-1 C
#: transposed (PT, QT: see Matrices), the
#: columns of A^-1 at every lobe's contact coordinates stored as rows (basis, W L x n: the
#: update's x0 + basis^T z runs along contiguous rows, which the compiler vectorises) and
#: their entries at those coordinates (G)
Stepper = namedtuple("Stepper", "dt a0 a1 x_f0 PT QT basis G")

#: the drive: hub-load coordinates (x, y; -1 without), direction (cos, sin), pitch radius,
#: A^-1 at the two coordinates (basis); J 1 on the twist (j) and A^-1 of it (u)
Drive = namedtuple("Drive", "x y cos sin radius basis j u")

#: everything set once: Layout, Matrices, Stepper, Drive, Unilateral (uni), the lash
#: adjuster of every train (a :data:`camtrain.dynamics.records.Hydraulic`, ``on`` 0 without)
System = namedtuple("System", "lay mats step drive uni hla")

#: every lobe's inputs at every step (lobes, steps): valve-referred lift b, its rate bd, the
#: contact gradient (gx, gy, gphi), friction arm, rocker ratio; follower axes (cosa, sina),
#: the turn (+1 anticlockwise), the drive's angular acceleration at every step (drive_acc)
Lobes = namedtuple("Lobes", "b bd gx gy gphi arm ratio cosa sina turn drive_acc")

#: friction tables: coefficient (lobes, levels, steps), its correction (lobes, steps), the
#: load levels (ln_first, ln_step); the level-1 film (film, squeeze flags; steady film under
#: 1 N ``unit`` and ``speed`` (lobes, steps), ``exponent``, ``film_table`` (ratios, levels,
#: grid), fractional grid column ``col`` (lobes, steps), film ratios ln_r0, d_ln_r)
Friction = namedtuple("Friction", "table corr ln_first ln_step film squeeze unit exponent speed "
                                  "film_table col ln_r0 d_ln_r")

#: stagger (bool), predictor code, passes per step at most, their tolerance, steps per sample
Scheme = namedtuple("Scheme", "stagger predictor iterations step_tol substeps")

#: q, v, acc, the contact states (act_c, act_s), the last two steps' loads, the films; every
#: adjuster's chamber ``hp`` (lobes, 4: pressure, check-valve and leak flows, last pressure
#: rate, as the single train's) and its value at the trial step's end ``hp_end``
State = namedtuple("State", "q v acc act_c act_s w_prev w_older film hp hp_end")

#: the grid samples (lobes, grid): load, valve acceleration, film; every adjuster's chamber
#: pressure and plunger extension (lobes, 2, grid)
Samples = namedtuple("Samples", "load acc film hla")

#: every lobe's inputs at an instant: b, bd, gx, gy, gphi (arrays over the lobes)
LobeAt = namedtuple("LobeAt", "b bd gx gy gphi")

#: the low-rank contact update's workspace (:mod:`._lowrank`; W coordinates per lobe, 5 or 6
#: with lash adjusters): every lobe's state indices ``dof`` (L, W), the closed contacts'
#: gradients ``coef`` (2 L, W), lobes ``lobe_of`` and stiffnesses ``kk`` (2 L), their small
#: system ``small`` (flat, (2 L)^2) and its right-hand side ``rhs`` (2 L), the coordinates'
#: values ``xc`` (W L)
Update = namedtuple("Update", "dof coef lobe_of kk small xc rhs")

#: work arrays of a revolution (n: state size, L: lobes) and the contact update's (``upd``)
Work = namedtuple("Work", "rhs_w rhs_c base x v1 a1v fric zf hub fr tang arm b0 bd0 w_pred "
                          "w_end q_s v_s acc_s c_s s_s hp_s upd")


def workspace(n: int, dof: np.ndarray):
    """(Work, the inputs at the step's end, the staggered step's prescribed inputs); ``dof``
    every lobe's state indices in the contact update (lobes, width: 5 coordinates per lobe,
    6 with lash adjusters)."""
    e, z = np.empty, np.zeros
    lobes, width = dof.shape
    upd = Update(dof, z((2 * lobes, width)), z(2 * lobes, dtype=np.int64), z(2 * lobes),
                 z(4 * lobes * lobes), z(width * lobes), z(2 * lobes))
    work = Work(e(n), e(n), e(n), e(n), e(n), e(n), z(n), z(width * lobes), z(2), z(lobes),
                z(lobes), z(lobes), e(lobes), e(lobes), z(lobes), z(lobes), e(n), e(n), e(n),
                e(lobes, dtype=np.bool_), e(lobes, dtype=np.bool_), z((lobes, 4)), upd)
    at = LobeAt(e(lobes), e(lobes), e(lobes), e(lobes), e(lobes))
    pre = LobeAt(e(lobes), e(lobes), z(lobes), z(lobes), z(lobes))
    return work, at, pre
