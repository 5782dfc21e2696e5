"""contactlib.io against damaged files, hostile paths, interrupts and a full disk (issue 42,
items 8 and 9).

* Intermediates carry a content check (npz: the ``contactlib_sha256`` array; netCDF: the
  ``contactlib_sha256`` global attribute): a changed, truncated or bit-flipped file is a
  :class:`contactlib.io.DamagedFileError` naming it, never used; case records are read
  strictly (a missing field is an error naming the field).
* An existing output that is not a regular file (FIFO, symbolic link, /dev/null) is refused.
* SIGINT and SIGTERM during a write end the process promptly and leave no temporary file.
* A full disk says "no space left on device" and names the file.
* Temporary files left by killed writers are removed by the next write of the same path.
* Duplicate keys in a YAML configuration are refused, naming the key and the line.
"""

from __future__ import annotations

import errno
import math
import os
import random
import signal
import stat
import subprocess
import sys
import textwrap
import time
import zipfile
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from contactlib import cli, io, stages
from contactlib.model import contact
from contactlib.result import Solution

from conftest import ENV


def _solution(stick_ratio: float = 0.5) -> Solution:
    xi = np.linspace(0.0, 1.0, 41)
    return Solution("sphere", 0.3, "default", 8, 0.0, stick_ratio, 0.15 * stick_ratio, xi,
                    np.sqrt(1 - xi**2), 0.1 * xi, 0.5 * xi, 1.02738,
                    frictional_work=0.001, iterations=5, residual_norm=6.3e-15,
                    message="note" if stick_ratio > 0.6 else "")


def _dataset() -> xr.Dataset:
    return io.to_dataset([_solution(0.2), _solution(0.5), _solution(0.9)])


@pytest.fixture(scope="module")
def records():
    return stages.solve_cases(contact("sphere", 0.3), "default", 16, [0.0, 0.5])


def _tmp_files(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.rglob("*.tmp"))


def _assert_damaged(err: pytest.ExceptionInfo, path: Path, *words: str) -> None:
    text = str(err.value)
    assert text.startswith(f"{path} is damaged or incomplete"), text
    assert "delete it" in text and "snakemake --rerun-incomplete" in text and "\n" not in text
    for word in words:
        assert word in text, (word, text)


# ----------------------------------------------------------------------------- npz records
def test_records_carry_a_checksum_and_every_field(tmp_path, records) -> None:
    path = io.write_records(records, tmp_path / "s.npz")
    with np.load(path) as data:
        names = set(data.files)
        assert "contactlib_sha256" in names and "none" in names
        assert "0/nodal_u" in names  # default method: computed
        assert set(data["none"].tolist()) == {f"{i}/elements" for i in range(2)}
    back = io.read_records(path)
    assert [r.resolved for r in back] == [r.resolved for r in records]
    assert all(r.elements is None for r in back)


@pytest.mark.parametrize("field", ["resolved", "error_estimate", "max_error"])
def test_a_record_field_removed_is_refused_by_name(tmp_path, records, field) -> None:
    """Issue 42: removing `resolved` (or an estimate) made the reader fill in a default."""
    path = io.write_records(records, tmp_path / "s.npz")
    with np.load(path) as data:
        arrays = {k: data[k] for k in data.files if k != f"1/{field}"}
    # rewritten as numpy would (the checksum kept, now wrong), ...
    np.savez(path, **arrays)
    with pytest.raises(io.DamagedFileError) as err:
        io.read_records(path)
    _assert_damaged(err, path, "does not match its checksum")
    # ... without the checksum, ...
    del arrays["contactlib_sha256"]
    np.savez(path, **arrays)
    with pytest.raises(io.DamagedFileError) as err:
        io.read_records(path)
    _assert_damaged(err, path, "no content checksum")
    # ... or through write_arrays (a valid checksum): the field is missing
    io.write_arrays(arrays, path)
    with pytest.raises(io.DamagedFileError) as err:
        io.read_records(path)
    _assert_damaged(err, path, f"case 1 has no field '{field}'")
    # only the explicit upgrade of an old layout fills in the default
    value = getattr(io.read_records(path, upgrade=True)[1], field)
    assert value is False if field == "resolved" else math.isnan(value)


