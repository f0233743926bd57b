"""Steady EHL line contact (docs/ehl.md "Cost"): the solve on 1,024 points against a floor of
the same run, and the cost against the number of points. Nothing here asserts a time.

Floor: one Newton step's irreducible work at the same size, a dense LU factorisation of an
(n-1) x (n-1) matrix plus one zero-padded FFT deflection, in bare numpy/scipy, on one BLAS thread
as the solvers run (a floor on threaded BLAS leaves its threads spinning into the next round,
whose process CPU time then counts them). The ratio reads
as "how many bare Newton steps the whole solve costs". The cost against points is read against
100 bare FFT deflections of the same size instead (the matrix-free solver's own unit of work,
O(n log n)): a dense LU floor grows as n^3 and is unaffordable at 16,384 points.
"""
from __future__ import annotations

import numpy as np
import scipy.linalg as sla
from conftest import note, paired, record

from camtrain.lubrication.ehl_elastic import ElasticKernel
from camtrain.lubrication.ehl_line import EHLResolution, LineContact, solve_ehl_line
from camtrain.lubrication.ehl_oil import Oil
from camtrain.numerics.blas_threads import one_blas_thread
from tests.lubrication.test_ehl_transient import goecmen_cycle

#: formulas_and_anchors case A: w = 200 N/mm, R = 20 mm, u_m = 1 m/s, eta0 = 0.04 Pa s,
#: alpha = 20 /GPa, E' = 226 GPa; Roelands, Dowson-Higginson density (M = 10.5, L = 9.3).
CASE_A = LineContact(2e5, 0.02, 2.26e11, 1.0, 1.0, Oil(0.04, 2e-8))


def bare_newton_step(n: int):
    rng = np.random.default_rng(0)
    A = rng.standard_normal((n - 1, n - 1)) + n * np.eye(n - 1)
    kernel = ElasticKernel.of_grid(n, 6.0 / n)
    P = rng.random(n)

    def step():
        with one_blas_thread():     # as the solvers run theirs (camtrain.numerics.blas_threads)
            sla.lu_factor(A, check_finite=False)
            kernel.deflection(P)
    return step


def bare_deflections(n: int, count: int = 100):
    """Floor of the cost against points: ``count`` zero-padded FFT deflections of n points
    (the O(n log n) work of a matrix-free product; a dense LU floor would be O(n^3) and take
    minutes and gigabytes at 16,384 points)."""
    kernel = ElasticKernel.of_grid(n, 6.0 / n)
    P = np.random.default_rng(0).random(n)

    def run():
        for _ in range(count):
            kernel.deflection(P)
    return run


def test_bench_ehl_line_1024(benchmark):
    """Target: under 0.1 s of CPU for 1,024 points."""
    resolution = EHLResolution(nodes=1024)
    timing = paired(lambda: solve_ehl_line(CASE_A, resolution), bare_newton_step(1024),
                    rounds=7, warmup=1)
    record(benchmark, "steady EHL line contact, 1024 points / one bare Newton step", timing,
           "< 0.1 s CPU", cpu=True)
    note("steady EHL line contact, 1024 points, CPU", f"{timing['cpu_subject_min']:.3g} s",
         "< 0.1 s")
    benchmark.pedantic(solve_ehl_line, args=(CASE_A, resolution), rounds=1, iterations=1)


