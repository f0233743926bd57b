"""Names resolved on first use, so that a run imports only the modules its deck and command
need: a "module:attribute" reference (deck kinds, deferred deck sections, study commands) and a
package's attributes imported from its submodules when first asked for (PEP 562)."""
from __future__ import annotations

import importlib


def resolve(reference: str):
    """The object a "module:attribute" reference names; the module is imported now."""
    module, attribute = reference.split(":")
    return getattr(importlib.import_module(module), attribute)


def package_attribute(package: str, table: dict[str, str], name: str, namespace: dict):
    """A package's ``__getattr__`` (PEP 562): ``name`` from the submodule that ``table`` names
    for it, bound into the package's ``namespace`` so that the next access is a plain one."""
    if name not in table:
        raise AttributeError(f"module {package!r} has no attribute {name!r}")
    value = resolve(f"{package}.{table[name]}:{name}")
    namespace[name] = value
    return value
