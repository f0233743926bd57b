"""Component names shared by products and results.

A valve train has one cam/follower pair, or two for a desmodromic train: the opening pair is the
train's ``main`` component, the closing pair its ``closing`` component. Products that hold one
field per pair are :class:`ByPair` collections, in pair order (``main`` first).
"""
from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Generic, TypeVar

MAIN, CLOSING = "main", "closing"

T = TypeVar("T")


@dataclass(frozen=True)
class ByPair(Generic[T]):
    """One field per cam/follower pair, in pair order (``main`` first)."""

    pairs: tuple[tuple[str, T], ...]

    def __getitem__(self, component: str) -> T:
        for name, value in self.pairs:
            if name == component:
                return value
        raise KeyError(component)

    def __contains__(self, component: str) -> bool:
        return any(name == component for name, _ in self.pairs)

    def __iter__(self) -> Iterator[tuple[str, T]]:
        return iter(self.pairs)

    @property
    def main(self) -> T:
        return self[MAIN]


def column_prefix(component: str) -> str:
    """Prefix of a pair's columns and metrics in flat tables: none for the main pair."""
    return "" if component == MAIN else component + "_"


def pair_label(component: str) -> str:
    """Text appended to a pair's descriptions: none for the main pair."""
    return "" if component == MAIN else f" ({component} pair)"


def result_component(component: str) -> str | None:
    """The component of a pair in a Result: None for the main pair (the train itself)."""
    return None if component == MAIN else component
