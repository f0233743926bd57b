"""The validation tier of every test (``pytest -m literature``, ``-m derived``, ...).

Tiers (the developers' guide):

* ``literature``  a published number; the source's table, figure or equation is named in the
  test (or in its module docstring) and in docs/references/, tolerance from the print precision.
* ``derived``     hand computations from the same formulas (docs/references/ DERIVED values,
  closed forms, limits that reduce a model to one camtrain already has).
* ``golden``      regression files of the shipped decks (tests/golden).
* ``convergence`` the observed order of a discretised solver, fitted.
* ``behaviour``   properties, hard cases, input errors, plumbing, outputs, the CLI.

A test module is in the tier ``FILES`` gives it (default: behaviour); ``TESTS`` moves single
tests of a module to another tier (key: a substring of the test's node id). A test may also carry
a tier marker itself, which wins.
"""
from __future__ import annotations

TIERS = ("literature", "derived", "golden", "convergence", "behaviour")

FILES = {
    "tests/golden/": "golden",
    "tests/bearings/test_bearings_published.py": "literature",
    "tests/bearings/test_finite_published.py": "literature",
    "tests/engine/test_ruston_yang.py": "literature",
    "tests/engine/test_ruston_deck.py": "literature",
    "tests/engine/test_zeta_deck.py": "literature",
    "tests/integration_camshaft/test_pinto_camshaft_ball.py": "literature",
    "tests/integration_camshaft/test_zeta_camshaft_yang.py": "literature",
    "tests/tribology/test_validation.py": "literature",
    "tests/tribology/test_pinto_valve_dataset.py": "literature",
    "tests/test_decks_kinematics.py": "literature",
    "tests/formulas/test_formulas_anchors.py": "derived",
    "tests/formulas/test_engine_friction.py": "derived",
    "tests/numerics/test_roots.py": "derived",
    "tests/formulas/test_formulas_cross.py": "derived",
    "tests/formulas/test_formulas_zeta_cycle.py": "derived",
    "tests/tribology/test_harrison.py": "derived",
    "tests/tribology/test_loads.py": "derived",
    "tests/tribology/test_desmodromic.py": "derived",
    "tests/tribology/test_greenwood_tripp.py": "derived",
    "tests/lubrication/test_reynolds_limits.py": "derived",
    "tests/bearings/test_finite_limits.py": "derived",
    "tests/lift/test_lift_williams.py": "derived",
    "tests/mechanisms/test_checks_and_identities.py": "derived",
    "tests/test_harrison_floor.py": "derived",
    "tests/piston/test_gas.py": "literature",
    "tests/piston/test_ring_march.py": "literature",
    "tests/piston/test_pack.py": "literature",
    "tests/piston/test_flame.py": "literature",
    "tests/piston/test_ring_film.py": "derived",
    "tests/lubrication/test_ehl_line.py": "literature",
}

TESTS = {
    "test_ehl_line.py::test_fft_deflection": "derived",
    "test_ehl_line.py::test_dowson_higginson_density_hand_values": "derived",
    "test_ehl_line.py::test_hertz_pressure_gives": "derived",
    "test_ehl_line.py::test_light_load_tends_to_martin": "derived",
    "test_ehl_line.py::test_high_load_tends_to_hertz": "derived",
    "test_ehl_line.py::test_compressibility_lowers": "behaviour",
    "test_ehl_line.py::test_friction_": "behaviour",
    "test_ehl_line.py::test_cli_": "behaviour",
    "test_ehl_line.py::test_matrix_free_steps": "behaviour",
    "test_ehl_line.py::test_multilevel_grids": "behaviour",
    "test_ehl_line.py::test_four_grid_preconditioner": "behaviour",
    "test_ehl_line.py::test_outlet_spike": "convergence",
    "test_ring_march.py::test_observed_order_of_the_film_march": "convergence",
    "test_ring_march.py::test_symmetric_barrel_gives_mirror_symmetric_films": "derived",
    "test_ring_march.py::test_liner_speed_is_the_exact_slider_crank": "derived",
    "test_gas.py::test_orifice_flow_reverses_with_the_pressures": "derived",
    "test_gas.py::test_mass_conserved_over_the_cyclic_solution": "derived",
    "test_gas.py::test_lsoda_reference_agrees_with_the_trapezoid": "derived",
    "test_flame.py::test_oil_control_ring_force": "derived",
    "test_flame.py::test_skirt_is_a_couette_film": "derived",
    "test_harrison.py::test_power_loss_against_ball": "literature",
    "test_desmodromic.py::test_power_against_ball": "literature",
    "test_reynolds_limits.py::test_semi_analytic_and_finite_volume_agree_to_second_order":
        "convergence",
    "test_reynolds_limits.py::test_node_convergence": "convergence",
    "test_squeeze_level1.py::test_first_order_in_the_angle_step": "convergence",
    "test_averaged_reynolds.py::test_march_orders_in_the_step": "convergence",
    "test_averaged_reynolds.py::test_no_squeeze_is_the_per_angle_steady_solution": "derived",
    "test_averaged_reynolds.py::test_constant_conditions_converge_to_steady": "derived",
    "test_averaged_reynolds.py::test_smooth_rigid_steady_limit_is_martin": "derived",
    "test_averaged_reynolds.py::test_load_balance_at_every_loaded_angle": "derived",
    "test_averaged_reynolds.py::test_mirrored_cycle_gives_the_same_film": "derived",
    "test_averaged_reynolds.py::test_level2_marches_agree_as_the_step_falls": "convergence",
    "test_squeeze_level1.py::test_zero_squeeze_is_the_steady_formula": "derived",
    "test_squeeze_level1.py::test_squeeze_factors_of_eq5": "derived",
    "test_squeeze_level1.py::test_march_satisfies_eq5_with_its_squeeze_ratio": "derived",
    "test_squeeze_level1.py::test_film_is_trapped_at_zero_entrainment": "literature",
    "test_finite_limits.py::test_pure_squeeze_closed_form_and_second_order_convergence":
        "convergence",
    "test_orbit_properties.py::test_periodic_and_resolution_converges": "convergence",
    "test_lift_table.py::test_convergence_order_under_grid_refinement": "convergence",
    "test_contact_geometry.py::test_zero_entrainment_power_loss_converges_with_angle_points":
        "convergence",
    "test_lift_and_bearing_extremes.py::test_bearing_orbit_converges_with_step_tolerance":
        "convergence",
}


def tier_of(nodeid: str, own: set[str]) -> str:
    """The tier of a test from its node id (``tests/x.py::test_y[...]``) and its own markers."""
    mine = own & set(TIERS)
    if mine:
        return sorted(mine)[0]
    for key, tier in TESTS.items():
        if key in nodeid:
            return tier
    path = nodeid.split("::", 1)[0]
    for prefix, tier in FILES.items():
        if path.startswith(prefix):
            return tier
    return "behaviour"