def test_bench_ehl_line_cost_against_points(benchmark):
    """CPU time of the solve at 256..16384 points and the fitted exponent of n (n log n over
    this range fits about n^1.12; docs/make_ehl_cost.py draws the same measurement)."""
    sizes = [256, 512, 1024, 2048, 4096, 8192, 16384]
    times = []
    for n in sizes:
        resolution = EHLResolution(nodes=n)
        timing = paired(lambda r=resolution: solve_ehl_line(CASE_A, r), bare_deflections(n),
                        rounds=3, warmup=1)
        times.append(timing["cpu_subject_min"])
        note(f"steady EHL line contact, {n} points, CPU",
             f"{timing['cpu_subject_min']:.3g} s ({timing['cpu_ratio_min']:.2f} x 100 bare "
             "FFT deflections)")
    exponent = np.polyfit(np.log(sizes), np.log(times), 1)[0]
    note("steady EHL line contact, cost ~ n^k", f"k = {exponent:.2f}", "n log n (k ~ 1.12)")
    benchmark.extra_info["exponent"] = exponent
    benchmark.pedantic(solve_ehl_line, args=(CASE_A, EHLResolution(nodes=256)), rounds=1,
                       iterations=1)


def bare_steps(n: int, steps: int):
    """Floor of a march: one bare Newton step (dense LU, FFT deflection) per angle."""
    one = bare_newton_step(n)

    def run():
        for _ in range(steps):
            one()
    return run


def test_bench_ehl_cam_cycle_512(benchmark):
    """Target: a whole cam cycle at 0.5 deg steps on 512 points under 20 s of CPU (the
    default linear solver, matrix-free at 512 points); the Newton and GMRES iterations per
    step are noted beside the time."""
    from camtrain.lubrication.ehl_transient import CycleResolution, march_ehl_cycle

    contact = goecmen_cycle(720)
    resolution = CycleResolution(nodes=512)
    runs = []
    timing = paired(lambda: runs.append(march_ehl_cycle(contact, resolution)),
                    bare_steps(512, 720), rounds=1, warmup=0)
    record(benchmark, "elastic film, cam cycle 720 steps x 512 points / one bare Newton "
           "step per angle", timing, "< 20 s CPU", cpu=True)
    note("elastic film, cam cycle 720 x 512, CPU", f"{timing['cpu_subject_min']:.3g} s "
         f"({timing['cpu_subject_min'] / 720 * 1e3:.3g} ms per step)", "< 20 s")
    out = runs[-1]
    newton = int(out.iterations.sum())
    note("elastic film, cam cycle 720 x 512, iterations",
         f"{newton / 720:.2f} Newton per step, {out.krylov_iterations / max(newton, 1):.1f} "
         f"GMRES per Newton, {out.split_steps} split steps")
    benchmark.extra_info["newton_per_step"] = newton / 720
    benchmark.pedantic(lambda: None, rounds=1, iterations=1)


def test_bench_ehl_cycle_cost_against_points(benchmark):
    """CPU time of 80 steps through the opening flank and the first entrainment reversal
    (-52 .. -12 deg) at 128..2048 points with matrix-free Newton directions, and the fitted
    exponent of n (target: n log n or n, k <= 1.1); the default ``auto`` takes the dense LU
    below 384 points, where it is cheaper."""
    from dataclasses import replace

    from camtrain.lubrication.ehl_transient import CycleResolution, march_ehl_cycle

    full = goecmen_cycle(720)
    window = slice(256, 336)
    part = replace(full, **{k: getattr(full, k)[window] for k in ("t", "w", "R", "u", "u_s")})
    sizes, times = [128, 256, 512, 1024, 2048], []
    for n in sizes:
        res = CycleResolution(nodes=n, linear_solver="krylov")
        timing = paired(lambda r=res: march_ehl_cycle(part, r), bare_steps(n, 80), rounds=1,
                        warmup=0)
        times.append(timing["cpu_subject_min"])
        note(f"elastic film, 80 steps, {n} points, CPU",
             f"{timing['cpu_subject_min']:.3g} s ({timing['cpu_ratio_min']:.2f} bare steps "
             "per angle)")
    exponent = np.polyfit(np.log(sizes), np.log(times), 1)[0]
    note("elastic film march, cost ~ n^k", f"k = {exponent:.2f}", "n log n or n (k <= 1.1)")
    benchmark.extra_info["exponent"] = exponent
    benchmark.pedantic(lambda: None, rounds=1, iterations=1)
