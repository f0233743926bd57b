"""The contact model of one cam/follower pair: Hertz field, film and friction as one object.

The load iteration (:mod:`camtrain.effects.loads`), the friction effect and the camshaft all use
the same :class:`CamContact`, built once from the deck for a pair. The film and the friction law
are chosen by name from registries (:data:`FILM_LAWS`, :data:`FRICTION_LAWS`), as the closed-form
film formulas are chosen in :mod:`camtrain.formulas.film`; a new law (a transient film, another
mixed-friction model) is one function registered with :func:`register_film_law` or
:func:`register_friction_law`, and every user of the contact model gets it.

Film law signature: ``law(contact, kin, load) -> FilmField`` (``load`` None: no contact load).
Friction law signature: ``law(contact, kin, load, hertz, h, use) -> F [N]`` on the angles ``use``
(loaded, finite film and Hertz field), with ``h`` the film the shear integral uses.
"""
from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from camtrain.components import CLOSING, MAIN
from camtrain.contact.products import FilmField, FrictionField, HertzField
from camtrain.identity_cache import by_identity

FilmLaw = Callable[..., FilmField]
FrictionLaw = Callable[..., np.ndarray]

#: film laws by name; see the module docstring for the signature
FILM_LAWS: dict[str, FilmLaw] = {}
#: friction laws by name (``tribology.friction_model``); see the module docstring
FRICTION_LAWS: dict[str, FrictionLaw] = {}


def register_film_law(name: str, law: FilmLaw) -> None:
    FILM_LAWS[name] = law


def register_friction_law(name: str, law: FrictionLaw) -> None:
    FRICTION_LAWS[name] = law


@dataclass(frozen=True)
class CamContact:
    """One cam/follower pair's contact: the reduced modulus E' [Pa], the cam width [m] (None:
    no Hertz line length given), the deck's lubricant and tribology options, and the names of the
    film and friction laws."""

    reduced_modulus: float
    width: float | None
    lubricant: object
    tribology: object
    film_law: str = "steady"
    friction_law: str = "cap"
    solver: object = None   #: the deck's resolution knobs (transient film laws read theirs)

    @classmethod
    def from_deck(cls, deck, component: str = MAIN) -> CamContact:
        """The contact of one pair of the deck's train (the closing pair has its own width);
        built once per deck model and pair (the model is immutable)."""
        if cls is not CamContact:
            return _contact_of(cls, deck, component)
        return _cached_contact(deck, component)

    def hertz(self, kin, load) -> HertzField:
        from camtrain.contact.hertz import hertz_field

        return hertz_field(self, kin, load)

    def film(self, kin, load=None) -> FilmField:
        """The film of the registered law; ``load`` None gives the load-free film."""
        return FILM_LAWS[self.film_law](self, kin, load)

    def friction(self, kin, load, hertz: HertzField, film: FilmField) -> FrictionField:
        """Friction force on the loaded angles with the given Hertz field and film."""
        load = np.asarray(load, dtype=float)
        h = film.for_shear
        use = (load > 0.0) & np.isfinite(h) & np.isfinite(hertz.pmax)
        force = np.zeros(load.shape)
        if np.count_nonzero(use):
            if film.friction is not None:   # the film law solved the contact
                force[use] = film.friction[use]
            else:
                force[use] = FRICTION_LAWS[self.friction_law](self, kin, load, hertz, h, use)
        return FrictionField(force=force, hertz=hertz, film=film, used=use)

    def solve(self, kin, load) -> FrictionField:
        """Hertz field, film and friction under a per-angle load (negative loads count as 0)."""
        load = np.maximum(np.asarray(load, dtype=float), 0.0)
        return self.friction(kin, load, self.hertz(kin, load), self.film(kin, load))


def _contact_of(cls, deck, component: str) -> CamContact:
    d = pair_deck(deck, component)
    film_law = d.tribology.film_model
    # the averaged Reynolds and elastic films solve the contact: their friction comes from the
    # same solution
    friction_law = ("averaged_reynolds" if film_law in ("averaged_reynolds", "ehl")
                    else d.tribology.friction_model)
    return cls(reduced_modulus=modulus(d), width=d.cam.width, lubricant=d.lubricant,
               tribology=d.tribology, film_law=film_law, friction_law=friction_law,
               solver=d.solver)


@by_identity
def _cached_contact(deck, component: str) -> CamContact:
    return _contact_of(CamContact, deck, component)


def modulus(deck) -> float:
    """Reduced modulus E' of the deck's cam and follower materials [Pa]."""
    from camtrain.formulas import reduced_modulus

    m = deck.materials
    return float(reduced_modulus(m.cam_modulus, m.cam_poisson, m.follower_modulus,
                                 m.follower_poisson))


def pair_deck(deck, component: str = MAIN):
    """The deck as one pair sees it: the closing pair of a desmodromic train has its own cam
    width."""
    c = deck.mechanism.closing
    if component != CLOSING or c is None or c.width is None:
        return deck
    return replace(deck, cam=replace(deck.cam, width=c.width))


# Deck-level conveniences (scripts and tests): one pair's contact physics from the deck.

def contact_hertz(deck, kin, load) -> HertzField:
    return CamContact.from_deck(deck).hertz(kin, load)


def contact_film(deck, kin, load=None) -> FilmField:
    return CamContact.from_deck(deck).film(kin, load)


def contact_friction(deck, kin, load) -> FrictionField:
    return CamContact.from_deck(deck).solve(kin, load)


def _register_laws() -> None:
    from camtrain.contact import film, friction, transient, transient_ehl

    register_film_law("steady", film.steady_film)
    register_film_law("squeeze", transient.squeeze_film)
    register_film_law("averaged_reynolds", transient.averaged_reynolds_film)
    register_film_law("ehl", transient_ehl.ehl_film)
    register_friction_law("averaged_reynolds", friction.film_solution_friction)
    for name in ("cap", "lambda", "lambda_cap"):
        register_friction_law(name, friction.ball_yang_friction)
    register_friction_law("greenwood_tripp", friction.greenwood_tripp_law)


_register_laws()
