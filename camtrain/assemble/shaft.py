"""The deck's [camshaft.flexibility] turned into the elastic shaft of
:mod:`camtrain.camshaft.elastic`, and the forces the drive adds to it."""
from __future__ import annotations

import math


def drive_of(deck):
    """(position, pitch radius, hub-load angle, preload) of [camshaft.drive], or None."""
    d = deck.camshaft.drive
    return None if d is None else (d.position, d.radius, d.hub_load_angle, d.preload)


def shaft_from_deck(deck, lobe_positions):
    """The elastic shaft of the deck's camshaft with lobes at ``lobe_positions`` [m]. Without
    a [camshaft.drive] the torsion is driven at the first bearing."""
    from camtrain.camshaft.elastic import elastic_shaft
    from camtrain.camshaft.flexible import ShaftSection

    cs = deck.camshaft
    f = cs.flexibility
    section = ShaftSection.hollow(f.diameter, f.bore, f.modulus, f.shear_modulus, f.density)
    drive = cs.drive.position if cs.drive is not None else cs.bearings[0].position
    return elastic_shaft(
        [b.position for b in cs.bearings], lobe_positions, drive, section,
        bearing_stiffness=math.inf if f.bearing_stiffness is None else f.bearing_stiffness,
        bearing_damping=f.bearing_damping, damping_ratio=f.damping_ratio,
        lobe_mass=f.lobe_mass, lobe_inertia=f.lobe_inertia,
        drive_stiffness=math.inf if f.drive_stiffness is None else f.drive_stiffness,
        drive_inertia=f.drive_inertia, nodes_per_span=f.nodes_per_span)


def answer(deck, shaft, lobe_forces, lobe_torques, total_torque, omega, theta):
    """The shaft's answer to its lobes' forces ((fx, fy) per lobe), their torques and the
    drive's hub load from the summed torque."""
    from camtrain.camshaft import shaft_forces
    from camtrain.camshaft.elastic import shaft_answer

    f = deck.camshaft.flexibility
    positions, fx, fy = shaft_forces(shaft.lobe_positions, lobe_forces, total_torque,
                                     drive_of(deck))
    return shaft_answer(shaft, positions, fx, fy, lobe_torques, omega, split=f.split,
                        response=f.response, overhang=deck.camshaft.overhang,
                        speed_amplitude=f.speed_amplitude, speed_order=f.speed_order,
                        theta=theta)