def test_records_refuse_unknown_and_misplaced_fields(tmp_path, records) -> None:
    path = io.write_records(records, tmp_path / "s.npz")
    arrays = io.read_arrays(path)
    for extra in ({"1/colour": np.array(1)}, {"7/k": np.array(0.1)}, {"x": np.array(1)},
                  {"-1/k": np.array(0.1)}):
        io.write_arrays({**arrays, **extra}, path)
        with pytest.raises(io.DamagedFileError) as err:
            io.read_records(path)
        _assert_damaged(err, path, "case-record")
    bad = dict(arrays, none=np.array(["0/elements", "1/elements", "0/k"]))
    io.write_arrays(bad, path)
    with pytest.raises(io.DamagedFileError, match="both given and None"):
        io.read_records(path)


def test_read_arrays_verifies_the_checksum(tmp_path) -> None:
    path = io.write_arrays({"a": np.arange(5.0), "s": np.array("text")}, tmp_path / "a.npz")
    assert sorted(io.read_arrays(path)) == ["a", "s"]  # the check is not handed on
    with zipfile.ZipFile(path) as z:
        members = {n: z.read(n) for n in z.namelist()}
    # a changed array with a consistent zip (CRCs recomputed): only the checksum sees it
    changed = np.arange(5.0)
    changed[3] = 3.5
    members["a.npy"] = members["a.npy"][:-changed.nbytes] + changed.tobytes()
    with zipfile.ZipFile(path, "w") as z:
        for name, data in members.items():
            z.writestr(name, data)
    with pytest.raises(io.DamagedFileError) as err:
        io.read_arrays(path)
    _assert_damaged(err, path, "does not match its checksum")
    plain = tmp_path / "plain.npz"
    np.savez(plain, a=np.arange(3))
    with pytest.raises(io.DamagedFileError, match="no content checksum"):
        io.read_arrays(plain)
    np.testing.assert_array_equal(io.read_arrays(plain, require_checksum=False)["a"],
                                  np.arange(3))
    with pytest.raises(ValueError, match="reserved"):
        io.write_arrays({"contactlib_sha256": np.zeros(1)}, tmp_path / "r.npz")


# ----------------------------------------------------------------------------- netCDF
def test_dataset_checksum_round_trip(tmp_path) -> None:
    ds = _dataset()
    path = io.write_dataset(ds, tmp_path / "d.nc")
    with xr.open_dataset(path) as raw:
        assert len(raw.attrs["contactlib_sha256"]) == 64
    back = io.read_dataset(path, require_checksum=True)
    xr.testing.assert_identical(back, ds)  # the check is not handed on
    # a dataset opened with xarray itself (check attribute included) writes the same file
    with xr.open_dataset(path) as raw:
        again = io.write_dataset(raw.load(), tmp_path / "again.nc")
    assert again.read_bytes() == path.read_bytes()


def test_dataset_whose_attributes_netcdf_changes_still_checks(tmp_path, monkeypatch) -> None:
    """An attribute netCDF gives back differently (a one-item list comes back a scalar):
    the check is then taken over the content as it reads back (a second write)."""
    ds = _dataset().assign_attrs(single=[7], pair=[1.5, 2.5])
    ds["label"] = ("stick_ratio", np.array(["a", "bb", "ccc"], dtype="U3"))
    writes = []
    real = xr.Dataset.to_netcdf

    def counted(self, *args, **kwargs):
        writes.append(1)
        return real(self, *args, **kwargs)

    monkeypatch.setattr(xr.Dataset, "to_netcdf", counted)
    path = io.write_dataset(ds, tmp_path / "d.nc")
    assert len(writes) == 2
    back = io.read_dataset(path, require_checksum=True)
    assert int(back.attrs["single"]) == 7 and list(back["label"].values) == ["a", "bb", "ccc"]
    writes.clear()
    io.write_dataset(_dataset(), tmp_path / "plain.nc")
    assert len(writes) == 1  # the usual case: the content in memory is the file's


def _edit(path: Path, edit) -> None:
    netCDF4 = pytest.importorskip("netCDF4")
    with netCDF4.Dataset(path, "a") as nc:
        edit(nc)


@pytest.mark.parametrize("change", ["value", "coordinate", "attribute", "global", "flag"])
def test_a_changed_dataset_that_still_parses_is_refused(tmp_path, change) -> None:
    """Issue 42: a bit flipped where the file still parses went undetected."""
    path = io.write_dataset(_dataset(), tmp_path / "d.nc")

    def edit(nc) -> None:
        if change == "value":
            nc["friction_coefficient"][1] = 0.0750001
        elif change == "coordinate":
            nc["stick_ratio"][0] = 0.2000001
        elif change == "attribute":
            nc["resolved"].setncattr("long_name", "converged")
        elif change == "global":
            nc.setncattr("poisson_ratio", 0.31)
        else:
            nc["resolved"][0] = 1 - nc["resolved"][0]

    _edit(path, edit)
    with pytest.raises(io.DamagedFileError) as err:
        io.read_dataset(path)
    _assert_damaged(err, path, "does not match its checksum")


