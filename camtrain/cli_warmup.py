"""`camtrain warmup`: compile the numba kernels once, before the first run needs them."""
from __future__ import annotations

import click


@click.command("warmup")
def warmup() -> None:
    """Compile every family of compiled kernels once (kept in numba's disk cache), so that no
    deck's first run pays for it. `make demo` runs it; rerun after upgrading camtrain or numba."""
    from camtrain.warmup import warm_up

    warm_up(lambda line: click.echo(line))
