"""Print pip constraints pinning every declared dependency (and the test extras) to its minimum.

`make test-oldest` installs camtrain against these pins, so the minimums in pyproject.toml are
versions the suite has actually passed on, not guesses.
"""
from __future__ import annotations

import re
import sys
import tomllib
from pathlib import Path

#: transitive dependencies held at the era of the minimums: matplotlib 3.9 (the minimum) calls
#: pyparsing's camelCase API, which pyparsing 3.3 deprecates with a warning on every plot
ERA_PINS = ("pyparsing<3.3",)

_REQ = re.compile(r"^\s*([A-Za-z0-9_.-]+)(\[[^\]]*\])?\s*>=\s*([0-9][0-9A-Za-z.]*)\s*$")


def pins(pyproject: Path, extras: tuple[str, ...] = ("test",)) -> list[str]:
    project = tomllib.loads(pyproject.read_text())["project"]
    reqs = list(project["dependencies"])
    for extra in extras:
        reqs += project["optional-dependencies"][extra]
    out = []
    for req in reqs:
        m = _REQ.match(req)
        if m is None:
            raise SystemExit(f"{req!r}: every dependency needs a '>=' minimum to pin")
        name, _extra, version = m.groups()
        out.append(f"{name}=={version}")
    return sorted(set(out))


if __name__ == "__main__":
    root = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent
    print("\n".join(pins(root / "pyproject.toml") + list(ERA_PINS)))
