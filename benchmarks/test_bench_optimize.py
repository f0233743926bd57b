"""Cost of `camtrain optimize` (`make bench`; figures in docs/design.md and performance.md).

* The Harrison base-radius optimum under "no concave flank": at most 200 chain evaluations and
  under 5 s of CPU (the search in this process, the deck already imported once).
* A four-variable flat-tappet search (base radius, spring rate, preload, the four-power half
  period, with no concave flank, no separation up to 3000 rpm and the valve-open area within
  2 %): under 60 s of CPU. The half period is a lift field, so these cases run one by one.
* The batch route is taken when every variable allows it.

Floor: the bare-numpy Harrison chain (``harrison_floor.py``) run as many times as the search
evaluated cases, so the ratio is the cost per evaluation against the bare physics.
"""
from __future__ import annotations

import time

from conftest import ROOT, cpu_seconds, note, paired, record

DECK = str(ROOT / "decks" / "harrison_flat.toml")


def _search(variables, constraints, **options):
    from camtrain.study.optimize import optimize

    return optimize(DECK, variables, constraints=constraints, **options)


def _floor(n: int):
    from harrison_floor import HARRISON, harrison_floor

    return lambda: [harrison_floor(1440, HARRISON) for _ in range(n)]


def test_bench_optimize_harrison_base_radius(benchmark):
    c = cpu_seconds()
    _search(["base_radius=10:25"], ["no_concave_flank"])      # imports, lift curve cached
    cold = cpu_seconds() - c
    c = cpu_seconds()
    out = _search(["base_radius=10:25"], ["no_concave_flank"])
    cpu = cpu_seconds() - c
    assert out.problem.route.batch
    assert out.evaluations <= 200
    assert abs(out.optimum.x[0] - 13.5902) <= 1e-3 * 15 + 1e-3
    assert cpu < 5.0 and cold < 5.0
    n = out.evaluations
    timing = paired(lambda: _search(["base_radius=10:25"], ["no_concave_flank"]), _floor(n),
                    rounds=3)
    record(benchmark, f"optimize Harrison r_B, {n} chain evaluations (batched)", timing)
    note("optimize Harrison r_B: chain evaluations, CPU (first in the process, again)",
         f"{n}, {cold:.2f} s, {cpu:.3f} s", "<= 200, < 5 s")
    benchmark.extra_info.update(evaluations=n, cpu_seconds=cpu)
    benchmark.pedantic(lambda: _search(["base_radius=10:25"], ["no_concave_flank"]), rounds=1,
                       iterations=1)


FOUR = ["base_radius=12:24", "spring_rate=20:60", "spring.preload_compression=1:12",
        "lift.four_power.half_period=50:70"]
FOUR_CONSTRAINTS = ["no_concave_flank", "no_separation=3000", "open_area=2"]


def test_bench_optimize_four_variables(benchmark):
    c, t = cpu_seconds(), time.perf_counter()
    out = _search(FOUR, FOUR_CONSTRAINTS)
    cpu, wall = cpu_seconds() - c, time.perf_counter() - t
    assert out.optimum.feasible and out.optimum.objective < out.datum.objective
    assert not out.problem.route.batch          # a lift field: case by case
    assert cpu < 60.0
    n = out.evaluations
    note("optimize flat tappet, 4 variables: evaluations, CPU, wall",
         f"{n}, {cpu:.2f} s, {wall:.2f} s", "< 60 s CPU")
    timing = paired(lambda: _search(FOUR, FOUR_CONSTRAINTS), _floor(n), rounds=1, warmup=0)
    record(benchmark, f"optimize flat tappet, 4 variables, {n} evaluations (case by case)",
           timing)
    benchmark.extra_info.update(evaluations=n, cpu_seconds=cpu)
    benchmark.pedantic(lambda: None, rounds=1, iterations=1)


def test_bench_optimize_uses_the_batch_route(benchmark, monkeypatch):
    from camtrain.study import batch

    sizes = []
    real = batch.run_batch
    monkeypatch.setattr(batch, "run_batch", lambda job: sizes.append(len(job.cases)) or
                        real(job))
    out = benchmark.pedantic(lambda: _search(["base_radius=12:24", "spring_rate=20:60",
                                              "spring.preload_compression=1:12"],
                                             ["no_concave_flank", "no_separation=3000"]),
                             rounds=1, iterations=1)
    assert out.problem.route.batch and sum(sizes) == out.evaluations and max(sizes) == 4
