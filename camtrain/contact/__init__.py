"""The cam/follower contact: Hertz field, lubricant film, friction, friction torque and power of
one cam/follower pair, and the valve-train guides. Physics only: inputs are the deck model,
a :class:`camtrain.mechanisms.Kinematics` and per-angle loads; outputs are frozen products
(:mod:`camtrain.contact.products`) that the effects hand on and write to the result."""
