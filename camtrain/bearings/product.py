"""The bearing-orbit product: the orbit of every bearing of a shaft or a stand-alone deck."""
from __future__ import annotations

from dataclasses import dataclass

from camtrain.bearings.result import JournalOrbit


@dataclass(frozen=True)
class BearingOrbits:
    """One entry per bearing in deck order: its JournalOrbit, or None (Petroff method, or the
    march did not converge: the run says so in a warning)."""

    orbits: tuple[JournalOrbit | None, ...]
