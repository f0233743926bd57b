"""Compiled scalar numerics shared by the physics kernels (numba); below every physics package."""
