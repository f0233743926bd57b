"""The coupled step's block products (camtrain/coupled/_step.py) run along rows of the transposed
matrices, one column's terms added to every row at a time, so that the compiler vectorises them.
Each entry must still sum the same terms in the same order as its row's sum would, which is what
keeps the coupled march's numbers the same to the bit: checked here against that row sum written
out term by term, with exact equality, on random blocks."""
from __future__ import annotations

import numpy as np

from camtrain.coupled._step import _block_matrix, _block_rhs
from camtrain.coupled.records import Matrices

BLOCKS = np.array([0, 7, 19, 24])


def _matrices(rng, n):
    K, C, M, Minv = (rng.standard_normal((n, n)) for _ in range(4))
    tr = np.ascontiguousarray
    return (K, C, M), Matrices(tr(K.T), tr(C.T), tr(M.T), Minv, tr(Minv.T),
                               rng.standard_normal(n))


def test_block_matrix_is_k_plus_a1_c_plus_a0_m_to_the_bit():
    rng = np.random.default_rng(3)
    (K, C, M), mats = _matrices(rng, BLOCKS[-1])
    a0, a1 = 4.0 / 0.37 ** 2, 2.0 / 0.37
    for lo, hi in zip(BLOCKS[:-1], BLOCKS[1:], strict=True):
        A = _block_matrix(mats, lo, hi, a0, a1)
        b = slice(lo, hi)
        assert np.array_equal(A, K[b, b] + a1 * C[b, b] + a0 * M[b, b])


def test_block_rhs_sums_every_row_in_column_order_to_the_bit():
    rng = np.random.default_rng(4)
    n = BLOCKS[-1]
    (_, C, M), mats = _matrices(rng, n)
    fric, wv, cv = (rng.standard_normal(n) for _ in range(3))
    for lo, hi in zip(BLOCKS[:-1], BLOCKS[1:], strict=True):
        R = _block_rhs(mats, fric, wv, cv, lo, hi, 2)
        for i in range(lo, hi):
            row = mats.f0[i] + fric[i]
            for e in range(lo, hi):
                row += M[i, e] * wv[e] + C[i, e] * cv[e]
            assert R[i - lo, 0] == row
        assert R.shape == (hi - lo, 3) and not R[:, 1:].any()
