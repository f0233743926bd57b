"""A resolved plan as data: which effects run, in which order, and why each was chosen or
skipped (:func:`camtrain.scene.resolve` makes it; a Result carries it and reads it back from a
saved file without the scene)."""
from __future__ import annotations

from dataclasses import dataclass, field

from camtrain.catalogue import EffectSpec


@dataclass(frozen=True)
class Step:
    """An effect's place in the plan: chosen or skipped, and why."""

    effect: str
    chosen: bool
    reason: str
    spec: EffectSpec | None = field(default=None, compare=False, repr=False)
    #: the model a chosen effect runs when it has several (the film's tribology.film_model as
    #: it runs: "steady" without contact loads); "" for an effect of one model. The panels it
    #: feeds follow from it (EffectSpec.model_panels)
    model: str = ""

    def as_dict(self) -> dict:
        out = {"effect": self.effect, "chosen": self.chosen, "reason": self.reason}
        if self.model:
            out["model"] = self.model
        return out


@dataclass(frozen=True)
class Plan:
    mode: str
    steps: tuple[Step, ...]
    kind: str = "valve_train"

    @property
    def chosen(self) -> list[str]:
        return [s.effect for s in self.steps if s.chosen]

    @property
    def effects(self) -> list[EffectSpec]:
        """The chosen effects in run order."""
        return [s.spec for s in self.steps if s.chosen]

    def as_dict(self) -> dict:
        return {"mode": self.mode, "steps": [s.as_dict() for s in self.steps]}