def test_dataset_without_checksum_reads_unless_required(tmp_path) -> None:
    """A user's dataset written by xarray itself reads; the workflow can insist on a check."""
    path = tmp_path / "user.nc"
    _dataset().to_netcdf(path, engine="netcdf4")
    assert float(io.read_dataset(path)["friction_coefficient"][1]) == 0.075
    with pytest.raises(io.DamagedFileError) as err:
        io.read_dataset(path, require_checksum=True)
    _assert_damaged(err, path, "no content checksum")


def test_workflow_dataset_without_checksum_is_refused(tmp_path) -> None:
    """A dataset with the workflow's provenance is the workflow's own: its check is required
    (one from an earlier version must be rebuilt, or read with require_checksum=False)."""
    path = tmp_path / "scene.nc"
    io.set_provenance(_dataset(), "scene", "abc123").to_netcdf(path, engine="netcdf4")
    with pytest.raises(io.DamagedFileError) as err:
        io.read_dataset(path)
    _assert_damaged(err, path, "no content checksum")
    assert io.read_dataset(path, require_checksum=False).attrs["scene"] == "scene"
    io.write_dataset(io.read_dataset(path, require_checksum=False), path)  # the upgrade
    assert io.read_dataset(path).attrs["scene_config_hash"] == "abc123"


@pytest.mark.parametrize("kind", ["npz", "nc"])
def test_random_bit_flips_are_refused_or_harmless(tmp_path, records, kind) -> None:
    """Every flip: DamagedFileError, or the very same content (zip dates, HDF5 spare bytes);
    never a raw exception (KeyError, ValueError, zlib.error, RuntimeError) or changed data."""
    if kind == "npz":
        good = io.write_records(records, tmp_path / "good.npz")
        ref = io.read_arrays(good)

        def read(path: Path):
            io.read_records(path)
            return io.read_arrays(path)

        def same(a, b) -> bool:
            return a.keys() == b.keys() and all(
                np.array_equal(a[k], b[k], equal_nan=a[k].dtype.kind == "f") for k in a)
    else:
        good = io.write_dataset(_dataset(), tmp_path / "good.nc")
        ref = io.read_dataset(good)
        read = io.read_dataset

        def same(a, b) -> bool:
            return a.identical(b)
    raw = good.read_bytes()
    rng = random.Random(42)
    bad = tmp_path / f"bad.{kind}"
    outcomes = {"damaged": 0, "same": 0}
    for _ in range(150):
        flipped = bytearray(raw)
        flipped[rng.randrange(len(raw))] ^= 1 << rng.randrange(8)
        bad.write_bytes(bytes(flipped))
        try:
            back = read(bad)
        except io.DamagedFileError as exc:
            assert str(exc).startswith(f"{bad} is damaged")
            outcomes["damaged"] += 1
            continue
        assert same(back, ref)
        outcomes["same"] += 1
    assert outcomes["damaged"] > 100, outcomes


# ----------------------------------------------------------------------------- hostile paths
def _special_paths(tmp_path: Path) -> dict[str, Path]:
    fifo = tmp_path / "pipe.nc"
    os.mkfifo(fifo)
    (tmp_path / "real.nc").write_bytes(b"keep")
    link = tmp_path / "link.nc"
    link.symlink_to(tmp_path / "real.nc")
    dangling = tmp_path / "dangling.nc"
    dangling.symlink_to(tmp_path / "nowhere.nc")
    return {"named pipe": fifo, "symbolic link": link, "symbolic link ": dangling}


def _unchanged(tmp_path: Path) -> None:
    assert stat.S_ISFIFO(os.lstat(tmp_path / "pipe.nc").st_mode)
    assert os.path.islink(tmp_path / "link.nc") and os.path.islink(tmp_path / "dangling.nc")
    assert (tmp_path / "real.nc").read_bytes() == b"keep"
    assert not (tmp_path / "nowhere.nc").exists() and _tmp_files(tmp_path) == []


