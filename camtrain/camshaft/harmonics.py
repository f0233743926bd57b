"""Harmonic orders of a camshaft torque by FFT (Williams 2013 §9.2, §2.20: order n = cycles per
camshaft revolution; the tabulated "Fourier component" is the peak amplitude of that order)."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from camtrain.errors import field_error

__all__ = ["Harmonics", "harmonic_orders", "order_curve", "both_banks_amplitude"]


@dataclass(frozen=True)
class Harmonics:
    """Orders of a periodic torque T(theta) = mean + sum A_n cos(n theta + phase_n).

    Attributes:
        order: n = 0, 1, ..., N/2 (cycles per camshaft revolution).
        amplitude: A_n [N m] (peak, not rms); A_0 = |mean|.
        phase: phase_n [rad].
        mean: mean torque [N m] (zero for a frictionless camshaft: no net work per revolution).
    """

    order: np.ndarray
    amplitude: np.ndarray
    phase: np.ndarray
    mean: float

    def __getitem__(self, n: int) -> float:
        return float(self.amplitude[int(n)])


def harmonic_orders(torque) -> Harmonics:
    """FFT of one camshaft revolution sampled on a uniform grid (theta_k = 2 pi k / N).

    A_n = 2 |X_n| / N for 0 < n < N/2, A_n = |X_n|/N at n = 0 and at the Nyquist order.
    """
    y = np.asarray(torque, dtype=float)
    if y.ndim != 1 or y.size < 4 or not np.all(np.isfinite(y)):
        raise field_error("torque", "must be a finite 1-D array of >= 4 samples per revolution")
    n = y.size
    x = np.fft.rfft(y) / n
    amp = 2.0 * np.abs(x)
    amp[0] = abs(x[0].real)
    if n % 2 == 0:
        amp[-1] = np.abs(x[-1])
    return Harmonics(order=np.arange(x.size), amplitude=amp, phase=np.angle(x),
                     mean=float(x[0].real))


def order_curve(h: Harmonics, orders, n: int) -> np.ndarray:
    """Sum of the chosen orders as a curve on an ``n``-point grid [N m] (no mean)."""
    th = np.arange(n) * (2.0 * np.pi / n)
    orders = np.atleast_1d(orders).astype(int)
    if np.any(orders < 1) or np.any(orders >= h.order.size):
        raise field_error("orders", "out of range", orders.tolist(), f"1..{h.order.size - 1}")
    return np.sum([h.amplitude[k] * np.cos(k * th + h.phase[k]) for k in orders], axis=0)


def both_banks_amplitude(one_bank_amplitude, order, v_angle):
    """Order amplitude of two identical banks V crank radians apart: 2 |cos(n V / 4)| A_n.

    Follows from TqBank2(theta) = TqBank1(theta + V/2) (Williams App 7); at V = 90 deg the
    orders 4 and 12 cancel and 8 and 16 double (Williams Tables 9.5-9.8).
    """
    return 2.0 * np.abs(np.cos(np.asarray(order) * np.asarray(v_angle) / 4.0)) * np.asarray(
        one_bank_amplitude, dtype=float)
