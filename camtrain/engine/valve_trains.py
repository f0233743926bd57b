"""The valve-train share of an engine's friction (Yang 1992 Part IV, Fig. 4.7): what one
valve-train run hands to the FLAME total.

Per camshaft: the cams and followers (the cycle-mean camshaft drive power over all lobes: the
spring work averages out, friction remains), the camshaft bearings, and the follower/guide and
valve/guide shear of every valve train (per-train values times the lobes). A deck without a
camshaft stands for ``trains`` identical cams.
"""
from __future__ import annotations

from dataclasses import dataclass


def valve_train_parts(metrics: dict, lobes: int | None, trains: int = 1) -> dict:
    """Friction power [W] by part from a valve-train run's metrics (name -> value in W): the
    cams (the camshaft's drive, or the cam contact's friction power, which for a turning
    roller holds its pin loss), the camshaft bearings, the guides and, for a pivoted follower
    with [mechanism.arm], its valve pad and pivot ("arms", not in the cam's power).

    ``lobes``: the lobe count of its camshaft, or None for a single-cam deck (then ``trains``
    copies of it).
    """
    if lobes is not None and "drive_power_mean" in metrics:
        parts = {"cams": metrics["drive_power_mean"],
                 "bearings": metrics.get("bearings_power_total", 0.0)}
        count = lobes
    else:
        parts = {"cams": trains * metrics.get("power_loss_mean", 0.0), "bearings": 0.0}
        count = trains
    parts["guides"] = count * metrics.get("guide_power_mean", 0.0)
    if "arm_power_mean" in metrics:   # a finger's or rocker's valve pad and pivot (one train)
        parts["arms"] = count * metrics["arm_power_mean"]
    return parts


@dataclass(frozen=True)
class ValveTrainFriction:
    """Friction power of each included valve train at the engine's speed: ``parts`` name ->
    {cams, bearings, guides} [W]; ``camshaft_speed`` name -> [rad/s]; ``notes`` name -> what
    was left out (warnings of the nested run)."""

    parts: dict
    camshaft_speed: dict
    notes: dict

    def power(self, name: str) -> float:
        """Total friction power [W] of one valve train."""
        return float(sum(self.parts[name].values()))

    @property
    def total(self) -> float:
        """Friction power of every valve train [W]."""
        return float(sum(self.power(n) for n in self.parts))
