"""Elastic camshaft effect: the camshaft's bending and torsion under its lobe and drive loads.

The shaft of ``[camshaft.flexibility]`` (Teodorescu et al. 2005 §2.6; stations at the bearings,
lobes and drive, Euler-Bernoulli bending in two planes on bearing springs, torsion from the drive:
:mod:`camtrain.camshaft.flexible`) answers the lobe forces and torques of the camshaft effect and
the drive's hub load with its periodic response, order by order
(:mod:`camtrain.camshaft.flexible_response`). The bearing loads it gives replace the simply
supported bays of the bearings effect; the named splits ``determinate`` and ``equal_share`` are
its limits. The loads are those of the trains as the plan computed them (rigid-train or dynamic):
the shaft's deflection does not act back on the trains here.
"""
from __future__ import annotations


def missing(deck) -> list[str]:
    cs = deck.camshaft
    if cs is None or cs.flexibility is None:
        return ["[camshaft.flexibility] section"]
    return [] if cs.bearings else ["[[camshaft.bearings]]"]


def reason(deck, planned) -> str:
    cs = deck.camshaft
    f = cs.flexibility
    support = ("rigid supports" if f.bearing_stiffness is None
               else f"bearing supports {f.bearing_stiffness * 1e-3:g} N/mm")
    drive = ("drive held at the mean speed" if f.drive_stiffness is None
             else f"drive spring {f.drive_stiffness:g} N·m/rad")
    return (f"[camshaft.flexibility] given: {f.split} bearing split, {f.response} shaft on "
            f"{len(cs.bearings)} bearings, {support}, {drive}, {f.nodes_per_span} extra stations "
            "per span")


def run(deck, inputs, res):
    from camtrain.assemble.shaft import answer, shaft_from_deck
    from camtrain.camshaft.product import CamshaftLoads
    from camtrain.tabulate.shaft import add_shaft

    cs = deck.camshaft
    loads = inputs[CamshaftLoads]
    if cs.drive is None:
        res.warn("no [camshaft.drive]: the drive hub load is left out of the elastic shaft and "
                 "its torsion is driven at the first bearing")
    shaft = shaft_from_deck(deck, loads.lobe_positions)
    theta = res["cam_angle"]
    omega = abs(loads.omega)
    out = answer(deck, shaft, loads.lobe_forces, loads.lobe_torques, loads.torque, omega, theta)
    add_shaft(res, shaft, out, theta, cs.orders, omega)
    return out
