"""Effects: each takes the model and the result so far, and adds its per-angle arrays and metrics.

An effect module exposes ``run(deck, state)``; the scene plan (camtrain.scene) decides which run.
"""
