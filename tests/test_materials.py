"""The materials table is package data: it loads from an installed package, not the repository.

``contactlib/data/materials.yaml`` is read with :mod:`importlib.resources`; the
repository's ``config/materials.yaml`` is a link to it. An installed copy of the
package (setuptools' ``build_py`` of this repository, which collects exactly the
files a wheel holds) must find the table away from the repository.
"""

from __future__ import annotations

import subprocess
import sys
from importlib import resources
from pathlib import Path

import yaml

from contactlib.model.materials import MATERIALS_FILE, materials

REPO = Path(__file__).resolve().parents[1]


def test_table_loads_through_importlib_resources():
    text = (resources.files("contactlib") / "data" / "materials.yaml").read_text(encoding="utf-8")
    table = yaml.safe_load(text)["materials"]
    assert table == materials()
    assert {"steel", "aluminium", "pmma", "soda_lime_glass"} <= set(table)
    assert MATERIALS_FILE.name == "materials.yaml"


def test_config_materials_points_to_the_package_data():
    link = REPO / "config" / "materials.yaml"
    assert link.resolve() == (REPO / "contactlib" / "data" / "materials.yaml").resolve()


def test_installed_package_finds_the_table(tmp_path):
    build, egg = tmp_path / "lib", tmp_path / "egg"
    egg.mkdir()
    subprocess.run([sys.executable, "-c",
                    "import sys, setuptools; sys.argv = ['setup.py', '-q', 'egg_info', "
                    f"'--egg-base', {str(egg)!r}, 'build_py', '--build-lib', {str(build)!r}]; "
                    "setuptools.setup()"], cwd=REPO, check=True, capture_output=True)
    assert (build / "contactlib" / "data" / "materials.yaml").is_file()
    code = ("import contactlib.model.materials as m; t = m.materials(); "
            "print(m.pair('steel', 'aluminium')[0], str(m.MATERIALS_FILE))")
    out = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, check=True,
                         capture_output=True, text=True, env={"PYTHONPATH": str(build)})
    ratio, where = out.stdout.split()
    assert float(ratio) == 207.0 / 69.0 and where.startswith(str(build))
