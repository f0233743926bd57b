"""camtrain: valve-train tribology and mechanics from a text deck."""
__version__ = "0.1.0"
