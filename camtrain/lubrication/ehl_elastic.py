r"""Elastic deformation of a plane-strain half-space under a line load, in Hertzian units.

With x = b X, p = p_h P, h = (b^2/R) H and p_h = b E'/(4R) (Hertz), the combined normal
deflection of both surfaces (plane strain, E' = 2/[(1-nu1^2)/E1 + (1-nu2^2)/E2]) is

.. math:: V(X) = -\frac{1}{\pi}\int P(S)\,\ln|X - S|\,dS

up to a constant, which the rigid approach H0 absorbs (Johnson 1985, *Contact Mechanics*,
ch. 2, line loading of an elastic half-space; Venner & Lubrecht 2000, ch. 2, in these units).

Discretisation (the documented choice): P is piecewise constant on cells of width dX centred on
the nodes, and the influence coefficient of cell j on node i is the exact integral

.. math:: K_{ij} = \int_{X_j - dX/2}^{X_j + dX/2} \ln|X_i - S|\,dS = F(X_i - X_j + dX/2)
          - F(X_i - X_j - dX/2),\quad F(t) = t\ln|t| - t,

which depends on i - j only (a Toeplitz matrix). The product K P is a *linear* convolution: it
is evaluated by FFT over a zero-padded length >= 2n - 1, which removes the wrap-around
(aliasing) of a circular convolution exactly; the result equals the dense product to rounding.
Cost O(n log n) per evaluation against O(n^2) for the dense sum.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy import fft as sfft
from scipy.linalg import toeplitz

__all__ = ["ElasticKernel", "UnitKernel", "influence_row"]


def _antiderivative(t: np.ndarray) -> np.ndarray:
    """F(t) = t ln|t| - t with F(0) = 0 (its limit)."""
    a = np.abs(t)
    safe = np.where(a > 0.0, a, 1.0)
    return np.where(a > 0.0, t * np.log(safe), 0.0) - t


def influence_row(n: int, dx: float) -> np.ndarray:
    """K(m) for m = 0..n-1 (K is even in m): the exact cell integral of ln|X - S|."""
    m = np.arange(n) * dx
    return _antiderivative(m + 0.5 * dx) - _antiderivative(m - 0.5 * dx)


@dataclass(frozen=True)
class ElasticKernel:
    """The deflection operator of a uniform grid: FFT of the padded kernel, dense on request."""

    n: int
    dx: float
    row: np.ndarray          # K(m), m = 0..n-1
    spectrum: np.ndarray     # rfft of the padded, wrapped kernel
    length: int              # padded FFT length (>= 2n - 1)

    @classmethod
    def of_grid(cls, n: int, dx: float) -> ElasticKernel:
        row = influence_row(n, dx)
        length = sfft.next_fast_len(2 * n - 1, real=True)
        wrapped = np.zeros(length)
        wrapped[:n] = row
        wrapped[length - n + 1:] = row[:0:-1]     # negative lags at the end (K even)
        return cls(n, dx, row, sfft.rfft(wrapped), length)

    def deflection(self, P: np.ndarray) -> np.ndarray:
        """V = -(1/pi) K P by zero-padded FFT (linear, not circular, convolution). numpy's
        FFT: the same pocketfft transform without scipy's backend dispatch, which costs a
        quarter of a 1,024-point transform (the march takes ~1e5 of them per cycle)."""
        conv = np.fft.irfft(np.fft.rfft(P, self.length) * self.spectrum, self.length)[:self.n]
        return conv * (-1.0 / np.pi)

    def dense(self) -> np.ndarray:
        """dV/dP = -(1/pi) K as a dense n x n matrix (for the Newton Jacobian)."""
        return -toeplitz(self.row) / np.pi


class UnitKernel:
    """The influence row, spectrum and dense matrix of unit spacing; a spacing dx scales them.
    The dense matrix (n^2 numbers: 128 MB at 4,096 points) is built, and scaled for a step,
    only when a dense Jacobian asks for it: the matrix-free march never does, and scaling it at
    every step cost O(n^2) per step (measured: a fifth of the march's CPU at 4,096 points)."""

    def __init__(self, n: int):
        self.unit = ElasticKernel.of_grid(n, 1.0)

    @cached_property
    def dense1(self) -> np.ndarray:
        return -toeplitz(influence_row(self.unit.n, 1.0)) / np.pi

    def at(self, dx: float):
        """(the kernel at spacing dx, a callable giving its dense influence on first use)."""
        k = self.unit
        return (ElasticKernel(k.n, dx, dx * k.row, dx * k.spectrum, k.length),
                lambda: dx * self.dense1)
