"""One run per output folder: a lock file holding the process id of the run that writes there.

Two runs writing case files of the same names into one folder destroy each other's results
(SQLite then reports "attempt to write a readonly database" to one of them, after minutes of
work). A command that writes into an output folder takes its lock first: it creates
``.lpc-mdo.lock`` there exclusively, with its process id, and removes it when it ends. A lock
whose process no longer runs (a run killed with kill -9 or a machine that went down) is stale
and taken over.
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


def _running(pid):
    """
    Return whether an lpc-mdo process with this id runs (on this machine).

    Where the process table can be read (``/proc``), a process whose command line does not
    mention lpc-mdo (a process id reused since the lock was written) does not count.
    """
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # it runs, under another user
        pass
    try:
        command = Path(f"/proc/{pid}/cmdline").read_bytes()
    except OSError:
        return True  # no process table to read: a running process is taken as the owner
    return b"lpc" in command


def _owner(path):
    """Return the process id in a lock file, or None when it cannot be read as one."""
    try:
        return int(path.read_text(encoding="ascii").strip())
    except (OSError, ValueError, UnicodeDecodeError):
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
            pid = _owner(path)
            if pid is not None and pid != os.getpid() and _running(pid):
                raise FolderInUse(folder, pid) from None
            with contextlib.suppress(FileNotFoundError):
                path.unlink()  # stale: its process has ended
            continue
        except OSError as err:
            raise LockFailed(path, err.strerror or str(err)) from err
        with os.fdopen(fd, "w", encoding="ascii") as fh:
            fh.write(f"{os.getpid()}\n")
        break
    else:
        raise FolderInUse(folder, _owner(path))
    try:
        yield path
    finally:
        if _owner(path) == os.getpid():
            with contextlib.suppress(FileNotFoundError):
                path.unlink()
