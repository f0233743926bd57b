"""Deck sections of the FLAME engine total (Yang 1992 Part IV): the valve-train decks the engine
includes by path, the accessories and how the bearing column is taken. Part of the engine deck
schema."""
from __future__ import annotations

from contextvars import ContextVar
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

from camtrain.deck.fields import option, quantity, section


@dataclass(frozen=True, kw_only=True)
class ValveTrainInclude:
    """A valve-train deck run at the engine's camshaft speed (one camshaft, or one cam)."""

    deck: str = option("Path of a valve-train deck, relative to this deck",
                       example="zeta_intake_camshaft.toml")
    name: str = option("Name in the tables", default="valve train")
    speed_ratio: float = quantity("Camshaft speed / engine speed (4-stroke: 0.5)", "-",
                                  default=0.5, gt=0, le=2)
    trains: int = quantity(
        "Valve trains this deck stands for when it has no [camshaft] section (its one cam is "
        "multiplied); with a [camshaft] its lobes count", "-", default=1, ge=1, le=64)


@dataclass(frozen=True, kw_only=True)
class AccessoriesSection:
    """Accessories (oil and water pumps, alternator, ...) as a share of the component sum."""

    share: float = quantity("Accessory loss as a share of bearings + valve trains + pistons "
                            "(Yang Part IV: 25, i.e. 20 % of the total)", "%", default=25.0,
                            ge=0, lt=1000)


@dataclass(frozen=True, kw_only=True)
class FlameSection:
    """The engine's friction total by component (Yang's FLAME, Part IV)."""

    valve_trains: tuple[ValveTrainInclude, ...] | None = section(
        "Valve-train decks, one [[flame.valve_trains]] per camshaft")
    accessories: AccessoriesSection = section("Accessories", default=AccessoriesSection())
    bearing_method: Literal["dynamic", "steady", "petroff"] = option(
        "Which crank-bearing power enters the total (partially grooved mains: the mean of the "
        "grooved and ungrooved totals, as FLAME)", default="dynamic")


#: the chain of decks being resolved in this thread (outermost first): an included deck that is
#: already on it would include itself again without end
_including: ContextVar[tuple[Path, ...]] = ContextVar("camtrain_including", default=())

#: most levels of decks including decks (a valve-train deck includes none; more is a mistake)
MAX_INCLUDE_DEPTH = 8


def _include_problem(path: str, p: Path, chain: tuple[Path, ...], given: str):
    """A Problem when including ``p`` would close a cycle or nest too deep, else None."""
    from camtrain.errors import Problem

    target = p.resolve()
    if target in chain:
        loop = chain[chain.index(target):] + (target,)
        return Problem(path, "includes a deck that is already being read (an include cycle: "
                       + " -> ".join(str(q) for q in loop) + ")", given,
                       "a valve-train deck that includes no deck of this chain")
    if len(chain) >= MAX_INCLUDE_DEPTH:
        return Problem(path, f"nests decks more than {MAX_INCLUDE_DEPTH} deep ("
                       + " -> ".join(str(q) for q in chain + (target,)) + ")", given,
                       "a valve-train deck (which includes no other deck)")
    return None


def resolve_valve_trains(flame: FlameSection | None, base_dir, source: str):
    """The flame section with every included deck path made absolute, each included deck
    checked to exist and to validate as a valve-train deck (problems name the include)."""
    import dataclasses

    from camtrain.deck.schema import Deck
    from camtrain.errors import InputError, Problem

    if flame is None or not flame.valve_trains:
        return flame
    from camtrain.deck.load import load_deck

    items, problems = [], []
    for i, vt in enumerate(flame.valve_trains):
        path = f"flame.valve_trains[{i}].deck"
        p = Path(vt.deck)
        p = p if p.is_absolute() else Path(base_dir) / p
        if not p.is_file():
            problems.append(Problem(path, "file not found", vt.deck,
                                    "a valve-train deck (path relative to the engine deck)"))
            continue
        chain = _including.get() or ((Path(source).resolve(),) if Path(source).is_file()
                                     else ())
        cycle = _include_problem(path, p, chain, vt.deck)
        if cycle is not None:
            problems.append(cycle)
            continue
        token = _including.set(chain + (p.resolve(),))
        try:
            model = load_deck(str(p)).model
        except InputError as exc:
            problems.append(Problem(path, "the included deck is invalid: "
                                    + "; ".join(q.render() for q in exc.problems), vt.deck))
            continue
        finally:
            _including.reset(token)
        if not isinstance(model, Deck):
            problems.append(Problem(path, "is not a valve-train deck", vt.deck,
                                    "a deck of kind valve_train"))
            continue
        items.append(dataclasses.replace(vt, deck=str(p)))
    if problems:
        raise InputError(problems, source=source)
    return dataclasses.replace(flame, valve_trains=tuple(items))
