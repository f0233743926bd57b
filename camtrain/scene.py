"""Scene plan: which effects a deck calls for, in which order, and why.

Each effect declares the effects it needs, the deck data it needs, and what it produces. A deck
either lists the effects it wants or says ``auto``; then an effect runs only when the deck supplies
its data (as in Ball's program: no spring or mass data -> kinematics and the load-free Blok film
only). The plan is resolved before any computation and printed by ``check`` and ``run``.
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from camtrain.deck.schema import EFFECT_NAMES, Deck
from camtrain.errors import InputError, Problem


@dataclass(frozen=True)
class Effect:
    """One physical effect of the run chain."""

    name: str
    description: str
    needs: tuple[str, ...]
    produces: tuple[str, ...]
    missing: Callable[[Deck], list[str]]
    runner: str  # "module:function"; imported only when the effect runs
    available: bool = True
    planned_in: str = ""  # where an effect that is not available yet will come from


@dataclass(frozen=True)
class Step:
    """An effect's place in the plan: chosen or skipped, and why."""

    effect: str
    chosen: bool
    reason: str
    available: bool = True

    def as_dict(self) -> dict:
        return {"effect": self.effect, "chosen": self.chosen, "reason": self.reason,
                "available": self.available}


@dataclass(frozen=True)
class Plan:
    mode: str
    steps: tuple[Step, ...]

    @property
    def chosen(self) -> list[str]:
        return [s.effect for s in self.steps if s.chosen]

    def as_dict(self) -> dict:
        return {"mode": self.mode, "steps": [s.as_dict() for s in self.steps]}


def _missing_loads(deck: Deck) -> list[str]:
    out = []
    if deck.spring is None:
        out.append("spring (rate, preload_compression)")
    if deck.masses is None:
        out.append("masses (valve_side)")
    return out


def _missing_hertz(deck: Deck) -> list[str]:
    return [] if deck.cam.width is not None else ["cam.width"]


def _missing_film(deck: Deck) -> list[str]:
    return [] if deck.lubricant is not None else ["lubricant (viscosity, pressure_viscosity)"]


def _nothing(deck: Deck) -> list[str]:
    return []


def _missing_camshaft(deck: Deck) -> list[str]:
    return [] if deck.camshaft is not None else ["[camshaft] section (lobes)"]


def _missing_bearings(deck: Deck) -> list[str]:
    if deck.camshaft is None:
        return ["[camshaft] section"]
    out = [] if deck.camshaft.bearings else ["[[camshaft.bearings]]"]
    if deck.camshaft.viscosity is None and deck.lubricant is None:
        out.append("camshaft.viscosity or lubricant.viscosity")
    return out


EFFECTS: dict[str, Effect] = {e.name: e for e in (
    Effect("kinematics", "lift law and follower kinematics: lift and derivatives, contact point, "
           "r_c, R, surface, entrainment and sliding velocities",
           (), ("lift", "r_c", "R", "V_c", "V_f", "u_e", "V_s"), _nothing,
           "camtrain.effects.kinematics:run"),
    Effect("loads", "contact load from the rigid-train D'Alembert balance; loss of contact",
           ("kinematics",), ("load",), _missing_loads,
           "camtrain.effects.loads:run"),
    Effect("hertz", "Hertz contact half-width and maximum pressure",
           ("loads",), ("hertz_pmax", "hertz_half_width"), _missing_hertz,
           "camtrain.effects.hertz:run"),
    Effect("film", "lubricant film thickness (EHL with load, Blok rigid-piezoviscous without)",
           ("kinematics",), ("film_min", "film_central", "lambda"), _missing_film,
           "camtrain.effects.film:run"),
    Effect("friction", "friction force and coefficient: viscous shear capped by boundary "
           "friction", ("hertz", "film"), ("friction_force", "friction_coefficient"), _nothing,
           "camtrain.effects.friction:run"),
    Effect("power", "friction torque about the cam axis and power loss",
           ("friction",), ("friction_torque", "power_loss"), _nothing,
           "camtrain.effects.power:run"),
    Effect("camshaft_torque", "camshaft: lobe torques phased and summed, drive power, harmonic "
           "orders, second bank, pendulum dampers", ("loads",),
           ("camshaft_torque", "order_n"), _missing_camshaft,
           "camtrain.effects.camshaft:run"),
    Effect("bearings", "camshaft bearings: lobe and drive forces split as beams, journal "
           "orbits (Booker mobility), minimum film and power",
           ("camshaft_torque",), ("bearing_i_load_x/y", "bearing_i_eccentricity"),
           _missing_bearings, "camtrain.effects.bearings:run"),
)}

