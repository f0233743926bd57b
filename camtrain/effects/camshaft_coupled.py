"""Coupled camshaft effect: every lobe's elastic train on the elastic camshaft, solved to one
periodic state by the solver the deck names (:mod:`camtrain.coupled`; Teodorescu et al. 2005
§2.6, §4). The result replaces the one-way elastic shaft (rank 1 for ``ElasticCamshaft``): the
bearings run on its loads. This module builds the problem, solves it and tabulates."""
from __future__ import annotations


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
    from camtrain.coupled import SOLVERS

    f = deck.camshaft.flexibility
    lobes = sum(1 for lobe in deck.camshaft.lobes if lobe.bank == 1)
    return (f"[dynamics] and [camshaft.flexibility] given (coupling two_way): {lobes} elastic "
            f"trains on the elastic shaft, {SOLVERS[f.coupling_solver].how} "
            f"({f.coupling_solver}) to a periodic state within {f.coupling_tolerance:g}")


def run(deck, inputs, res):
    from camtrain.assemble.coupled import coupled_problem
    from camtrain.camshaft.product import CamshaftLoads
    from camtrain.coupled import solve
    from camtrain.loads import ContactLoad
    from camtrain.mechanisms import TrainKinematics
    from camtrain.tabulate.shaft import add_coupled

    problem = coupled_problem(deck, inputs[TrainKinematics].main, inputs[ContactLoad].load,
                              inputs[CamshaftLoads].lobe_positions, res["cam_angle"])
    result = solve(problem)
    add_coupled(res, problem, result, deck.camshaft.orders)
    return result.shaft
