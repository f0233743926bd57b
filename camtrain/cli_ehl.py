"""`camtrain ehl`: the steady isothermal elastohydrodynamic line contact (docs/ehl.md).

Only click is imported at module level so that `camtrain --help` stays fast.
"""
from __future__ import annotations

import sys

import click

POSITIVE = click.FloatRange(min=0.0, min_open=True)


@click.command("ehl")
@click.option("--load", "load", type=POSITIVE, required=True,
              help="Load per unit contact length [N/mm].")
@click.option("--radius", type=POSITIVE, required=True, help="Reduced radius R [mm].")
@click.option("--speed", type=POSITIVE, required=True,
              help="Mean entrainment speed u_m = (u1 + u2)/2 [m/s].")
@click.option("--slide-roll", type=click.FloatRange(-2.0, 2.0), default=0.0, show_default=True,
              help="Slide-to-roll ratio (u2 - u1)/u_m [-] (friction only).")
@click.option("--modulus", type=POSITIVE, default=210.0, show_default=True,
              help="Young's modulus of both bodies [GPa].")
@click.option("--poisson", type=click.FloatRange(0.0, 0.5), default=0.3, show_default=True,
              help="Poisson's ratio of both bodies [-].")
@click.option("--eta0", type=POSITIVE, required=True, help="Ambient viscosity [Pa s].")
@click.option("--alpha", type=click.FloatRange(min=0.0), required=True,
              help="Pressure-viscosity coefficient [1/GPa].")
@click.option("--viscosity", type=click.Choice(["roelands", "barus"]), default="roelands",
              show_default=True)
@click.option("--density", type=click.Choice(["dowson_higginson", "incompressible"]),
              default="dowson_higginson", show_default=True)
@click.option("--cavitation", type=click.Choice(["reynolds", "half_sommerfeld"]),
              default="reynolds", show_default=True,
              help="Exit condition: reynolds (P = dP/dx = 0 at the film's rupture) or "
                   "half_sommerfeld (full-film pressure, its negative part dropped: a bound "
                   "for comparison with the older literature, docs/ehl.md).")
@click.option("--eyring", type=POSITIVE, default=None,
              help="Eyring stress [MPa]: friction by the Eyring law (default Newtonian).")
@click.option("--nodes", type=click.IntRange(64, 20000), default=1024, show_default=True,
              help="Grid points.")
@click.option("--inlet", type=click.FloatRange(max=-0.5), default=None,
              help="Inlet end [Hertz half-widths] (default automatic, -4.5 or wider).")
@click.option("--out", "out", type=click.Path(file_okay=False), default=None,
              help="Directory for ehl.csv and ehl.png.")
def ehl(load, radius, speed, slide_roll, modulus, poisson, eta0, alpha, viscosity, density,
        cavitation, eyring, nodes, inlet, out) -> None:
    """Solve a steady elastohydrodynamic line contact and print its key numbers."""
    from pathlib import Path

    from camtrain.formulas.elastic import reduced_modulus
    from camtrain.lubrication.ehl_friction import ehl_friction
    from camtrain.lubrication.ehl_line import (
        EHLResolution,
        LineContact,
        NotConverged,
        solve_ehl_line,
    )
    from camtrain.lubrication.ehl_oil import Oil
    from camtrain.report.ehl import key_numbers, write_ehl

    E_r = float(reduced_modulus(modulus * 1e9, poisson, modulus * 1e9, poisson))
    u1, u2 = speed * (1 - slide_roll / 2), speed * (1 + slide_roll / 2)
    oil = Oil(eta0, alpha * 1e-9, viscosity, density)
    contact = LineContact(load * 1e3, radius * 1e-3, E_r, u1, u2, oil)
    try:
        solution = solve_ehl_line(contact, EHLResolution(nodes=nodes, inlet=inlet,
                                                             cavitation=cavitation))
    except NotConverged as exc:
        click.echo(f"error: {exc}", err=True)
        sys.exit(4)
    friction = ehl_friction(solution, "eyring" if eyring else "newtonian",
                            None if eyring is None else eyring * 1e6)
    for name, value, unit in key_numbers(solution, friction):
        click.echo(f"{name:28s} {value:12.5g} {unit}")
    if out is not None:
        for path in write_ehl(solution, friction, Path(out)):
            click.echo(f"wrote {path}")
