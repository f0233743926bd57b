"""Coupled camshaft effect: every lobe's elastic valve train on the elastic camshaft, iterated to
one periodic state (Teodorescu et al. 2005 §2.6, §4; the iteration in
:mod:`camtrain.dynamics.coupling`).

Each lobe drives its own copy of the deck's elastic train ([dynamics]), phased by its angle of
maximum lift; the shaft ([camshaft.flexibility]) answers all their contact forces, friction
(the deck's contact model: film and friction law at every angle of every lobe) and torques
with its bending and twist; the motion of each lobe along its follower axis and its twist
change that train's cam input. The result replaces the one-way elastic shaft (rank 1 for
``ElasticCamshaft``): the bearings run on its loads.
"""
from __future__ import annotations

MODEL = "elastic trains on the elastic camshaft, coupled"


def missing(deck) -> list[str]:
    cs = deck.camshaft
    out = []
    if cs is None or cs.flexibility is None:
        out.append("[camshaft.flexibility] section")
    elif cs.flexibility.coupling != "two_way":
        out.append('camshaft.flexibility.coupling = "two_way"')
    if cs is not None and not cs.bearings:
        out.append("[[camshaft.bearings]]")
    if getattr(deck, "dynamics", None) is None:
        out.append("[dynamics] section (the elastic train of every lobe)")
    return out


def reason(deck, planned) -> str:
    cs = deck.camshaft
    lobes = sum(1 for lobe in cs.lobes if lobe.bank == 1)
    how = {"monolithic": "marched together", "staggered": "marched in turn every step",
           "waveform": "iterated revolution by revolution"}[cs.flexibility.coupling_solver]
    return (f"[dynamics] and [camshaft.flexibility] given (coupling two_way): {lobes} elastic "
            f"trains on the elastic shaft, {how} ({cs.flexibility.coupling_solver}) to a "
            f"periodic state within {cs.flexibility.coupling_tolerance:g}")


