"""Run a resolved plan: call each chosen effect in order, time it, collect one Result."""
from __future__ import annotations

import importlib
import time

from camtrain.deck.schema import Deck
from camtrain.result import Result
from camtrain.scene import EFFECTS, Plan, resolve


class State:
    """What effects share during one run: the model, the result, and intermediate objects."""

    def __init__(self, deck: Deck, result: Result):
        self.deck = deck
        self.result = result
        self.objects: dict[str, object] = {}


def run_plan(deck: Deck, plan: Plan | None = None) -> Result:
    """Run every chosen effect of the plan. Effects not available yet are reported, not faked."""
    plan = plan or resolve(deck)
    result = Result(plan=plan)
    state = State(deck, result)
    blocked: set[str] = set()
    for name in plan.chosen:
        effect = EFFECTS[name]
        if not effect.available or any(dep in blocked for dep in effect.needs):
            blocked.add(name)
            result.not_available.append(name)
            why = (f"is not available yet (arrives with {effect.planned_in})"
                   if not effect.available else "cannot run: an effect it needs is not available")
            result.warn(f"effect '{name}' {why}; nothing was computed for it")
            continue
        module_name, func_name = effect.runner.split(":")
        func = getattr(importlib.import_module(module_name), func_name)
        start = time.perf_counter()
        func(deck, state)
        result.timings[name] = time.perf_counter() - start
    return result
