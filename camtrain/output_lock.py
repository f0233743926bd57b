"""One writer per output directory: an advisory lock beside it for as long as a command runs.

Two commands writing the same directory at once would interleave or silently replace each
other's files. :func:`output_lock` takes an exclusive ``flock`` on a hidden ``.<name>.lock`` file
beside the directory and refuses (exit 2, naming the directory and the holder's process id) when
another process holds it. The lock file is removed when the command ends, also on an error,
Ctrl-C or SIGTERM. On a system without ``fcntl`` (Windows) no lock is taken.

It also refuses an output path that is a dangling symbolic link (the directory could not be
made there) or an existing file.
"""
from __future__ import annotations

import os
from contextlib import contextmanager
from pathlib import Path

from camtrain.errors import InputError, Problem


def checked_output_dir(out_dir: Path, option: str = "--out") -> Path:
    """``out_dir`` made absolute, refused (exit 2) when it cannot be a directory."""
    out_dir = Path(out_dir)
    if out_dir.is_symlink() and not out_dir.exists():
        raise InputError(Problem(option, "is a symbolic link to a path that does not exist",
                                 str(out_dir), "a directory, or a path where one can be made",
                                 f"It points at {os.readlink(out_dir)!r}; remove the link or "
                                 "give another output directory"))
    if out_dir.exists() and not out_dir.is_dir():
        raise InputError(Problem(option, "is an existing file, not a directory", str(out_dir),
                                 "a directory, or a path where one can be made"))
    resolved = out_dir.resolve()
    if resolved.parent == resolved:
        raise InputError(Problem(option, "is the file-system root", str(out_dir),
                                 "a directory below it"))
    return resolved


def lock_path(out_dir: Path) -> Path:
    return out_dir.parent / f".{out_dir.name}.lock"


@contextmanager
def output_lock(out_dir: Path, option: str = "--out"):
    """Hold the lock of ``out_dir`` for the block (see the module docstring)."""
    try:
        import fcntl
    except ImportError:  # pragma: no cover - no advisory locks on this system
        yield
        return
    target = checked_output_dir(out_dir, option)
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(Problem(option, f"its parent directory cannot be made: {exc.strerror}",
                                 str(out_dir))) from None
    path = lock_path(target)
    fd = _acquire(fcntl, path, out_dir, option)
    if fd is None:
        yield
        return
    try:
        yield
    finally:
        Path(path).unlink(missing_ok=True)   # before the lock goes: see _acquire
        os.close(fd)


def _acquire(fcntl, path: Path, shown: Path, option: str) -> int | None:
    """An open, exclusively locked descriptor of ``path``. A lock taken on a file that its holder
    unlinked meanwhile is worthless (the next process makes a new file), so the descriptor must
    still be the file at ``path`` once locked; otherwise it is tried again. None when no lock
    file can be made there."""
    while True:
        try:
            fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
        except OSError:
            # a parent directory this user cannot write (an existing output directory in it
            # still can be): the command runs unlocked rather than not at all
            return None
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            holder = os.read(fd, 32).decode("ascii", "replace").strip() or "?"
            os.close(fd)
            raise InputError(Problem(
                option, f"another camtrain process (pid {holder}) is writing this directory",
                str(shown), "one process per output directory",
                "Wait for it to finish, or give another output directory")) from None
        try:
            same = os.fstat(fd).st_ino == os.stat(path).st_ino
        except FileNotFoundError:
            same = False
        if same:
            os.ftruncate(fd, 0)
            os.write(fd, f"{os.getpid()}\n".encode())
            return fd
        os.close(fd)
