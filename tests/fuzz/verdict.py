"""What a fuzzed `camtrain run` must never do, as one assertion over a finished case."""
from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner

ALLOWED_EXITS = (0, 1, 2, 3, 4)


def run_deck(text: str, out_dir: Path):
    """`camtrain run - --no-plots --json` on deck ``text``, in process."""
    from camtrain.cli import main

    return CliRunner().invoke(main, ["run", "-", "--no-plots", "--json", "--out", str(out_dir)],
                              input=text)


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
