"""Tests of the middle floor: catalogue, plan, runner, products, imports."""
