"""The deck's [roller] turned into physics: its pin, its inertia, and the tables of its spin
marched with the elastic train (:mod:`camtrain.dynamics.spin`)."""
from __future__ import annotations

#: the traction and pin tables of the marched roller reach this multiple of the rigid train's
#: largest load (above it they are held: the dynamics effect warns when the marched load passes
#: it)
LOAD_CAP_FACTOR = 3.0


def face_mass(deck) -> float:
    """mechanism.roller.mass [kg] (a roller finger's or rocker's roller), 0 without it."""
    face = deck.mechanism.roller
    return face.mass if face is not None else 0.0


def pin_of(deck):
    """The deck's pin as physics (:class:`camtrain.roller.pin.Pin`)."""
    from camtrain.bearings import JournalBearing
    from camtrain.roller.pin import Pin

    r = deck.roller
    eta = r.pin_viscosity if r.pin_viscosity is not None else deck.lubricant.viscosity
    if r.pin == "needle":
        return Pin("needle", pitch_diameter=r.needle_pitch_diameter,
                   kinematic_viscosity=eta / r.oil_density, f0=r.needle_f0, f1=r.needle_f1)
    if r.pin == "bushing":
        return Pin("bushing", bearing=JournalBearing(r.pin_diameter, r.pin_length,
                                                     r.pin_clearance, eta, name="roller"),
                   model=r.pin_model, asperities=bushing_asperities(deck), terms=r.pin_terms)
    return Pin(r.pin)


def bushing_asperities(deck):
    """The bushing's Greenwood-Tripp asperities with roller.pin_friction = "mixed" (None for
    hydrodynamic): roughness roller.pin_roughness (else lubricant.roughness), the tribology
    section's asperity and boundary parameters, the pair's reduced modulus (pin and roller of
    the follower's material)."""
    from camtrain.contact.model import CamContact
    from camtrain.roller.pin import Asperities

    r = deck.roller
    if r.pin_friction != "mixed":
        return None
    trib = deck.tribology
    sigma = r.pin_roughness if r.pin_roughness is not None else deck.lubricant.roughness
    beta = sigma / trib.roughness_slope
    return Asperities(sigma=sigma, beta=beta,
                      zeta=trib.asperity_density_product / (beta * sigma),
                      reduced_modulus=float(CamContact.from_deck(deck).reduced_modulus),
                      tau0=trib.eyring_stress, m=trib.boundary_shear_coefficient)


def inertia_of(deck, radius: float) -> float:
    """The roller's spin inertia J about its pin [kg m^2] (roller.inertia, its mass or width, or
    mechanism.roller.mass as a solid disc of the follower radius)."""
    return deck.roller.moment_of_inertia(radius, face_mass(deck))


def marches_roller(deck) -> bool:
    """The elastic train marches the roller's spin: [roller] and [dynamics] with
    dynamics.roller = "marched" and a pin that lets the roller turn."""
    d, r = getattr(deck, "dynamics", None), getattr(deck, "roller", None)
    return d is not None and r is not None and d.roller == "marched" and r.pin != "locked"


def spin_tables(deck, kin, load_cap: float):
    """The roller's traction and pin tables on the kinematics' grid (SI) for the march: the
    roller effect's traction law (:class:`camtrain.roller.traction.Traction`) at
    ``dynamics.roller_load_levels`` loads from 0 to ``load_cap`` [N], uniform in W^(1/3)
    (LEVEL_POWER: finer at light load, where the roller slips most), and
    ``dynamics.roller_table_points`` sliding speeds clustered at zero (the grid of the roller's
    own inertial march); its pin torque at the same loads and as many roller speeds."""
    import numpy as np

    from camtrain.contact.model import CamContact
    from camtrain.dynamics.spin import RollerTables
    from camtrain.dynamics.spin.step import LEVEL_POWER
    from camtrain.roller.solve import clustered_grid
    from camtrain.roller.traction import Traction

    r = deck.roller
    contact = CamContact.from_deck(deck)
    radius = float(np.max(kin.follower_radius))
    grid = clustered_grid(deck.dynamics.roller_table_points)
    loads = load_cap * np.linspace(0.0, 1.0, deck.dynamics.roller_load_levels) ** LEVEL_POWER
    v0 = np.asarray(kin.sliding, dtype=float)
    n = v0.size
    vmax = float(np.max(np.abs(v0)))
    scale = np.abs(v0) + vmax + 1e-12
    # the angles of equal contact kinematics (a dwell) share their rows: computed once
    key = np.stack([np.broadcast_to(np.asarray(a, dtype=float), v0.shape)
                    for a in (kin.v_cam, kin.sliding, kin.radius_x, kin.radius_y)], axis=1)
    _, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    idx = np.repeat(first, grid.size)
    sliding = (scale[first, None] * grid[None, :]).ravel()
    table = np.zeros((n, loads.size, grid.size))
    for level, w in enumerate(loads[1:], start=1):
        load = np.full(n, w)
        traction = Traction(contact, kin, load, contact.hertz(kin, load), r.traction,
                            r.rolling_resistance, tabulated=True)
        rows = traction.force(sliding, idx).reshape(first.size, grid.size)
        table[:, level, :] = rows[np.ravel(inverse)]
    speed_scale = 2.0 * (vmax / radius + 1e-12)
    speeds = np.broadcast_to(speed_scale * grid[None, :], (loads.size, grid.size))
    pin = pin_of(deck).torque(speeds, np.broadcast_to(loads[:, None], speeds.shape))
    ratio = np.broadcast_to(np.asarray(kin.rocker_ratio, dtype=float), (n,)).copy()
    return RollerTables(theta=np.asarray(kin.theta, dtype=float), grid=grid, loads=loads,
                        traction=table, sliding_scale=scale, pin=np.asarray(pin, dtype=float),
                        speed_scale=speed_scale, v_s0=v0, ratio=ratio, radius=radius,
                        inertia=float(inertia_of(deck, radius)))
