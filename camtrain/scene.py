"""Scene plan: which effects a deck calls for, in which order, and why.

The deck's kind (:data:`camtrain.catalogue.KINDS`) gives the effects that may run. A deck
either lists the effects it wants or says ``auto``; then an effect runs only when the deck
supplies its data and the products it needs are planned (as in Ball's program: no spring or mass
data -> kinematics and the load-free Blok film only). Where several effects offer the same
product, the highest ranked with its data present is chosen, and the plan says so. The plan is
resolved before any computation (no physics or numpy is imported) and printed by ``check`` and
``run``.
"""
from __future__ import annotations

import importlib
import sys
import weakref

from camtrain.catalogue import EffectSpec, kind_of
from camtrain.errors import InputError, Problem
from camtrain.plan import Plan, Step

__all__ = ["Plan", "Step", "resolve", "effect_module"]


def included(deck, spec: EffectSpec) -> list[tuple[str, object, Plan]]:
    """(name, deck model, plan) of every deck the effect ``spec`` includes
    (EffectSpec.includes): an engine deck's valve trains, composed here as plans of their own."""
    if not spec.includes:
        return []
    module, _, func = spec.includes.partition(":")
    decks = getattr(importlib.import_module(module), func)(deck)
    return [(name, model, resolve(model)) for name, model in decks]


def effect_module(spec: EffectSpec):
    """The module of an effect (its top level imports no physics)."""
    module = sys.modules.get(spec.module)
    return module if module is not None else importlib.import_module(spec.module)


#: plans of the decks of this process, by id of the (immutable) deck model: (weak reference to
#: the deck, the effects the plan was resolved over, the plan); an entry leaves with its deck
_PLANS: dict[int, tuple[weakref.ref, tuple[EffectSpec, ...], Plan]] = {}


def resolve(deck, effects: tuple[EffectSpec, ...] | None = None) -> Plan:
    """Resolve the plan for a deck before any computation.

    ``effects`` replaces the deck kind's registered effects (tests and extensions). The plan
    depends only on the immutable deck model and the catalogue, so the plan of a deck's
    registered effects is resolved once per process (repeated runs of one deck reuse it)."""
    kind = kind_of(deck)
    cached = _PLANS.get(id(deck)) if effects is None else None
    if cached is not None and cached[0]() is deck and cached[1] is kind.effects:
        return cached[2]
    specs, rivals = _ordered(effects if effects is not None else kind.effects)
    if deck.effects == "auto":
        plan = Plan("auto", _resolve_auto(deck, specs, rivals), kind.name)
    else:
        plan = Plan("explicit", _resolve_explicit(deck, specs, deck.effects), kind.name)
    if effects is None:
        key = id(deck)
        try:
            ref = weakref.ref(deck, lambda _, key=key: _PLANS.pop(key, None))
        except TypeError:   # a deck object that cannot be weakly referenced: not cached
            return plan
        _PLANS[key] = (ref, kind.effects, plan)
    return plan


#: run order and rivals of the effect lists plans were resolved over, by the list's identity
_ORDERS: dict[int, tuple[object, tuple[EffectSpec, ...], dict[str, tuple[str, ...]]]] = {}


def _ordered(specs) -> tuple[tuple[EffectSpec, ...], dict[str, tuple[str, ...]]]:
    """:func:`order` and each effect's rivals (the others offering one of its products), once
    per effect list (a sweep resolves a plan for every case's model)."""
    hit = _ORDERS.get(id(specs))
    if hit is not None and hit[0] is specs:
        return hit[1], hit[2]
    ordered = tuple(order(specs))
    rivals = {spec.name: tuple(s.name for s in ordered if s is not spec
                               and set(s.produces) & set(spec.produces)) for spec in ordered}
    if isinstance(specs, tuple):   # immutable: the entry cannot go stale (it keeps specs alive)
        if len(_ORDERS) >= 16:
            _ORDERS.clear()
        _ORDERS[id(specs)] = (specs, ordered, rivals)
    return ordered, rivals


