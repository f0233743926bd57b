"""A compile says so once, by name; a cached family says nothing (camtrain.numerics.compile_notice)."""
from __future__ import annotations

from camtrain.numerics import compile_notice


class _Index:
    def __init__(self, overloads):
        self.overloads = overloads

    def _load_index(self):
        return self.overloads


class _Kernel:
    """Stands for a numba dispatcher: its disk cache's index holds ``overloads``."""

    def __init__(self, overloads):
        self._cache = type("Cache", (), {"_cache_file": _Index(overloads)})()


def test_an_uncached_family_is_announced_once_by_name(monkeypatch):
    heard = []
    monkeypatch.setattr(compile_notice, "_announced", set())
    compile_notice.listen(heard.append)
    try:
        cold = [_Kernel({}), _Kernel({"sig": 1})]
        assert compile_notice.announce("journal-orbit", cold)
        assert not compile_notice.announce("journal-orbit", cold)
        assert not compile_notice.announce("ring-film", [_Kernel({"sig": 1})])
    finally:
        compile_notice.listen(None)
    assert heard == [compile_notice.message("journal-orbit")]
    assert heard[0].startswith("compiling the journal-orbit kernels, once per installation, about")


def test_a_numba_without_this_cache_layout_is_not_guessed_at():
    assert compile_notice.is_cached(object())


def test_the_installed_numba_has_the_cache_index_read():
    """is_cached reads numba's own index; on this numba that read works (returns a dict), so a
    compile is announced rather than silently assumed cached."""
    from camtrain.bearings import _orbit_march

    assert isinstance(_orbit_march.march_orbit._cache._cache_file._load_index(), dict)


def test_every_family_names_its_compile_time():
    for family in ("journal-orbit", "valve-train dynamics", "shaft-and-trains", "ring-film"):
        assert "about" in compile_notice.message(family)