def test_writers_refuse_what_is_not_a_regular_file(tmp_path) -> None:
    for kind, path in _special_paths(tmp_path).items():
        with pytest.raises(FileExistsError, match=f"{path} is a {kind.strip()}"):
            io.check_writable(path)
        with pytest.raises(FileExistsError, match="not a regular file"):
            io.write_dataset(_dataset(), path)
        with pytest.raises(FileExistsError, match="not a regular file"):
            io.write_arrays({"a": np.zeros(2)}, _as(path, ".npz"))
        with pytest.raises(FileExistsError, match="not a regular file"):
            io.write_table([{"a": 1}], _as(path, ".csv"))
    assert stat.S_ISFIFO(os.lstat(tmp_path / "pipe.npz").st_mode)
    assert os.path.islink(tmp_path / "link.csv")
    _unchanged(tmp_path)


def _as(path: Path, suffix: str) -> Path:
    """A special file of the same kind under a name with ``suffix``."""
    target = path.with_suffix(suffix)
    if not os.path.lexists(target):
        if path.is_symlink():
            target.symlink_to(os.readlink(path))
        else:
            os.mkfifo(target)
    return target


def test_dev_null_is_refused_and_stays_a_device(monkeypatch) -> None:
    """Never written: check_writable alone (as root the writers would replace it)."""
    with pytest.raises(FileExistsError, match="/dev/null is a character device"):
        io.check_writable("/dev/null")
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)


@pytest.mark.parametrize("command", ["solve", "sweep", "history"])
def test_cli_refuses_special_outputs(tmp_path, capsys, monkeypatch, command) -> None:
    def must_not_write(*args, **kwargs):
        raise AssertionError("the output was written")

    monkeypatch.setattr(io, "write_dataset", must_not_write)
    argv = {"solve": ["solve", "--geometry", "sphere", "--nu", "0.3", "--stick-ratio", "0.5",
                      "--n", "16"],
            "sweep": ["sweep", "--geometry", "sphere", "--nu", "0.3", "--stick-ratios",
                      "0.5", "--n", "16"],
            "history": ["history", "--geometry", "sphere", "--nu", "0.3", "--friction",
                        "0.2", "--load-path", "0,1", "--steps", "2", "--n", "16"]}[command]
    paths = dict(_special_paths(tmp_path), device=Path("/dev/null"))
    for kind, path in paths.items():
        code = cli.main([*argv, "--output", str(path)])
        out, err = capsys.readouterr()
        assert code == 2, (kind, err)
        assert err.startswith("contactlib: error: --output: ") and err.count("\n") == 1, err
        assert "not a regular file" in err and "Traceback" not in err and out == ""
    _unchanged(tmp_path)
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)


# ----------------------------------------------------------------------------- full disk
def test_full_disk_names_the_file_and_the_cause(tmp_path, monkeypatch) -> None:
    def full(*args, **kwargs):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    path = tmp_path / "out.nc"
    monkeypatch.setattr(xr.Dataset, "to_netcdf", full)
    with pytest.raises(OSError) as err:
        io.write_dataset(_dataset(), path)
    assert str(err.value).startswith(f"cannot write {path}: no space left on device")
    assert err.value.errno == errno.ENOSPC and "\n" not in str(err.value)
    assert os.listdir(tmp_path) == []

    monkeypatch.setattr(np, "savez", full)
    with pytest.raises(OSError, match="no space left on device"):
        io.write_arrays({"a": np.zeros(3)}, tmp_path / "a.npz")
    assert os.listdir(tmp_path) == []


def test_netcdf_hdf_error_on_a_full_disk_says_so(tmp_path, monkeypatch) -> None:
    """netCDF4 reports a full disk as "RuntimeError: NetCDF: HDF error"."""
    def hdf_error(*args, **kwargs):
        raise RuntimeError("NetCDF: HDF error")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", hdf_error)
    path = tmp_path / "out.nc"
    with pytest.raises(RuntimeError, match=f"cannot write {path}: NetCDF: HDF error"):
        io.write_dataset(_dataset(), path)  # space left: the error, now naming the file
    monkeypatch.setattr(io.atomic, "_disk_full", lambda folder: True)
    with pytest.raises(OSError, match=f"cannot write {path}: no space left on device"):
        io.write_dataset(_dataset(), path)
    assert os.listdir(tmp_path) == []


def test_cli_full_disk_is_one_line(tmp_path, capsys, monkeypatch) -> None:
    def full(*args, **kwargs):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(xr.Dataset, "to_netcdf", full)
    out = tmp_path / "o.nc"
    code = cli.main(["solve", "--geometry", "sphere", "--nu", "0.3", "--stick-ratio", "0.5",
                     "--n", "16", "--output", str(out)])
    err = capsys.readouterr().err
    assert code == 1 and err.count("\n") == 1 and "Traceback" not in err
    assert f"cannot write {out}: no space left on device" in err
    assert os.listdir(tmp_path) == []


