"""The one atomic write of contactlib, behind every file it writes.

:func:`atomic_write` fills a temporary file in the destination folder, then
:func:`os.replace`, with SIGINT and SIGTERM held meanwhile; an existing
destination that is not a regular file (a link, a pipe, a device) is
refused, a full disk is one line naming the file, and the temporary files of
killed writers are removed. :func:`check_writable` does the first steps
before any work, so that an unwritable output is refused before a long
computation.
"""

from __future__ import annotations

import errno
import hashlib
import os
import signal
import socket
import stat
import tempfile
import threading
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

__all__ = ["atomic_write", "check_writable"]


_FILE_KINDS = ((stat.S_ISLNK, "a symbolic link"), (stat.S_ISFIFO, "a named pipe (FIFO)"),
               (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
               (stat.S_ISSOCK, "a socket"))


def _refuse_special(path: Path) -> None:
    """Refuse to replace an existing ``path`` that is not a regular file (or a folder).

    The atomic write replaces whatever is at ``path``: a symbolic link, a
    named pipe or a device (``/dev/null``) would be replaced by a file, so
    only a regular file (or nothing) may be there.
    """
    try:
        mode = os.lstat(path).st_mode
    except (FileNotFoundError, NotADirectoryError):
        return
    except OSError:  # e.g. a name too long: the temporary file reports it
        return
    if stat.S_ISDIR(mode):
        raise IsADirectoryError(f"{path} is a folder, not a file")
    for test, kind in _FILE_KINDS:
        if test(mode):
            raise FileExistsError(f"{path} is {kind}, not a regular file: refusing to "
                                  f"replace it (give the path of a regular file)")


# temporary files: ".<name>.<host>-<pid>-<random>.tmp", so that a writer can tell a stale
# one (left by a killed process of this machine) from one that is being written
_HOST_TAG = hashlib.sha256(socket.gethostname().encode("utf-8", "replace")).hexdigest()[:6]
# convention: an hour-old temporary file of an earlier version counts as stale
_LEGACY_TMP_AGE = 3600.0  # s: ".<name>.<random>.tmp" of earlier versions, no owner recorded


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # e.g. another user's process
        return True
    return True


def _remove_stale_temporaries(path: Path) -> None:
    """Remove temporary files of ``path`` left by killed writers (SIGKILL, power cut).

    Only those of this machine whose process is gone, and those of earlier
    versions (no owner recorded) older than an hour; never another running
    writer's.
    """
    prefix, own = f".{path.name}.", f"{_HOST_TAG}-{os.getpid()}-"
    try:
        names = [n for n in os.listdir(path.parent) if n.startswith(prefix)
                 and n.endswith(".tmp")]
    except OSError:
        return
    for name in names:
        middle = name[len(prefix):-len(".tmp")]
        parts = middle.split("-")
        stale = False
        if len(parts) == 3 and parts[0] == _HOST_TAG and parts[1].isdigit():
            stale = not middle.startswith(own) and not _pid_alive(int(parts[1]))
        elif len(parts) == 1 and len(middle) == 8:  # tempfile's random part alone
            try:
                stale = time.time() - os.lstat(path.parent / name).st_mtime > _LEGACY_TMP_AGE
            except OSError:
                continue
        if stale:
            try:
                (path.parent / name).unlink()
            except OSError:
                pass


def _atomic_target(path: str | os.PathLike[str]) -> tuple[Path, Path]:
    """Destination and a fresh temporary file beside it (parents created).

    Raises
    ------
    IsADirectoryError
        If ``path`` is a folder.
    FileExistsError
        If ``path`` exists and is not a regular file (a symbolic link, a
        named pipe, a device such as ``/dev/null``, a socket).
    """
    path = Path(path)
    if path.is_dir():
        raise IsADirectoryError(f"output path is a directory: {path}")
    _refuse_special(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp_name = tempfile.mkstemp(prefix=f".{path.name}.{_HOST_TAG}-{os.getpid()}-",
                                    suffix=".tmp", dir=path.parent)
    os.close(fd)
    umask = os.umask(0)  # mkstemp makes the file 0600: give it the usual permissions
    os.umask(umask)
    os.chmod(tmp_name, 0o666 & ~umask)
    return path, Path(tmp_name)


_DEFERRED = (signal.SIGINT, signal.SIGTERM)


class _DeferSignals:
    """Hold SIGINT and SIGTERM while a file is written and renamed (main thread only).

    An interrupt inside netCDF4/HDF5 can leave a lock held (Ctrl-C hung the
    write) and SIGTERM's default action ends the process before the
    temporary file is removed. Inside the ``with`` block a signal is only
    noted; :meth:`deliver` hands it on to the handler that was in place,
    after a cleanup. Leaving the block delivers what is still noted.
    """

    def __init__(self) -> None:
        self.received: list[int] = []
        self.previous: dict[int, Any] = {}

    def __enter__(self) -> _DeferSignals:
        if threading.current_thread() is not threading.main_thread():
            return self  # Python runs signal handlers in the main thread only
        for sig in _DEFERRED:
            handler = signal.getsignal(sig)
            if handler is None or handler is signal.SIG_IGN:
                continue  # not installed from Python, or ignored: left alone
            try:
                signal.signal(sig, self._note)
            except (ValueError, OSError):
                continue
            self.previous[sig] = handler
        return self

    def _note(self, signum: int, frame: Any) -> None:
        self.received.append(signum)

    def deliver(self, cleanup: Callable[[], None] = lambda: None) -> None:
        """If a signal came: restore the handlers, clean up, hand the signal on.

        ``cleanup`` runs before a signal whose action ends the process
        (``SIG_DFL``), and when a Python handler raises (KeyboardInterrupt);
        a handler that returns lets the caller go on.
        """
        if not self.received:
            return
        previous, received = self.previous, list(dict.fromkeys(self.received))
        self._restore()
        self.received = []
        for sig in received:
            if previous.get(sig) is signal.SIG_DFL:
                cleanup()
                signal.raise_signal(sig)  # ends the process
            else:
                try:
                    signal.raise_signal(sig)  # runs the handler: KeyboardInterrupt, ...
                except BaseException:
                    cleanup()
                    raise

    def _restore(self) -> None:
        for sig, handler in self.previous.items():
            signal.signal(sig, handler)
        self.previous = {}

    def __exit__(self, *exc: Any) -> None:
        self.deliver()
        self._restore()


def _disk_full(folder: Path) -> bool:
    """Whether the file system of ``folder`` has (next to) no space left."""
    try:
        st = os.statvfs(folder)
    except OSError:
        return False
    blocks = st.f_bfree if hasattr(os, "geteuid") and os.geteuid() == 0 else st.f_bavail
    return blocks * st.f_frsize < 1 << 20


def _write_error(path: Path, tmp: Path, exc: BaseException) -> BaseException | None:
    """One line naming ``path`` and the cause for an error of a write; None: keep ``exc``."""
    code = getattr(exc, "errno", None)
    if code in (errno.ENOSPC, errno.EDQUOT) or (
            isinstance(exc, (OSError, RuntimeError)) and _disk_full(tmp.parent)):
        reason = ("disk quota exceeded" if code == errno.EDQUOT
                  else "no space left on device")
        err = OSError(f"cannot write {path}: {reason} (nothing was written; free some "
                      f"space and run again)")
        err.errno = errno.EDQUOT if code == errno.EDQUOT else errno.ENOSPC
        return err
    if type(exc) is RuntimeError:  # netCDF4's errors name no file
        return RuntimeError(f"cannot write {path}: {exc}")
    return None


def atomic_write(path: str | os.PathLike[str], write: Callable[[Path], None]) -> Path:
    """The one atomic write of contactlib: ``write(tmp)``, then ``os.replace(tmp, path)``.

    ``write`` fills a fresh temporary file beside ``path`` (same folder, so
    the replace is atomic; parent folders are created). On any failure the
    temporary file is removed and ``path`` is left as it was. SIGINT and
    SIGTERM are held while the file is written (in the main thread): one
    that comes then removes the temporary file, leaves ``path`` as it was
    and is handed on (KeyboardInterrupt, or the end of the process by
    SIGTERM). After a successful write the temporary files of ``path`` left
    by killed processes are removed. A full disk is an :class:`OSError`
    naming ``path`` and saying "no space left on device".
    """
    with _DeferSignals() as held:
        path, tmp = _atomic_target(path)

        def discard() -> None:
            tmp.unlink(missing_ok=True)

        try:
            write(tmp)
            held.deliver(discard)  # an interrupt during the write: no file
            os.replace(tmp, path)
        except BaseException as exc:
            replacement = _write_error(path, tmp, exc) if isinstance(exc, Exception) else None
            discard()
            held.deliver()
            if replacement is not None:
                raise replacement from exc
            raise
        _remove_stale_temporaries(path)
    return path


def check_writable(path: str | os.PathLike[str]) -> Path:
    """Check, before any work, that a writer of this module can write ``path``.

    Does what :func:`write_dataset` and the other writers do first (create
    missing parent folders, create the temporary file beside the
    destination), then removes the temporary file and every folder it
    created, so nothing is left behind. This catches an unwritable folder, a
    path through a file, a name too long (the temporary name is longer than
    the destination's) and an existing path that is not a regular file (a
    symbolic link, a named pipe, a device such as ``/dev/null``: the write
    would replace it) before a long computation rather than after it.

    Parameters
    ----------
    path : str or os.PathLike
        The destination file.

    Returns
    -------
    pathlib.Path
        ``path``; missing parent folders will be created by the writer.

    Raises
    ------
    OSError
        One line naming ``path`` and the reason (never the temporary name).
    """
    if os.fspath(path).strip() == "" or Path(path).name in ("", ".", ".."):
        raise OSError(f"{os.fspath(path)!r} is not a file name")
    path = Path(path)
    if path.is_dir():
        raise IsADirectoryError(f"{path} is a folder, not a file")
    _refuse_special(path)
    ancestors = [a for a in path.parents]
    for folder in ancestors:  # the nearest existing ancestor must be a folder
        if folder.exists() or folder.is_symlink():
            if not folder.is_dir():
                raise NotADirectoryError(f"cannot write {path}: {folder} is a file, not a folder")
            break
    created = [a for a in ancestors if not (a.exists() or a.is_symlink())]
    tmp: Path | None = None
    try:
        _, tmp = _atomic_target(path)
    except OSError as exc:
        reason = exc.strerror or type(exc).__name__
        if exc.errno == errno.ENAMETOOLONG:
            reason = "file name too long"
        raise type(exc)(f"cannot write {path}: {reason.lower()}") from None
    finally:
        if tmp is not None:
            tmp.unlink(missing_ok=True)
        for folder in created:  # deepest first
            try:
                folder.rmdir()
            except OSError:
                pass
    return path