#: The one effect of a stand-alone ``kind = "journal_bearing"`` deck (run by camtrain.api).
BEARING_EFFECT = Effect("journal_bearing", "journal orbit, minimum film and power of one "
                        "bearing under its load diagram", (), ("eccentricity", "min_film"),
                        _nothing, "camtrain.effects.bearings:run_bearing_deck")

assert tuple(EFFECTS) == EFFECT_NAMES


def resolve(deck: Deck) -> Plan:
    """Resolve the plan for a deck before any computation."""
    if getattr(deck, "kind", "valve_train") == "journal_bearing":
        solver = deck.solver
        why = f"stand-alone bearing deck: {solver.method} method, {solver.film} film"
        return Plan("journal_bearing", (Step(BEARING_EFFECT.name, True, why),))
    if deck.effects == "auto":
        return _resolve_auto(deck)
    return _resolve_explicit(deck, deck.effects)


def _film_reason(deck: Deck, with_load: bool) -> str:
    if with_load:
        return "lubricant given and contact loads planned: EHL film with the contact load"
    return ("lubricant given, no contact loads: Blok rigid-piezoviscous film, "
            "which needs no load (Ball 1988 eq. 4.3)")


def _resolve_auto(deck: Deck) -> Plan:
    chosen: set[str] = set()
    steps = []
    for name, eff in EFFECTS.items():
        unmet = [n for n in eff.needs if n not in chosen]
        missing = eff.missing(deck)
        if unmet:
            steps.append(Step(name, False, "needs " + ", ".join(unmet) + ", which will not run",
                              eff.available))
        elif missing:
            steps.append(Step(name, False, "no data: " + "; ".join(missing), eff.available))
        else:
            chosen.add(name)
            reason = _auto_reason(deck, name, chosen)
            steps.append(Step(name, True, reason, eff.available))
    return Plan("auto", tuple(steps))


def _auto_reason(deck: Deck, name: str, chosen: set[str]) -> str:
    if name == "kinematics":
        return f"always: {deck.lift.form} lift on a {deck.mechanism.type} follower"
    if name == "loads":
        return "spring and masses given"
    if name == "hertz":
        return "contact load and cam width available"
    if name == "film":
        return _film_reason(deck, "loads" in chosen)
    if name == "friction":
        return "Hertz zone and film available"
    if name == "power":
        return "friction available"
    if name == "camshaft_torque":
        torque = "W e + F r" if "power" in chosen else "W e only (no friction)"
        return f"{len(deck.camshaft.lobes)} lobes given; lobe torque {torque}"
    if name == "bearings":
        return f"{len(deck.camshaft.bearings)} bearings given; {deck.camshaft.method} method"
    return "data given"  # pragma: no cover


def _resolve_explicit(deck: Deck, requested: tuple[str, ...]) -> Plan:
    wanted: dict[str, str] = {}

    def want(name: str, why: str) -> None:
        if name in wanted:
            return
        for dep in EFFECTS[name].needs:
            want(dep, f"needed by {name}")
        wanted[name] = why

    for name in requested:
        want(name, "requested in the deck")
    problems = []
    for name in wanted:
        missing = EFFECTS[name].missing(deck)
        if missing:
            problems.append(Problem("effects", f"effect {name!r} is requested "
                                    f"({wanted[name]}) but its data are missing: "
                                    + "; ".join(missing)))
    if problems:
        raise InputError(problems)
    steps = []
    for name, eff in EFFECTS.items():
        if name in wanted:
            reason = wanted[name]
            if name == "film":
                reason += "; " + _film_reason(deck, "loads" in wanted)
            steps.append(Step(name, True, reason, eff.available))
        else:
            steps.append(Step(name, False, "not requested", eff.available))
    return Plan("explicit", tuple(steps))
