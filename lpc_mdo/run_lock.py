"""One run per output folder: a lock file holding the process id of the run that writes there.

Two runs writing case files of the same names into one folder destroy each other's results
(SQLite then reports "attempt to write a readonly database" to one of them, after minutes of
work). A command that writes into an output folder takes its lock first: it creates
``.lpc-mdo.lock`` there exclusively, with its process id and that process's start time, and
removes it when it ends. A lock whose process no longer runs (a run killed with kill -9 or a
machine that went down) is stale and taken over; so is one whose process id now belongs to
another process (started at another time: the id was reused), and so is a lock without a start
time. Where start times cannot be read (no ``/proc``), any running process of that id holds the
lock.
"""

import contextlib
import os
from pathlib import Path

#: Name of the lock file in an output folder.
LOCK_NAME = ".lpc-mdo.lock"


class LockFailed(RuntimeError):
    """The lock file of an output folder cannot be created (``reason`` says why)."""

    def __init__(self, path, reason):
        super().__init__(f"{path}: {reason}")
        self.path, self.reason = path, reason


class FolderInUse(RuntimeError):
    """The output folder is locked by another running process; ``pid`` is that process."""

    def __init__(self, folder, pid):
        super().__init__(f"{folder} is in use by process {pid}")
        self.folder, self.pid = folder, pid


def _start_time(pid):
    """Return the start time of a process (clock ticks since boot, /proc), or None."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text(encoding="ascii", errors="replace")
    except OSError:
        return None
    # Field 22 (starttime), counted after the command name in parentheses (which may hold
    # spaces and parentheses itself).
    fields = stat[stat.rfind(")") + 2 :].split()
    return fields[19] if len(fields) > 19 else None


def _running(pid, started):
    """
    Return whether the process that wrote a lock (id ``pid``, start time ``started``) runs.

    A process of that id that started at another time is another process (the id was reused).
    """
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # it runs, under another user
        pass
    now = _start_time(pid)
    if now is None:  # no process table: any running process of that id holds the lock
        return True
    # A lock without a start time, where start times can be read, was not written by a run of
    # this lpc-mdo on this machine (which always writes one): stale.
    return started is not None and now == started


def _owner(path):
    """Return (process id, start time or None) of a lock file, or None when unreadable."""
    try:
        words = path.read_text(encoding="ascii").split()
        return int(words[0]), (words[1] if len(words) > 1 else None)
    except (OSError, ValueError, UnicodeDecodeError, IndexError):
        return None


@contextlib.contextmanager
def folder_lock(folder):
    """
    Hold the lock of an output folder (created if missing) for the duration of the block.

    Raises
    ------
    FolderInUse
        When another running process holds it.
    """
    folder = Path(folder)
    path = folder / LOCK_NAME
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise LockFailed(folder, err.strerror or str(err)) from err
    if path.is_dir() or path.is_symlink():
        raise LockFailed(path, "a folder or link of the lock file's name is in the way")
    for _ in range(3):  # a stale lock is removed once; a race with another starter retried
        try:
            fd = os.open(path, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644)
        except FileExistsError:
            owner = _owner(path)
            if owner is not None and owner[0] != os.getpid() and _running(*owner):
                raise FolderInUse(folder, owner[0]) from None
            with contextlib.suppress(FileNotFoundError):
                path.unlink()  # stale: its process has ended
            continue
        except OSError as err:
            raise LockFailed(path, err.strerror or str(err)) from err
        with os.fdopen(fd, "w", encoding="ascii") as fh:
            fh.write(f"{os.getpid()} {_start_time(os.getpid()) or ''}".strip() + "\n")
        break
    else:
        owner = _owner(path)
        raise FolderInUse(folder, None if owner is None else owner[0])
    try:
        yield path
    finally:
        owner = _owner(path)
        if owner is not None and owner[0] == os.getpid():
            with contextlib.suppress(FileNotFoundError):
                path.unlink()