def run(deck, inputs, res):
    import math

    import numpy as np

    from camtrain.build.dynamics import setup
    from camtrain.build.shaft import answer, shaft_from_deck
    from camtrain.camshaft import lobe_force, shift_curve
    from camtrain.camshaft.product import CamshaftLoads
    from camtrain.contact.model import CamContact
    from camtrain.dynamics import CamInput, march
    from camtrain.dynamics.coupling import lobe_input_perturbation, waveform_relaxation
    from camtrain.dynamics.findings import findings
    from camtrain.formulas import cam_torque
    from camtrain.loads import ContactLoad
    from camtrain.mechanisms import TrainKinematics
    from camtrain.tabulate.shaft import add_shaft

    cs, f = deck.camshaft, deck.camshaft.flexibility
    kin = inputs[TrainKinematics].main
    single = inputs[ContactLoad].load
    shaft_loads = inputs[CamshaftLoads]
    lobes = [lobe for lobe in cs.lobes if lobe.bank == 1]
    gammas = [lobe.max_lift_angle for lobe in lobes]
    axes = np.array([lobe.follower_axis_angle for lobe in lobes])
    theta = res["cam_angle"]
    omega = abs(deck.speed.omega)
    turn = 1.0 if cs.rotation == "anticlockwise" else -1.0
    run_setup = setup(deck, kin)
    cam = run_setup.cam
    ratio = np.asarray(kin.rocker_ratio, dtype=float) * np.ones_like(theta)
    contact = CamContact.from_deck(deck)
    shaft = shaft_from_deck(deck, shaft_loads.lobe_positions)
    arm_sign = np.sign(np.where(kin.friction_arm == 0, 1.0, kin.friction_arm))
    responses = [None] * len(lobes)

    def lobe_loads(loads):
        """Forces and torques on the shaft of every lobe from its load (shaft frame)."""
        forces, torques = [], []
        for j, g in enumerate(gammas):
            w = np.maximum(shift_curve(loads[j], -g), 0.0)  # the lobe's own angle frame
            fr = contact.solve(kin, w).force
            torque = cam_torque(w, kin.torque_arm_normal, fr, kin.friction_arm)
            forces.append(lobe_force(shift_curve(w, g), shift_curve(-turn * fr * arm_sign, g),
                                     axes[j]))
            torques.append(shift_curve(np.asarray(torque, dtype=float), g))
        return forces, np.array(torques)

    def solve_shaft(loads):
        forces, torques = lobe_loads(loads)
        return answer(deck, shaft, forces, torques, torques.sum(axis=0), omega, theta)

    def solve_trains(along, twist):
        new = []
        for j, g in enumerate(gammas):
            delta, d1, d2 = lobe_input_perturbation(shift_curve(along[j], -g),
                                                    shift_curve(twist[j], -g), ratio,
                                                    kin.valve_d1)
            moved = CamInput(cam.theta, cam.lift + delta, cam.d1 + d1, cam.d2 + d2)
            # each train starts from its state of the previous pass (fewer revolutions)
            responses[j] = march(run_setup.model, moved, run_setup.base, run_setup.settings,
                                 start=responses[j])
            new.append(shift_curve(responses[j].contact_force[0] * ratio, g))
        return np.array(new)

    def motion(out):
        """Each lobe's displacement along its follower axis [m] and its twist [rad]."""
        along = (out.deflection_x * np.cos(axes)[:, None]
                 + out.deflection_y * np.sin(axes)[:, None])
        return along, out.twist

    if f.coupling_solver in ("monolithic", "staggered"):
        return _monolithic(deck, res, kin, run_setup, shaft, gammas, axes, ratio, turn,
                           contact, omega, theta)
    n = len(lobes)
    marched = None
    if f.coupling_start == "monolithic":
        marched = _monolithic(deck, res, kin, run_setup, shaft, gammas, axes, ratio, turn,
                              contact, omega, theta, report=False)
        along0, twist0 = motion(solve_shaft(marched))
    else:
        rigid = np.array([shift_curve(np.maximum(single, 0.0), g) for g in gammas])
        along0, twist0 = motion(solve_shaft(rigid))
    # rows scaled so a pass's change weighs displacement and twist alike
    scale = np.array([max(float(np.max(np.abs(along0))), 1e-15),
                      max(float(np.max(np.abs(twist0))), 1e-15)])

    def one_pass(x):
        loads = solve_trains(x[:n] * scale[0], x[n:] * scale[1])
        along, twist = motion(solve_shaft(loads))
        return np.vstack([along / scale[0], twist / scale[1]])

    precondition = None
    if f.coupling_preconditioner == "interface_newton":
        precondition = _interface_newton(shaft, run_setup.model, axes, ratio, omega,
                                         theta.size, n)
    start = np.vstack([along0 / scale[0], twist0 / scale[1]])
    if precondition is not None and marched is None:
        # the start is the pass from the rigid shaft's motion (zero): take its Newton step
        start = precondition(start)
    state = waveform_relaxation(one_pass, start,
                      tol=f.coupling_tolerance, max_iterations=f.coupling_passes,
                      relaxation=f.relaxation, method=f.coupling_method,
                      precondition=precondition)
    loads = solve_trains(state.motion[:n] * scale[0], state.motion[n:] * scale[1])
    out = solve_shaft(loads)
    add_shaft(res, shaft, out, theta, cs.orders, omega)
    accelerations = [shift_curve(responses[j].a[run_setup.model.valve], g)
                     for j, g in enumerate(gammas)]
    _report(res, loads, accelerations, theta, "waveform iteration", state.iterations,
            state.change, state.converged, f.coupling_tolerance, cs.orders)
    if marched is not None:
        gap = float(np.max(np.abs(loads - marched))) / max(float(np.max(marched)), 1e-300)
        res.add_metric("coupling_start_gap", gap, "-",
                       "largest difference of any lobe's load between the waveform iteration "
                       "and the monolithic march it started from, over the largest marched load")
    for j, g in enumerate(gammas):
        seps = [s for s in findings(responses[j]).separations if s.in_flight]
        res.add_metric("separations", len(seps), "-",
                       f"lobe {j + 1}: losses of the cam contact while the valve is in flight "
                       "(not its landing on the seat)", component=f"lobe_{j + 1}")
        for s in seps:
            res.add_event("contact_loss", math.remainder(s.loss + g, 2 * math.pi),
                          f"lobe {j + 1}: the cam loses the follower", component=f"lobe_{j + 1}")
    return out


