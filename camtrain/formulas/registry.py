"""Method registries: named published formulas with their validity ranges.

A registry maps a method name (``author_year`` plus a suffix where one paper gives several
results) to a :class:`Method` record. Dispatchers such as
:func:`camtrain.formulas.film.film_thickness` look the name up; ``*_methods`` functions list the
methods whose required inputs are present and whose validity ranges contain the operating point.
"""
from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np

from camtrain.errors import field_error


@dataclass(frozen=True)
class Method:
    """One published formula.

    Attributes:
        name: registry key, e.g. ``"dowson_higginson_1977"``.
        func: the implementing function.
        kind: what it returns, e.g. ``"line/minimum"`` or ``"point/central"``.
        requires: input names the dispatcher must receive.
        ranges: dimensionless group -> (low, high) inclusive validity range.
        range_source: where the ranges come from (the paper, or "nominal" when the paper gives
            none and the range is a camtrain choice).
        reference: source and equation number.
        aliases: other accepted names.
    """

    name: str
    func: Callable
    kind: str
    requires: tuple[str, ...]
    ranges: Mapping[str, tuple[float, float]] = field(default_factory=dict)
    range_source: str = "nominal"
    reference: str = ""
    aliases: tuple[str, ...] = ()

    def in_range(self, groups: Mapping[str, np.ndarray]) -> bool:
        """True if every element of every group named in ``ranges`` lies inside its range."""
        for key, (lo, hi) in self.ranges.items():
            if key not in groups:
                continue
            g = np.asarray(groups[key], dtype=float)
            if not np.all((g >= lo) & (g <= hi)):
                return False
        return True


class Registry(dict):
    """A dict of :class:`Method` keyed by name, resolving aliases on lookup."""

    def __init__(self, topic: str, methods: list[Method]):
        super().__init__((m.name, m) for m in methods)
        self.topic = topic
        self._alias = {a: m.name for m in methods for a in m.aliases}

    def get_method(self, name: str) -> Method:
        key = self._alias.get(name, name)
        if key not in self:
            raise field_error("method", f"unknown {self.topic} method", name,
                              "one of " + ", ".join(sorted(self)))
        return self[key]

    def applicable(self, provided: set[str], groups: Mapping[str, np.ndarray],
                   check_ranges: bool = True, kinds: tuple[str, ...] | None = None) -> list[str]:
        names = []
        for m in self.values():
            if kinds is not None and m.kind not in kinds:
                continue
            if not set(m.requires) <= provided:
                continue
            if check_ranges and not m.in_range(groups):
                continue
            names.append(m.name)
        return names