# ----------------------------------------------------------------------------- stale temporaries
def _dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


def test_stale_temporaries_of_killed_writers_are_removed(tmp_path) -> None:
    path = tmp_path / "out.nc"
    tag = io.atomic._HOST_TAG
    stale = tmp_path / f".out.nc.{tag}-{_dead_pid()}-abcd1234.tmp"
    live = tmp_path / f".out.nc.{tag}-{os.getppid()}-abcd1234.tmp"  # a running process
    other_host = tmp_path / ".out.nc.zzzzzz-1-abcd1234.tmp"  # no hex digest: not ours
    old = tmp_path / ".out.nc.k2j4h5g6.tmp"  # an earlier version's: no owner recorded
    fresh = tmp_path / ".out.nc.a1b2c3d4.tmp"
    other = tmp_path / f".other.nc.{tag}-{_dead_pid()}-abcd1234.tmp"
    for p in (stale, live, other_host, old, fresh, other):
        p.write_bytes(b"partial")
    two_hours_ago = time.time() - 7200
    os.utime(old, (two_hours_ago, two_hours_ago))
    io.write_dataset(_dataset(), path)
    left = sorted(p.name for p in tmp_path.iterdir())
    assert left == sorted(p.name for p in (path, live, other_host, fresh, other)), left
    io.read_dataset(path, require_checksum=True)


# ----------------------------------------------------------------------------- interrupts
@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_signal_during_a_write_leaves_the_old_file_and_no_temporary(tmp_path, sig) -> None:
    """In process: the signal comes inside the write; it is held until the temporary file
    is gone, then handed on (here: a handler that raises)."""
    path = io.write_dataset(_dataset(), tmp_path / "out.nc")
    before = path.read_bytes()
    calls: list[int] = []

    def handler(signum, frame):
        calls.append(signum)
        raise KeyboardInterrupt

    previous = signal.signal(sig, handler)
    real = xr.Dataset.to_netcdf
    finished: list[bool] = []

    def interrupted(self, target, *args, **kwargs):
        real(self, target, *args, **kwargs)
        os.kill(os.getpid(), sig)  # noted, not raised here: the write goes on
        time.sleep(0.05)
        assert calls == []
        real(self, target, *args, **kwargs)
        finished.append(True)

    try:
        with pytest.MonkeyPatch.context() as mp:
            mp.setattr(xr.Dataset, "to_netcdf", interrupted)
            with pytest.raises(KeyboardInterrupt):
                io.write_dataset(io.to_dataset(_solution(0.7)), path)
        assert finished and calls == [sig] and signal.getsignal(sig) is handler
    finally:
        signal.signal(sig, previous)
    assert path.read_bytes() == before and os.listdir(tmp_path) == ["out.nc"]


def test_a_handler_that_returns_lets_the_write_finish(tmp_path) -> None:
    calls: list[int] = []
    previous = signal.signal(signal.SIGINT, lambda signum, frame: calls.append(signum))
    real = np.savez

    def interrupted(fh, **arrays):
        os.kill(os.getpid(), signal.SIGINT)
        real(fh, **arrays)

    try:
        with pytest.MonkeyPatch.context() as mp:
            mp.setattr(np, "savez", interrupted)
            path = io.write_arrays({"a": np.arange(3)}, tmp_path / "a.npz")
    finally:
        signal.signal(signal.SIGINT, previous)
    assert calls == [signal.SIGINT] and os.listdir(tmp_path) == ["a.npz"]
    np.testing.assert_array_equal(io.read_arrays(path)["a"], np.arange(3))


CHILD = textwrap.dedent("""
    import signal
    import sys
    # an interactive process's Ctrl-C, whatever launched the suite: a shell without job
    # control starts background jobs with SIGINT ignored, and the child would inherit that
    signal.signal(signal.SIGINT, signal.default_int_handler)
    import numpy as np
    import xarray as xr
    from contactlib import io

    rng = np.random.default_rng(0)
    ds = xr.Dataset({"noise": (("a", "b"), rng.random((600, 1000)))})  # 4.8 MB, incompressible
    path = sys.argv[1]
    try:
        while True:
            io.write_dataset(ds, path)
    except KeyboardInterrupt:
        sys.exit(130)
""")


