"""What a fuzzed `camtrain run` must never do, as one assertion over a finished case."""
from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner

ALLOWED_EXITS = (0, 1, 2, 3, 4)


class Hang(BaseException):
    """A case ran past its time box (a BaseException: the CLI's own handlers let it through)."""


def run_deck(text: str, out_dir: Path, box: float | None = None):
    """`camtrain run - --no-plots --json` on deck ``text``, in process; with ``box`` [s] a run
    still going after that long raises :class:`Hang` (main thread, POSIX only)."""
    import signal
    import threading

    from camtrain.cli import main

    def invoke():
        return CliRunner().invoke(main, ["run", "-", "--no-plots", "--json", "--out",
                                         str(out_dir)], input=text)

    if not box or threading.current_thread() is not threading.main_thread() \
            or not hasattr(signal, "SIGALRM"):
        return invoke()

    def expire(signum, frame):
        raise Hang(f"the run took longer than its time box of {box:g} s")

    previous = signal.signal(signal.SIGALRM, expire)
    signal.setitimer(signal.ITIMER_REAL, box)
    try:
        res = invoke()
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    if isinstance(res.exception, Hang):
        raise res.exception
    return res


def assert_sane(res, out_dir: Path, what: str = "") -> None:
    """Exit 0-4, no traceback, no output directory on failure, no silent non-finite metric."""
    context = f"{what}\nexit {res.exit_code}\n{res.output[-2000:]}"
    escaped = res.exception is not None and not isinstance(res.exception, SystemExit)
    assert not escaped, f"exception escaped the CLI: {res.exception!r}\n{context}"
    assert "Traceback" not in res.output, f"traceback printed\n{context}"
    assert res.exit_code in ALLOWED_EXITS, f"exit code {res.exit_code}\n{context}"
    if res.exit_code in (2, 3, 4):
        assert res.output.lstrip().startswith("error:") or "error:" in res.output, context
        assert not out_dir.exists(), f"output directory left after a failed run\n{context}"
        return
    summary = json.loads(res.stdout if hasattr(res, "stdout") else res.output)
    warnings = " ".join(summary["warnings"])
    silent = [name for name, m in summary["metrics"].items()
              if m["value"] is None and name not in warnings]
    assert not silent, f"non-finite metrics without a warning naming them: {silent}\n{context}"


def write_report(path: str, tally: dict[tuple[str, str], int], seconds: float) -> None:
    """Cases per kind and exit code (``hang``: past the time box) as a small text table."""
    kinds = sorted({k for k, _ in tally})
    codes = sorted({c for _, c in tally}, key=lambda c: (not c.isdigit(), int(c) if
                                                          c.isdigit() else 0, c))
    lines = [f"{'kind':<18}{'cases':>7}" + "".join(f"{'exit ' + c:>9}" for c in codes)]
    for kind in kinds:
        row = [tally.get((kind, c), 0) for c in codes]
        lines.append(f"{kind:<18}{sum(row):>7}" + "".join(f"{n:>9}" for n in row))
    total = [sum(tally.get((k, c), 0) for k in kinds) for c in codes]
    lines.append(f"{'all':<18}{sum(total):>7}" + "".join(f"{n:>9}" for n in total))
    lines.append(f"wall time {seconds:.0f} s")
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    Path(path).write_text("\n".join(lines) + "\n", encoding="utf-8")
