"""Error types a user can cause, and the exit codes the CLI maps them to.

Physics and deck code raise these; only the CLI turns them into exit codes and one readable
message. Anything else escaping is a bug in camtrain (exit code 70, internal error).
"""
from __future__ import annotations

from dataclasses import dataclass

EXIT_OK = 0
EXIT_LIMITS_VIOLATED = 1
EXIT_INVALID_INPUT = 2
EXIT_PHYSICALLY_IMPOSSIBLE = 3
EXIT_NOT_CONVERGED = 4
EXIT_INTERNAL = 70


@dataclass(frozen=True)
class Problem:
    """One thing wrong with a deck: where, what was found, what was expected, and a hint."""

    path: str
    message: str
    value: object = None
    expected: str = ""
    hint: str = ""

    def render(self) -> str:
        text = f"{self.path}: {self.message}" if self.path else self.message
        if self.value is not None:
            text += f" (got {self.value!r})"
        if self.expected:
            text += f"; expected {self.expected}"
        if self.hint:
            text += f". {self.hint}"
        return text


class CamtrainError(Exception):
    """Base class for every error a user's input can cause."""

    exit_code = EXIT_INVALID_INPUT


class InputError(CamtrainError):
    """The deck (or a command-line value) is invalid. Carries every problem found at once."""

    exit_code = EXIT_INVALID_INPUT

    def __init__(self, problems: list[Problem] | Problem | str, *, source: str = ""):
        if isinstance(problems, str):
            problems = [Problem("", problems)]
        elif isinstance(problems, Problem):
            problems = [problems]
        self.problems = list(problems)
        self.source = source
        super().__init__(self.render())

    def render(self) -> str:
        head = f"{self.source}: " if self.source else ""
        if len(self.problems) == 1:
            return head + self.problems[0].render()
        lines = [f"{head}{len(self.problems)} problems in the deck:"]
        lines += [f"  - {p.render()}" for p in self.problems]
        return "\n".join(lines)


def field_error(path: str, message: str, value: object = None, expected: str = "",
                hint: str = "") -> InputError:
    """Shorthand for a single-field input error (used by physics modules too)."""
    return InputError(Problem(path, message, value, expected, hint))


class GeometryError(CamtrainError):
    """A physically impossible request: the geometry cannot work (names the angle where it fails).

    Examples: a flat follower on a cam that would have to be concave, a cusp, a four-bar chain that
    cannot assemble, contact running off the follower face.
    """

    exit_code = EXIT_PHYSICALLY_IMPOSSIBLE


class ConvergenceError(CamtrainError):
    """An iterative solver did not reach its stated tolerance (names solver, tolerance, residual)."""

    exit_code = EXIT_NOT_CONVERGED