def test_signals_from_outside_end_the_process_promptly_and_leave_no_temporary(tmp_path):
    """Ctrl-C hung in netCDF4/HDF5 (2 of 18) and SIGTERM left a temporary file (3 of 3).
    Each child writes a dataset in a loop; the signal comes while a temporary file exists."""
    script = tmp_path / "child.py"
    script.write_text(CHILD)
    rng = random.Random(1)
    for i, sig in enumerate([signal.SIGINT, signal.SIGTERM] * 3):
        folder = tmp_path / f"run{i}"
        folder.mkdir()
        out = folder / "out.nc"
        proc = subprocess.Popen([sys.executable, str(script), str(out)], env=ENV,
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        try:
            deadline = time.monotonic() + 30
            while not _tmp_files(folder) or (i % 2 == 0 and not out.exists()):
                assert proc.poll() is None, proc.communicate()
                assert time.monotonic() < deadline, "the child never wrote"
                time.sleep(0.002)
            time.sleep(rng.uniform(0.0, 0.05))
            proc.send_signal(sig)
            try:
                _, err = proc.communicate(timeout=15)
            except subprocess.TimeoutExpired:
                pytest.fail(f"{sig.name} #{i}: the process did not end (hung)")
        finally:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
        expected = 130 if sig == signal.SIGINT else -signal.SIGTERM
        assert proc.returncode == expected, (sig.name, proc.returncode, err[-500:])
        assert _tmp_files(folder) == [], sig.name
        if out.exists():  # the previous write's file, whole
            assert io.read_dataset(out, require_checksum=True)["noise"].shape == (600, 1000)


# ----------------------------------------------------------------------------- YAML
@pytest.mark.parametrize("text, key, line", [
    ("scenes:\n  a:\n    nu: 0.3\n  b:\n    nu: 0.2\n  a:\n    nu: 0.4\n", "'a'", 6),
    ("scenes:\n  a:\n    nu: 0.3\n    n: 32\n    nu: 0.4\n", "'nu'", 5),
    ("figures:\n  fig2: [a]\nscenes: {}\nfigures:\n  fig3: [a]\n", "'figures'", 4),
    ("scenes:\n  a:\n    layer: {h: 1, h: 2}\n", "'h'", 3),
])
def test_check_yaml_refuses_duplicate_keys(tmp_path, text, key, line) -> None:
    path = tmp_path / "c.yaml"
    path.write_text(text)
    with pytest.raises(ValueError) as err:
        io.check_yaml(path)
    message = str(err.value)
    assert message.startswith(f"{path}, line {line}, column ") and "\n" not in message
    assert f"duplicate key {key} (first at line" in message


def test_check_yaml_keeps_merge_keys_and_distinct_keys(tmp_path) -> None:
    path = tmp_path / "c.yaml"
    path.write_text("base: &b\n  nu: 0.3\n  n: 32\nscene:\n  <<: *b\n  nu: 0.4\n"
                    "other: {1: a, '1': b}\n")
    assert io.check_yaml(path) == {"base": {"nu": 0.3, "n": 32},
                                   "scene": {"nu": 0.4, "n": 32}, "other": {1: "a", "1": "b"}}


def test_check_yaml_on_a_folder_or_device_says_it_in_words(tmp_path) -> None:
    with pytest.raises(ValueError, match=f"^{tmp_path}: is a folder, not a YAML file$"):
        io.check_yaml(tmp_path)
    with pytest.raises(ValueError, match="^/dev/null: is not a regular file$"):
        io.check_yaml("/dev/null")
    (tmp_path / "latin.yaml").write_bytes(b"a: \xe9\n")
    with pytest.raises(ValueError, match="not UTF-8 text"):
        io.check_yaml(tmp_path / "latin.yaml")


def test_check_config_folder_and_duplicates_are_one_line(tmp_path, capsys) -> None:
    code = cli.main(["check-config", str(tmp_path)])
    err = capsys.readouterr().err
    assert code == 2 and err == f"contactlib: error: {tmp_path}: is a folder, not a YAML file\n"
    assert "IsADirectoryError" not in err
    path = tmp_path / "c.yaml"
    path.write_text("scenes:\n  s:\n    geometry: sphere\n    nu: 0.3\n"
                    "    stick_ratios: [0.5]\n  s:\n    geometry: cylinder\n    nu: 0.3\n"
                    "    stick_ratios: [0.5]\n")
    code = cli.main(["check-config", str(path)])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1
    assert f"{path}, line 6, column 3: duplicate key 's' (first at line 2)" in err
