"""The FLAME engine total (Yang 1992 Part IV): friction of a whole engine from its components.

The components run independently, each with its own effective viscosity (no coupling):
bearings + valve trains + piston assemblies, plus accessories taken as a fixed share of that sum
(Yang: 20 % of the total, i.e. 0.25 x the components). A partially grooved main bearing set is
the mean of the ungrooved and fully grooved totals (Yang's Table 7.1 bearing column, exact at
3000 and 6000 rpm). The friction mean effective pressure is not in Yang; it is the usual
fmep = P n_R / (V_d N), n_R = 2 crank revolutions per cycle for a 4-stroke engine.
"""
from __future__ import annotations

from dataclasses import dataclass

#: Yang Part IV: accessories are 20 % of the total, i.e. 0.25 x the component sum.
YANG1992_ACCESSORY_SHARE = 0.25


def partial_groove_mean(ungrooved: float, grooved: float) -> float:
    """Bearing loss of partially grooved mains: the mean of the two extremes (Yang Table 7.1)."""
    return 0.5 * (ungrooved + grooved)


def accessories(components: float, share: float = YANG1992_ACCESSORY_SHARE) -> float:
    """Accessory loss [W] as a share of the component sum (Yang Part IV)."""
    return share * components


def fmep(power: float, displacement: float, engine_speed: float, strokes: int = 4) -> float:
    """Friction mean effective pressure [Pa] from friction power [W], swept volume [m^3] and
    engine speed [rev/s]; ``strokes`` 4 (two revolutions per cycle) or 2."""
    if strokes not in (2, 4):
        raise ValueError(f"strokes must be 2 or 4, got {strokes!r}")
    return power * (strokes // 2) / (displacement * engine_speed)


@dataclass(frozen=True)
class FlameTotal:
    """One speed of the FLAME table [W]: components, accessories, total, shares, fmep [Pa]."""

    bearings: float
    valve_train: float
    piston: float
    accessories: float
    total: float
    fmep: float

    def share(self, component: str, with_accessories: bool = False) -> float:
        """A component's share of the total (or of the component sum without accessories)."""
        value = getattr(self, component)
        return value / (self.total if with_accessories else self.total - self.accessories)


def flame_total(bearings: float, valve_train: float, piston: float, *, displacement: float,
                engine_speed: float, strokes: int = 4,
                accessory_share: float = YANG1992_ACCESSORY_SHARE) -> FlameTotal:
    """Sum the components of one speed as FLAME does (Yang Part IV)."""
    components = bearings + valve_train + piston
    extra = accessories(components, accessory_share)
    total = components + extra
    return FlameTotal(bearings, valve_train, piston, extra, total,
                      fmep(total, displacement, engine_speed, strokes))


def treatment_totals(bearings, method: str = "dynamic") -> dict:
    """Engine bearing totals [W] per grooving treatment ({'ungrooved': W, 'grooved': W} as
    solved) of an :class:`~camtrain.engine.crank_bearings.EngineBearings`; a bearing solved in
    one treatment only counts in both."""
    out: dict = {}
    for b in bearings.bearings:
        tags = set(b.variants)
        for tag in ("ungrooved", "grooved"):
            v = b.variants[tag] if tag in tags else next(iter(b.variants.values()))
            x = getattr(v, method)
            if x is None:
                return {}
            out[tag] = out.get(tag, 0.0) + (x if isinstance(x, float) else x.mean_power)
    return out


@dataclass(frozen=True)
class EngineFriction:
    """The FLAME total of an engine at one speed (SI).

    ``speed`` [rad/s]; ``total`` the :class:`FlameTotal` [W, Pa]; ``valve_trains`` name ->
    friction power [W] of each included valve-train deck; ``valve_train_parts`` name -> {part:
    W} (cams, bearings, guides; arms: a pivoted follower's valve pad and pivot);
    ``bearing_treatments`` {'ungrooved': W, 'grooved': W} of the crank bearings (empty
    without them); ``missing`` the components left out (no data).
    """

    speed: float
    total: FlameTotal
    valve_trains: dict
    valve_train_parts: dict
    bearing_treatments: dict
    missing: tuple
