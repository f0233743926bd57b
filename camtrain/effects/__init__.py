"""Effects: each takes the deck model and the products of earlier effects, adds its per-angle
arrays and metrics to the result, and returns its own products.

Which effects exist, what they need and produce, and which deck kinds they serve is listed in one
place, :mod:`camtrain.catalogue`; the scene plan (:mod:`camtrain.scene`) decides which run.
"""
