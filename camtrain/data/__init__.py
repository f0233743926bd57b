"""Data sets shipped with camtrain (lift tables of the sources)."""
