"""Lift laws from the valve events an engine needs (`camtrain design`, docs/design.md).

Modules: :mod:`.construct` (the events and limits -> a quintic B-spline lift, least jerk
energy), :mod:`.check` (every event and limit measured on a lift law) and :mod:`.command` (a
deck's [design] section -> the designed deck and its report).
"""
