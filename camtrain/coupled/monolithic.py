"""The monolithic solver: every lobe's train and the shaft marched together in time, one state
vector, to their common periodic state (:mod:`.march`; docs/camshaft_dynamics.md). Its
iteration is the march's: revolutions until two agree at the grid samples."""
from __future__ import annotations

from .problem import CoupledResult

LABEL = "monolithic march"


def solve(problem) -> CoupledResult:
    return marched(problem, staggered=False)


def marched(problem, *, staggered: bool, answer: bool = True):
    """The march of ``problem`` (``staggered``: shaft and trains in turn within every step,
    :mod:`.staggered`) as a :class:`.problem.CoupledResult`; without ``answer`` only every
    lobe's marched cam-level load (lobes, n; shaft frame).

    A steady film depends on the angle and the load only: the march takes each contact's
    friction from its current load at every step (tables corrected every revolution); the
    level-1 squeeze film is carried per contact through the march; the averaged Reynolds film
    lags a revolution. The drive's speed (Williams' oscillation) turns every lobe. The march
    starts from the single train's periodic state on a rigid shaft (fewer revolutions)."""
    from camtrain.dynamics import march as single_march
    from camtrain.dynamics.excitation import TimeBase

    from . import film as film_model
    from . import march
    from .lobes import LobeFriction, shaft_answer, shaft_loads
    from .tables import FRICTION_LEVELS

    p, c, o = problem, problem.coupling, problem.options
    friction = LobeFriction(p)
    steady = p.contact.film_law == "steady"
    film = None
    if p.contact.film_law == "squeeze":
        film = film_model.squeeze_film_model(p.contact, p.kin, FRICTION_LEVELS)
    speed = TimeBase(p.omega, o.speed_amplitude, o.speed_order if o.speed_amplitude else 0)
    single = single_march(p.train, p.cam, speed, p.settings)
    result = march.march_coupled(
        p.shaft, p.train, p.cam, p.ratio, p.axes, p.phases, p.omega,
        substeps=p.settings.substeps, friction=friction.coefficients,
        friction_table=friction.table if steady else None, friction_arm=p.kin.friction_arm,
        turn=p.turn, cycles_max=p.settings.cycles_max, period_tol=c.tolerance, start=single,
        film=film, drive=None if o.drive is None else o.drive[1:], staggered=staggered,
        predictor=c.predictor, iterations=c.iterations, speed=speed)
    forces, torques, loads = shaft_loads(p, friction.own_frame(result.loads))
    if not answer:
        return loads
    return CoupledResult(
        loads, result.valve_acceleration, shaft_answer(p, forces, torques),
        "staggered march" if staggered else LABEL, result.cycles, result.change,
        result.converged, missed=result.missed if staggered else None, film=result.film)
