"""Roller followers: the roller's rotation on its pin and the losses it brings (docs/rollers.md).

Physics on arrays, no deck: the roller's surface speed, slip and slide-roll ratio
(:mod:`.speeds`), the cam-roller traction and hydrodynamic rolling resistance (:mod:`.traction`),
the pin's friction torque (:mod:`.pin`), the roller's equation of motion solved quasi-statically
(:mod:`.quasi_static`) or marched to a periodic state (:mod:`.march`), and the product
:class:`.product.RollerMotion`. Any mechanism whose :class:`camtrain.mechanisms.base.Kinematics`
describes a line contact on a curved follower face can carry a roller: the physics reads only the
cam and follower surface speeds, the follower radius and the contact's load, Hertz field and film.
"""