def _interface_newton(shaft, model, axes, ratio, omega, points, n):
    """The waveform pass's linear Jacobian on the lobes' motion along their follower axes
    (camtrain.dynamics.interface): shaft receptance between the lobes (both planes, projected
    on the axes) times each train's dynamic contact stiffness, R^2 g."""
    import numpy as np

    from camtrain.camshaft.flexible_response import lobe_receptance
    from camtrain.dynamics.interface import contact_stiffness, interface_newton

    orders = np.arange(points // 2 + 1)
    plane = lobe_receptance(shaft.beam, shaft.lobe_nodes, omega, orders)
    along = plane * np.cos(axes[:, None] - axes[None, :])[None]
    r2 = float(np.mean(ratio)) ** 2
    train = contact_stiffness(model, omega, orders) * r2
    # the load pushes the lobe away from its follower: -S G
    return interface_newton(-along * train[:, None, None], slice(0, n))


def _report(res, loads, valve_accelerations, theta, solver: str, passes: int, change: float,
            converged: bool, tolerance: float, orders: int) -> None:
    """Every lobe's coupled load and valve acceleration with their orders up to ``orders``,
    the summed load and the solver's convergence (passes of the iteration or revolutions of
    the march)."""
    import numpy as np

    for j, load in enumerate(loads):
        comp = f"lobe_{j + 1}"
        res.add_column("load", load, "N", f"lobe {j + 1}: contact load of its elastic train on "
                       f"the elastic shaft ({solver})", component=comp)
        res.add_column("valve_acceleration", valve_accelerations[j], "m/s^2",
                       f"lobe {j + 1}: valve acceleration", component=comp)
        i = int(np.argmax(load))
        res.add_metric("load_max", load[i], "N", f"lobe {j + 1}: largest contact load",
                       theta[i], component=comp)
    res.add_column("camshaft_load_sum", np.sum(loads, axis=0), "N",
                   "sum of the lobes' contact loads")
    from camtrain.tabulate.shaft import add_orders

    lobes = [f"lobe_{j + 1}" for j in range(len(loads))]
    add_orders(res, "load", dict(zip(lobes, loads, strict=True)), "N", "contact load", orders)
    add_orders(res, "valve_acceleration", dict(zip(lobes, valve_accelerations, strict=True)),
               "m/s^2", "valve acceleration", orders)
    res.add_metric("coupling_passes", passes, "-", f"passes of the {solver}")
    res.add_metric("coupling_change", change, "-",
                   f"relative change between the last two passes of the {solver}")
    if not converged:
        res.warn(f"camshaft coupling: no periodic state after {passes} passes of the {solver} "
                 f"(last change {change:.3g} > {tolerance:g}); the results are the last pass's")


def _monolithic(deck, res, kin, run_setup, shaft, gammas, axes, ratio, turn, contact,
                omega, theta, report: bool = True):
    """Every train and the shaft marched together (camtrain.dynamics.monolithic); without
    ``report`` only every lobe's marched load (shaft frame) is returned."""
    import numpy as np

    from camtrain.build.shaft import answer, drive_of
    from camtrain.camshaft import lobe_force, shift_curve
    from camtrain.dynamics import march
    from camtrain.dynamics.coupled_film import squeeze_film_model
    from camtrain.dynamics.excitation import TimeBase
    from camtrain.dynamics.monolithic import FRICTION_LEVELS, march_coupled
    from camtrain.formulas import cam_torque
    from camtrain.tabulate.shaft import add_shaft

    cs, f = deck.camshaft, deck.camshaft.flexibility
    arm_sign = np.sign(np.where(kin.friction_arm == 0, 1.0, kin.friction_arm))

    def own_frame(loads):
        """Cam-level loads of every lobe in its own angle frame."""
        return [np.maximum(shift_curve(loads[j] * 1.0, -g), 0.0) * ratio
                for j, g in enumerate(gammas)]

    def friction(loads):
        mu = []
        for j, w in enumerate(own_frame(loads)):
            force = contact.solve(kin, w).force
            coefficient = np.divide(force, w, out=np.zeros_like(w), where=w > 0)
            mu.append(shift_curve(coefficient, gammas[j]))
        return np.array(mu)

    def friction_table(levels):
        """Coefficient under each constant valve-referred load level, own angle frame."""
        mu = []
        for level in levels:
            w = level * ratio
            force = contact.solve(kin, w).force
            mu.append(np.divide(force, w, out=np.zeros_like(w), where=w > 0))
        return np.array(mu)

    # a steady film depends on the angle and the load only: the march takes each contact's
    # friction from its current load at every step; the level-1 squeeze film is carried per
    # contact through the march; the averaged Reynolds film lags a revolution
    steady = contact.film_law == "steady"
    film = None
    if contact.film_law == "squeeze":
        film = squeeze_film_model(contact, kin, FRICTION_LEVELS)
    drive = drive_of(deck)
    sub = run_setup.settings.substeps
    # the drive's speed (Williams' oscillation, camshaft.flexibility) turns every lobe
    speed = TimeBase(omega, f.speed_amplitude, f.speed_order if f.speed_amplitude else 0)
    # start from the single train's periodic state on a rigid shaft (fewer revolutions)
    single = march(run_setup.model, run_setup.cam, speed, run_setup.settings)
    result = march_coupled(shaft, run_setup.model, run_setup.cam, ratio, axes,
                           np.asarray(gammas), omega, substeps=sub,
                           friction=friction,
                           friction_table=friction_table if steady else None,
                           friction_arm=kin.friction_arm, turn=turn,
                           cycles_max=run_setup.settings.cycles_max,
                           period_tol=f.coupling_tolerance, start=single, film=film,
                           drive=None if drive is None else drive[1:],
                           staggered=f.coupling_solver == "staggered",
                           predictor=f.coupling_predictor, iterations=f.coupling_iterations,
                           speed=speed)
    forces, torques, loads = [], [], []
    for j, (g, w) in enumerate(zip(gammas, own_frame(result.loads), strict=True)):
        fr = contact.solve(kin, w).force
        torque = cam_torque(w, kin.torque_arm_normal, fr, kin.friction_arm)
        forces.append(lobe_force(shift_curve(w, g), shift_curve(-turn * fr * arm_sign, g),
                                 axes[j]))
        torques.append(shift_curve(np.asarray(torque, dtype=float), g))
        loads.append(shift_curve(w, g))
    torques = np.array(torques)
    if not report:
        return np.array(loads)
    out = answer(deck, shaft, forces, torques, torques.sum(axis=0), omega, theta)
    add_shaft(res, shaft, out, theta, cs.orders, omega)
    solver = ("monolithic march" if f.coupling_solver == "monolithic"
              else "staggered march")
    _report(res, loads, result.valve_acceleration, theta, solver, result.cycles,
            result.change, result.converged, f.coupling_tolerance, cs.orders)
    if f.coupling_solver == "staggered":
        res.add_metric("coupling_step_misses", result.missed, "-",
                       "steps of the last revolution whose staggered passes did not agree "
                       "with their predicted loads")
        if result.missed:
            res.warn(f"camshaft coupling: {result.missed} steps of the staggered march kept "
                     f"a load that differs from the shaft's after {f.coupling_iterations} "
                     "passes (give more coupling_iterations, or a smaller step)")
    if result.film is not None:
        for j, load in enumerate(loads):
            res.add_column("film", np.where(load > 0.0, result.film[j], np.nan), "m",
                           f"lobe {j + 1}: level-1 squeeze film of its cam contact, marched "
                           "with the coupled trains at every step (NaN: out of contact)",
                           component=f"lobe_{j + 1}")
    return out
