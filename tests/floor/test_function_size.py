"""The size of compiled kernels and of the dynamics' functions, counted from the source (AST).

A numba kernel takes a few typed records, not a long list of positional arguments (the records
of camtrain/dynamics/records.py and camtrain/coupled/records.py): none takes more than
MAX_KERNEL_ARGUMENTS. No function of the valve-train dynamics and the coupled camshaft is longer
than MAX_LINES (its docstring included)."""
from __future__ import annotations

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[2] / "camtrain"
MAX_KERNEL_ARGUMENTS = 16
MAX_LINES = 100
#: packages whose every function is held to MAX_LINES
SHORT = ("dynamics", "coupled")


def functions(path: Path):
    tree = ast.parse(path.read_text(encoding="utf-8"))
    for node in ast.walk(tree):
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            yield node


def compiled(node) -> bool:
    """Decorated by numba: njit, jit, numba.njit(...), vectorize, ..."""
    for d in node.decorator_list:
        target = d.func if isinstance(d, ast.Call) else d
        name = target.attr if isinstance(target, ast.Attribute) else getattr(target, "id", "")
        if name in ("njit", "jit", "vectorize", "guvectorize", "cfunc", "generated_jit"):
            return True
    return False


def arguments(node) -> int:
    a = node.args
    return (len(a.posonlyargs) + len(a.args) + len(a.kwonlyargs) + (a.vararg is not None)
            + (a.kwarg is not None))


def test_the_counts_see_a_long_kernel():
    source = ("from numba import njit\n@njit(cache=True)\ndef k(" +
              ", ".join(f"a{i}" for i in range(17)) + "):\n" + "    a0 += 1\n" * 101)
    (node,) = [n for n in ast.walk(ast.parse(source)) if isinstance(n, ast.FunctionDef)]
    assert compiled(node) and arguments(node) == 17
    assert node.end_lineno - node.lineno + 1 == 102


def test_no_compiled_function_takes_more_than_16_arguments():
    long = [f"{path.relative_to(PACKAGE.parent)}:{node.lineno} {node.name} ({arguments(node)})"
            for path in sorted(PACKAGE.rglob("*.py")) for node in functions(path)
            if compiled(node) and arguments(node) > MAX_KERNEL_ARGUMENTS]
    assert long == []


def test_no_function_of_the_dynamics_is_longer_than_100_lines():
    paths = [p for package in SHORT for p in sorted((PACKAGE / package).rglob("*.py"))]
    assert paths
    long = [f"{path.relative_to(PACKAGE.parent)}:{node.lineno} {node.name} "
            f"({node.end_lineno - node.lineno + 1} lines)"
            for path in paths for node in functions(path)
            if node.end_lineno - node.lineno + 1 > MAX_LINES]
    assert long == []
