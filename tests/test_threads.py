"""BLAS thread pools: results do not depend on the thread count.

The truth here is the bytes: the same command run with one and with two
OpenBLAS threads must write identical files (CLI sweep, CLI history, a
workflow dataset), and a dense LU at those sizes must really differ between
one and two threads (else the file comparisons would prove nothing).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml
from scipy import linalg
from threadpoolctl import threadpool_info, threadpool_limits

import contactlib
from contactlib import threads
from contactlib.io import read_dataset

REPO = Path(__file__).resolve().parents[1]
BLAS_VARS = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def env_with_threads(count: int) -> dict[str, str]:
    env = dict(os.environ, PYTHONPATH=str(REPO), PYTHONHASHSEED="0")
    for var in BLAS_VARS:
        env[var] = str(count)
    return env


def cli(tmp: Path, count: int, *args: str) -> bytes:
    out = tmp / f"out-{count}.nc"
    proc = subprocess.run([sys.executable, "-m", "contactlib", *args, "--output", str(out)],
                          env=env_with_threads(count), capture_output=True, text=True,
                          timeout=600)
    assert proc.returncode == 0, proc.stderr
    return out.read_bytes()


def two_threads_possible() -> bool:
    with threadpool_limits(limits=2, user_api="blas"):
        return any(p["num_threads"] >= 2 for p in threadpool_info() if p["user_api"] == "blas")


# ----------------------------------------------------------------------------- premise
def test_lu_bits_depend_on_the_thread_count_without_the_policy():
    """The premise of the policy: getrf at 1 and 2 threads differ in the last bits."""
    if not two_threads_possible():
        pytest.skip("this BLAS cannot run two threads here")
    a = np.random.default_rng(0).standard_normal((512, 512)) + 512 * np.eye(512)
    factors = {}
    for count in (1, 2):
        with threadpool_limits(limits=count, user_api="blas"):
            factors[count] = linalg.lu_factor(a, check_finite=False)[0]
    if np.array_equal(factors[1], factors[2]):
        pytest.skip("this BLAS gives identical LU bits at 1 and 2 threads")
    np.testing.assert_allclose(factors[1], factors[2], rtol=0, atol=1e-9)


def test_entry_points_run_on_one_blas_thread_and_restore_the_caller_limits():
    seen = []

    @threads.blas_single_threaded
    def probe():
        seen.extend(p["num_threads"] for p in threadpool_info())
        with threads.single_blas_thread():  # nested: still one
            seen.extend(p["num_threads"] for p in threadpool_info())

    with threadpool_limits(limits=2):
        before = [p["num_threads"] for p in threadpool_info()]
        probe()
        after = [p["num_threads"] for p in threadpool_info()]
    assert seen and set(seen) == {1}
    assert before == after


def test_a_blas_loaded_inside_the_block_is_limited_too():
    """threadpoolctl limits the pools loaded when it is called: scipy's own OpenBLAS,
    first imported inside the block, must run on one thread as well."""
    code = ("import sys\n"
            "from contactlib import threads\n"
            "assert 'scipy' not in sys.modules\n"
            "with threads.single_blas_thread():\n"
            "    from scipy import linalg\n"
            "    from threadpoolctl import threadpool_info\n"
            "    info = threadpool_info()\n"
            "assert len(info) >= 1 and {p['num_threads'] for p in info} == {1}, info\n")
    env = env_with_threads(2)
    proc = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 0, proc.stderr


# ----------------------------------------------------------------------------- bytes
def test_cli_sweep_bytes_do_not_depend_on_blas_threads(tmp_path):
    # n = 256 (the default): systems of ~400 unknowns, where LU bits differ
    args = ("sweep", "--geometry", "sphere", "--nu", "0.3", "--stick-ratios", "0.3,0.7")
    one, two = cli(tmp_path, 1, *args), cli(tmp_path, 2, *args)
    assert one == two


@pytest.mark.slow  # (fast tier: test_cli_sweep_bytes_do_not_depend_on_blas_threads)
def test_cli_history_bytes_do_not_depend_on_blas_threads(tmp_path):
    args = ("history", "--geometry", "sphere", "--nu", "0.3", "--friction", "0.2",
            "--load-path", "0,1,0", "--steps", "20")
    one, two = cli(tmp_path, 1, *args), cli(tmp_path, 2, *args)
    assert one == two


@pytest.mark.slow  # a workflow run; the CLI byte checks above stay in the fast tier
@pytest.mark.workflow
@pytest.mark.skipif(shutil.which("snakemake") is None, reason="snakemake is not installed")
def test_workflow_dataset_bytes_do_not_depend_on_threads(tmp_path):
    """Snakemake sets the BLAS variables to a job's threads: run with 1 and with 2."""
    cfg = {"scenes": {"s": {"geometry": "sphere", "nu": 0.3, "method": "default", "n": 256,
                            "stick_ratios": [0.3, 0.7], "outputs": ["k_curve"]}},
           "figures": {}}
    files = {}
    for count in (1, 2):
        wd = tmp_path / f"t{count}"
        wd.mkdir()
        shutil.copy(REPO / "Snakefile", wd / "Snakefile")
        shutil.copytree(REPO / "workflow", wd / "workflow",
                        ignore=shutil.ignore_patterns("__pycache__"))
        shutil.copytree(REPO / "config", wd / "config")
        (wd / "config" / "config.yaml").write_text(yaml.safe_dump(cfg))
        set_threads = [f"{rule}={count}" for rule in ("influence", "solve", "check", "assemble")]
        proc = subprocess.run([sys.executable, "-m", "snakemake", "--cores", "2",
                               "--set-threads", *set_threads],
                              cwd=wd, env=env_with_threads(count), capture_output=True,
                              text=True, timeout=900)
        assert proc.returncode == 0, proc.stdout + proc.stderr
        files[count] = wd / "results" / "datasets" / "s.nc"
    assert files[1].read_bytes() == files[2].read_bytes()
    # and the numbers are the library's, called here on two threads (each call owns its
    # store of stick blocks, so the bits do not depend on earlier calls)
    with threadpool_limits(limits=2):
        ref = contactlib.sweep("sphere", 0.3, [0.3, 0.7], n=256)
    np.testing.assert_array_equal(read_dataset(files[2])["friction_coefficient"].values,
                                  [s.friction_coefficient for s in ref])


