"""The deck's two-way coupled camshaft ([dynamics] and [camshaft.flexibility] with coupling =
"two_way") turned into the plain problem the coupled solvers take
(:class:`camtrain.coupled.problem.CoupledProblem`)."""
from __future__ import annotations

import numpy as np


def coupled_problem(deck, kin, rigid_load, lobe_positions, theta):
    """The coupled problem of the deck's bank-1 lobes (at ``lobe_positions`` [m]) on the main
    pair's kinematics ``kin`` and grid ``theta`` [rad], the rigid train's contact load
    ``rigid_load`` [N]."""
    from camtrain.assemble.dynamics import setup
    from camtrain.assemble.shaft import drive_of, shaft_from_deck
    from camtrain.contact.model import CamContact
    from camtrain.coupled.problem import CoupledProblem, Coupling, ShaftOptions

    cs, f = deck.camshaft, deck.camshaft.flexibility
    lobes = [lobe for lobe in cs.lobes if lobe.bank == 1]
    run_setup = setup(deck, kin, spin=False)   # the coupled march carries no roller spin
    coupling = Coupling(f.coupling_solver, f.coupling_tolerance, f.coupling_passes,
                        f.relaxation, f.coupling_method, f.coupling_preconditioner,
                        f.coupling_start, f.coupling_predictor, f.coupling_iterations)
    options = ShaftOptions(f.split, f.response, cs.overhang, f.speed_amplitude, f.speed_order,
                           drive_of(deck))
    return CoupledProblem(
        kin=kin, contact=CamContact.from_deck(deck), train=run_setup.model, cam=run_setup.cam,
        base=run_setup.base, settings=run_setup.settings,
        shaft=shaft_from_deck(deck, lobe_positions), options=options,
        phases=np.asarray([lobe.max_lift_angle for lobe in lobes]),
        axes=np.array([lobe.follower_axis_angle for lobe in lobes]),
        ratio=np.asarray(kin.rocker_ratio, dtype=float) * np.ones_like(theta), theta=theta,
        omega=abs(deck.speed.omega), turn=1.0 if cs.rotation == "anticlockwise" else -1.0,
        rigid_load=rigid_load, coupling=coupling)