def order(specs: tuple[EffectSpec, ...]) -> list[EffectSpec]:
    """Topological order over products (needs and uses); ties: higher rank, then listed order.

    Raises ValueError on a cycle (a catalogue error, not a user error)."""
    producers: dict[str, list[int]] = {}
    for i, s in enumerate(specs):
        for p in s.produces:
            producers.setdefault(p, []).append(i)
    deps = [{j for p in s.needs + s.uses for j in producers.get(p, ()) if j != i}
            for i, s in enumerate(specs)]
    done: list[int] = []
    left = set(range(len(specs)))
    while left:
        ready = [i for i in left if deps[i] <= set(done)]
        if not ready:
            names = ", ".join(specs[i].name for i in sorted(left))
            raise ValueError(f"the effects {names} need each other's products (a cycle)")
        nxt = min(ready, key=lambda i: (-specs[i].rank, i))
        done.append(nxt)
        left.remove(nxt)
    return [specs[i] for i in done]


def _model(module, deck, planned) -> str:
    """The model the effect runs for this deck and plan (its module's ``model(deck,
    planned)``), "" for an effect of one model."""
    model = getattr(module, "model", None)
    return model(deck, frozenset(planned)) if model is not None else ""


def _resolve_auto(deck, specs, rivals_of: dict[str, tuple[str, ...]]) -> tuple[Step, ...]:
    planned: dict[str, str] = {}  # product -> effect that provides it
    steps = []
    for spec in specs:
        module = effect_module(spec)
        unmet = [p for p in spec.needs if p not in planned]
        taken = [p for p in spec.produces if p in planned]
        if taken:
            by = planned[taken[0]]
            steps.append(Step(spec.name, False, f"{taken[0]} comes from {by} instead "
                              f"(ranked higher, its data are present)", spec))
            continue
        if unmet:
            steps.append(Step(spec.name, False, "needs " + ", ".join(unmet)
                              + ", which no planned effect provides", spec))
            continue
        missing = module.missing(deck)
        if missing:
            steps.append(Step(spec.name, False, "no data: " + "; ".join(missing), spec))
            continue
        reason = module.reason(deck, frozenset(planned))
        model = _model(module, deck, planned)
        rivals = rivals_of[spec.name]
        if rivals:
            reason += f" (chosen over {', '.join(rivals)} for {', '.join(spec.produces)})"
        for p in spec.produces:
            planned[p] = spec.name
        steps.append(Step(spec.name, True, reason, spec, model))
    return tuple(steps)


def _resolve_explicit(deck, specs: list[EffectSpec], requested: tuple[str, ...]) -> tuple[Step, ...]:
    by_name = {s.name: s for s in specs}
    wanted: dict[str, str] = {}

    def provider(product: str) -> EffectSpec | None:
        offers = [s for s in specs if product in s.produces]
        for s in offers:
            if s.name in wanted or s.name in requested:
                return s
        for s in offers:  # the first with its data, else the first (it reports what is missing)
            if not effect_module(s).missing(deck):
                return s
        return offers[0] if offers else None

    def want(name: str, why: str) -> None:
        if name in wanted:
            return
        for product in by_name[name].needs:
            dep = provider(product)
            if dep is not None:
                want(dep.name, f"needed by {name}")
        wanted[name] = why

    for name in requested:
        if name not in by_name:
            raise InputError(Problem("effects", "is not an effect of this deck kind", name,
                                     "one of " + ", ".join(by_name)))
        want(name, "requested in the deck")
    problems = []
    for name, why in wanted.items():
        missing = effect_module(by_name[name]).missing(deck)
        if missing:
            problems.append(Problem("effects", f"effect {name!r} is requested ({why}) but its "
                                    "data are missing: " + "; ".join(missing)))
    if problems:
        raise InputError(problems)
    planned = frozenset(p for n in wanted for p in by_name[n].produces)
    steps = []
    for spec in specs:
        if spec.name in wanted:
            module = effect_module(spec)
            reason = wanted[spec.name] + "; " + module.reason(deck, planned)
            steps.append(Step(spec.name, True, reason, spec, _model(module, deck, planned)))
        else:
            steps.append(Step(spec.name, False, "not requested", spec))
    return tuple(steps)
