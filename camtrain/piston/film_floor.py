"""The ring film march's floor, a plain number the reports read without the compiled kernel."""

#: The film march's floor [m]: 0.1 nm, a dry ring carrying its load in boundary friction. A
#: film at the floor is not a film thickness but "no oil film"; reports say so rather than
#: print or plot the number.
FILM_FLOOR = 1e-10


def at_floor(film) -> bool:
    """Whether a film [m] (a number or an array, elementwise) sits at the march's floor."""
    return film <= FILM_FLOOR * (1.0 + 1e-6)
