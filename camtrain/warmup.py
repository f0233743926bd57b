"""Compile every family of numba kernels once, ahead of a user's first run (``camtrain warmup``;
``make demo`` runs it).

numba keeps compiled kernels in its disk cache (``cache=True`` on every kernel), so a compile is
paid once per installation; without this step it falls on the first run of the first deck that
marches an orbit, an elastic train, a shaft with its trains or a ring pack (12-46 s of CPU on the
reference machine against 1-7 s warm; docs/performance.md, "First run"). Each family is
compiled by running a deck that uses it: a template where one does (the stand-alone bearing and
the engine template march journal orbits; the push-rod template with an elastic train), else
the shipped deck of a source checkout (``decks/``). Runs whose kernels are already cached take
their warm time only.
"""
from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

#: decks/ of a source checkout (absent from an installed wheel)
SOURCE_DECKS = Path(__file__).resolve().parent.parent / "decks"

#: the elastic train of decks/pushrod_dynamics.toml (assumed stiffnesses, masses and damping)
_PUSHROD_DYNAMICS = """
[dynamics]
follower_mass = 0.054
contact_stiffness = 2.0e5
pushrod_stiffness = 3.0e4
rocker_stiffness = 3.0e4
stem_stiffness = 1.0e5
seat_stiffness = 2.0e5
damping_ratio = 0.05
spring_damping_ratio = 0.02
"""


@dataclass(frozen=True)
class WarmupCase:
    """One deck run to compile a family: a template (with text added) or a shipped deck."""

    family: str
    name: str
    template: str | None = None
    extra: str = ""
    deck: str | None = None

    def available(self) -> bool:
        return self.template is not None or (SOURCE_DECKS / f"{self.deck}.toml").is_file()

    def load(self):
        from camtrain import api

        if self.template is not None:
            from camtrain.deck.templates import render_template

            return api.loads(render_template(self.template) + self.extra, self.name)
        return api.load(SOURCE_DECKS / f"{self.deck}.toml")


CASES = (
    WarmupCase("journal-orbit", "journal_bearing template", template="journal_bearing"),
    WarmupCase("journal-orbit", "engine template", template="engine"),
    WarmupCase("journal-orbit", "zeta_intake_camshaft", deck="zeta_intake_camshaft"),
    WarmupCase("valve-train dynamics", "pushrod template, elastic", template="pushrod",
               extra=_PUSHROD_DYNAMICS),
    WarmupCase("shaft-and-trains", "zeta_intake_camshaft_coupled",
               deck="zeta_intake_camshaft_coupled"),
    WarmupCase("ring-film", "zeta_engine", deck="zeta_engine"),
    WarmupCase("roller", "harrison_roller_needle", deck="harrison_roller_needle"),
)


def warm_up(say: Callable[[str], None] = print) -> list[tuple[WarmupCase, float | None]]:
    """Run every case (compiling what is not cached); (case, CPU seconds or None if skipped)."""
    done = []
    for case in CASES:
        if not case.available():
            say(f"{case.family}: {case.name} is not installed (a source checkout's decks/); "
                "these kernels compile on the first run that uses them")
            done.append((case, None))
            continue
        start = time.process_time()
        _run_quietly(case)
        seconds = time.process_time() - start
        say(f"{case.family}: {case.name} ran in {seconds:.1f} s of CPU")
        done.append((case, seconds))
    return done


def _run_quietly(case: WarmupCase) -> None:
    import warnings

    from camtrain import api

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        api.run(case.load())
