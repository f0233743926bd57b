"""Run a resolved plan: call each chosen effect in order, hand it the products it declared,
check what it returns, time it, and collect one Result."""
from __future__ import annotations

import importlib
import time
from functools import cache
from typing import TypeVar

from camtrain.catalogue import PRODUCTS, EffectSpec
from camtrain.formulas._util import trusted_inputs
from camtrain.progress import detail
from camtrain.result import Result
from camtrain.scene import Plan, effect_module, included, resolve

T = TypeVar("T")


class Inputs:
    """The products one effect may read: those it ``needs`` (always there) and those it
    ``uses`` (there when the plan provides them). Keyed by product class."""

    def __init__(self, spec: EffectSpec, products: dict[str, object], included=None):
        self._spec = spec
        self._products = products
        #: name -> (deck model, Result) of the decks the effect includes (EffectSpec.includes)
        self.included = included or {}

    def _declared(self, cls: type, kinds: tuple[str, ...]) -> str:
        name = cls.__name__
        if name not in kinds:
            raise TypeError(f"effect {self._spec.name!r} reads {name}, which it does not "
                            f"declare in the catalogue ({', '.join(kinds) or 'nothing'})")
        return name

    def __getitem__(self, cls: type[T]) -> T:
        """A needed product."""
        return self._products[self._declared(cls, self._spec.needs)]

    def get(self, cls: type[T]) -> T | None:
        """An optional (``uses``) or needed product, None when the plan does not provide it."""
        return self._products.get(self._declared(cls, self._spec.needs + self._spec.uses))


@cache
def product_class(name: str) -> type:
    module, cls = PRODUCTS[name].split(":")
    return getattr(importlib.import_module(module), cls)


def run_plan(deck, plan: Plan | None = None, progress=None) -> Result:
    """Run every chosen effect of the plan (resolved here when not given).

    ``progress(effect name, done, total)``, when given, is called before each effect runs
    (a progress bar names what runs) and once more when all have run."""
    plan = plan or resolve(deck)
    result = Result(plan=plan)
    products: dict[str, object] = {}
    effects = plan.effects
    with trusted_inputs():  # the deck was validated at its boundary: no per-formula checks
        for done, spec in enumerate(effects):
            if progress is not None:
                progress(spec.name, done, len(effects))
            start = time.perf_counter()
            if spec.supersedes:   # this effect owns these findings: earlier ones go
                result.drop_findings(spec.supersedes)
            if progress is None and not spec.includes:   # a run's usual step: nothing around it
                out = effect_module(spec).run(deck, Inputs(spec, products), result)
            else:
                with _details(progress, spec.name, done, len(effects)):
                    included = _run_included(deck, spec)
                    out = effect_module(spec).run(deck, Inputs(spec, products, included),
                                                  result)
            result.timings[spec.name] = time.perf_counter() - start
            products.update(_checked(spec, out))
    if progress is not None:
        progress("done", len(effects), len(effects))
    warn_non_finite(result)
    return result


def cases_refusal(deck, plan: Plan, swept: tuple[str, ...]) -> str:
    """Why the plan's effects cannot run this deck's cases over a leading case axis ("" when
    they can): an effect joins by defining ``run_cases(deck, inputs, cases)`` in its module,
    and may refuse a deck with ``cases_refused(deck, swept) -> str`` (``swept``: the deck
    paths the cases vary)."""
    for spec in plan.effects:
        module = effect_module(spec)
        if not hasattr(module, "run_cases"):
            return f"the {spec.name} effect runs case by case (it has no run over a case axis)"
        refused = getattr(module, "cases_refused", None)
        why = refused(deck, swept) if refused is not None else ""
        if why:
            return why
    return ""


def run_cases(deck, plan: Plan, cases) -> dict[str, object]:
    """Every chosen effect of the plan over a leading case axis: each effect's ``run_cases``
    with the products it declared, checked as :func:`run_plan` checks a run's, on the
    :class:`camtrain.assemble.cases.Cases` it reads its per-case deck data from and adds its
    metrics to. Returns the products by name."""
    products: dict[str, object] = {}
    with trusted_inputs():
        for spec in plan.effects:
            out = effect_module(spec).run_cases(deck, Inputs(spec, products), cases)
            products.update(_checked(spec, out))
    return products


def _run_included(deck, spec: EffectSpec) -> dict:
    """The runs of the decks an effect includes, each through its own plan (scene.included)."""
    runs = {}
    for name, model, plan in included(deck, spec):
        detail(name)
        runs[name] = (model, run_plan(model, plan))
    return runs


def _details(progress, name: str, done: int, total: int):
    """What the effect tells of its work (camtrain.progress.detail) goes to ``progress`` as
    "<effect>: <what it does now>"."""
    from contextlib import nullcontext

    from camtrain.progress import listening

    if progress is None:
        return nullcontext()
    return listening(lambda text: progress(f"{name}: {text}", done, total))


def warn_non_finite(result: Result) -> None:
    """A metric that came out NaN or infinite is never silent: a warning names it (unless an
    effect's own warning already does)."""
    import math

    for name, metric in result.metrics.items():
        if math.isfinite(metric.value) or any(name in w for w in result.warnings):
            continue
        what = "not computed (NaN)" if math.isnan(metric.value) else f"{metric.value}"
        result.warn(f"{name} is {what}: {metric.description}")


def _checked(spec: EffectSpec, out) -> dict[str, object]:
    """The products an effect returned, by name, after checking them against its declaration."""
    items = out if isinstance(out, tuple) else (() if out is None else (out,))
    got = {}
    for obj in items:
        name = type(obj).__name__
        if name not in spec.produces or not isinstance(obj, product_class(name)):
            raise TypeError(f"effect {spec.name!r} returned a {name}, which is not one of the "
                            f"products it declares ({', '.join(spec.produces)})")
        got[name] = obj
    if len(got) != len(spec.produces):   # (every name in got is one of them)
        lost = sorted(set(spec.produces) - set(got))
        raise TypeError(f"effect {spec.name!r} did not return {', '.join(lost)}")
    return got