# ----------------------------------------------------------------------------- requested
def test_requested_counts(monkeypatch):
    monkeypatch.delenv(threads.ENV, raising=False)
    assert threads.requested() == 1
    assert threads.requested(3) == 3
    monkeypatch.setenv(threads.ENV, "2")
    assert threads.requested() == 2
    assert threads.requested(1) == 1


@pytest.mark.parametrize("value", [0, -1, 1.5, True, "two", "2.0"])
def test_requested_refuses_a_bad_count_naming_it(value):
    with pytest.raises(ValueError, match=r"threads must be a positive integer, got " +
                       repr(value).replace("(", r"\(").replace(".", r"\.")):
        threads.requested(value)


def test_requested_refuses_a_bad_environment_value(monkeypatch):
    monkeypatch.setenv(threads.ENV, "many")
    with pytest.raises(ValueError, match="CONTACTLIB_THREADS must be a positive integer, "
                                         "got 'many'"):
        threads.requested()


# ----------------------------------------------------------------------------- map_cases
def _square_after_lu(x: int) -> tuple[int, bytes, int]:
    """A case with an LU in it: its bits, and the process that ran it."""
    a = np.random.default_rng(x).standard_normal((300, 300)) + 300 * np.eye(300)
    with threads.single_blas_thread():
        lu = linalg.lu_factor(a, check_finite=False)[0]
    return x * x, lu.tobytes(), os.getpid()


def _fail_on_two(x: int) -> int:
    if x == 2:
        raise ValueError("case 2 failed")
    return x


def test_map_cases_gives_the_serial_results_in_order_from_other_processes():
    items = [3, 1, 2, 5]
    serial = threads.map_cases(_square_after_lu, items, 1)
    parallel = threads.map_cases(_square_after_lu, items, 2)
    assert [r[0] for r in parallel] == [9, 1, 4, 25]
    assert [r[:2] for r in parallel] == [r[:2] for r in serial]
    assert {r[2] for r in serial} == {os.getpid()}
    assert os.getpid() not in {r[2] for r in parallel}


def test_map_cases_raises_a_case_error_and_refuses_a_bad_count():
    for workers in (1, 2):
        with pytest.raises(ValueError, match="case 2 failed"):
            threads.map_cases(_fail_on_two, [1, 2, 3], workers)
    with pytest.raises(ValueError, match="threads must be a positive integer, got 0"):
        threads.map_cases(_fail_on_two, [1], 0)
    assert threads.map_cases(_fail_on_two, [], 2) == []


# ----------------------------------------------------------------------------- lazy package
def _run_python(code: str) -> None:
    """Run ``code`` in a fresh interpreter (one BLAS thread); its assertions must hold."""
    proc = subprocess.run([sys.executable, "-c", code], env=env_with_threads(1),
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr


def test_package_imports_no_solver_and_history_stays_the_function():
    code = ("import sys, contactlib\n"
            "assert 'contactlib.api' not in sys.modules and 'scipy.linalg' not in sys.modules\n"
            "from contactlib import history\n"
            "import contactlib.history_api as h\n"
            "assert callable(contactlib.history) and h.history is contactlib.history\n"
            "assert contactlib.history.__module__ == 'contactlib.history_api'\n"
            "assert contactlib.solve.__module__ == 'contactlib.api'\n"
            "assert contactlib.Solution.__name__ == 'Solution'\n")
    _run_python(code)


def test_workflow_check_and_energy_stages_need_no_solver_imports():
    """The check and energy jobs are elementwise work on stored samples: their
    process imports neither scipy nor the solvers (most of a job's time), and
    the work equals stages.work_case, the library's own per-case work."""
    code = ("import sys\n"
            "import numpy as np\n"
            "from contactlib.scene import parse_scene\n"
            "scene = parse_scene('s', {'geometry': 'sphere', 'nu': 0.3, 'n': 32,\n"
            "                          'stick_ratios': [0.3, 0.7],\n"
            "                          'outputs': ['k_curve', 'energy']})\n"
            "import contactlib.stages as stages\n"
            "records = stages.solve_cases(scene.geometry_object, 'default', 32, [0.3, 0.7])\n"
            "want = [stages.work_case(scene.geometry_object, r) for r in records]\n"
            "for name in [m for m in sys.modules if m.startswith(('scipy', 'contactlib.'))]:\n"
            "    del sys.modules[name]\n"
            "from contactlib import pipeline\n"
            "work = pipeline.energy(scene, records)['frictional_work']\n"
            "pipeline.check(records)\n"
            "assert np.array_equal(work, want) and min(want) > 0, (work, want)\n"
            "loaded = sorted(m for m in sys.modules if m.startswith('scipy')\n"
            "                or m in ('contactlib.stages', 'contactlib.solvers.default_method'))\n"
            "assert not loaded, loaded\n")
    _run_python(code)
