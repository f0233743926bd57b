"""Shared helpers that turn physics results into Result columns, metrics and warnings for
several effects (journal-bearing orbits, elastic-shaft reactions and orders, crank-bearing
tables). They are not effects: no ``missing``/``reason``/``run``, not in the catalogue."""
