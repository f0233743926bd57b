"""The zero-entrainment finding in one wording, for the effect that owns the entrainment of a
cam contact: the kinematics effect (the non-rotating follower's V_c + V_f) or, when the
follower's roller turns, the roller effect (V_c + V_roll)."""
from __future__ import annotations

import math

#: what the zero-entrainment warning says of the steady film, naming the option that changes it
STEADY_FILM_NOTE = (" (tribology.film_model = \"steady\" has no squeeze film; \"squeeze\" or "
                    "\"averaged_reynolds\" marches the film through it)")


def zero_entrainment_warning(angles, label: str = "", carried: str = "") -> str:
    """The warning for the angles [rad] where the entrainment passes through zero ('' if none);
    ``carried`` says what carries the load through it instead of the steady film's note."""
    if not len(angles):
        return ""
    where = ", ".join(f"{math.degrees(a):.2f}" for a in angles)
    return (f"entrainment velocity passes through zero{label} at {where} deg: the steady EHL "
            "film vanishes there" + (carried or STEADY_FILM_NOTE))
