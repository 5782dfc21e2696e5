"""Datasets and files: every CF convention and the one atomic write of contactlib.

This is the only part of :mod:`contactlib` that touches the disk, and the
only one that knows the file conventions. It turns the results of the
numerics into CF-annotated :class:`xarray.Dataset` objects (variable names
and scalings of docs/conventions.md) and writes and reads them. One concern
a module; every public name is re-exported here, so ``contactlib.io.X`` and
``from contactlib.io import X`` are the way to use them:

* :mod:`contactlib.io.conventions`: names, units and attributes
  (:func:`cf_attrs`, :func:`version`, :data:`CONVENTIONS`), the workflow's
  provenance (:func:`set_provenance`) and the netCDF encoding;
* :mod:`contactlib.io.datasets`: :func:`to_dataset` for
  :class:`~contactlib.result.Solution` objects (``contactlib solve``/``sweep``),
  :func:`scene_to_dataset` for a workflow scene, :func:`history_to_dataset`
  and :func:`stack_histories` for loading histories
  (:class:`~contactlib.history_api.HistoryResult`), :func:`study_to_dataset`
  and :func:`study_from_dataset` for convergence studies
  (:class:`~contactlib.convergence.Study`), :func:`layer_study_to_dataset`;
* :mod:`contactlib.io.fretting`: :func:`fretting_to_dataset` and
  :func:`fretting_study_to_dataset`;
* :mod:`contactlib.io.physical`: :func:`physical_to_dataset` and
  :func:`physical_fretting_to_dataset` (SI variables beside the dimensionless ones);
* :mod:`contactlib.io.files`: :func:`write_dataset`, :func:`read_dataset`,
  :func:`write_arrays`, :func:`read_arrays`, :func:`write_table`,
  :func:`write_figure`;
* :mod:`contactlib.io.records`: :func:`write_records` and :func:`read_records`
  for the case records (:class:`~contactlib.result.CaseRecord`) the workflow
  passes between its stages (npz);
* :mod:`contactlib.io.checksums`: the content checks and :class:`DamagedFileError`;
* :mod:`contactlib.io.atomic`: the one atomic write and :func:`check_writable`;
* :mod:`contactlib.io.inputs`: :func:`check_yaml` and :func:`read_load_table`.

Every file the workflow passes on carries a content check, the SHA-256 of
its content (npz: an array ``contactlib_sha256``; netCDF: a global attribute
``contactlib_sha256``), written by the writers and verified by the readers:
a truncated, corrupt or changed file is a :class:`DamagedFileError` naming
it, never used, and case records are read strictly (a missing field is an
error, not a default).

Every writer (:func:`write_dataset`, :func:`write_arrays`,
:func:`write_records`, :func:`write_table`, :func:`write_figure`) goes
through one atomic write: a temporary file in the destination folder, then
:func:`os.replace`, with SIGINT and SIGTERM held meanwhile; an existing
destination that is not a regular file (a link, a pipe, a device) is
refused. The numerics never import this package; it imports them
only for their types and constants, and only when a conversion needs them.

Examples
--------
>>> import numpy as np
>>> from contactlib.result import Solution
>>> from contactlib.io import to_dataset
>>> xi = np.linspace(0.0, 1.0, 5)
>>> sol = Solution("sphere", 0.3, "default", 4, 0.0, 0.5, 0.2, xi,
...                np.sqrt(1 - xi**2), 0.1 * xi, 0.5 * xi, 1.0)
>>> ds = to_dataset(sol)
>>> ds["pressure"].dims, float(ds["stick_ratio"])
(('xi',), 0.5)
"""

from __future__ import annotations

from contactlib.io.atomic import check_writable
from contactlib.io.checksums import DamagedFileError
from contactlib.io.conventions import COMPRESSION, CONVENTIONS, cf_attrs, set_provenance, version
from contactlib.io.datasets import (history_to_dataset, layer_study_to_dataset,
                                    scene_to_dataset, stack_histories, study_from_dataset,
                                    study_to_dataset, to_dataset)
from contactlib.io.files import (read_arrays, read_dataset, write_arrays, write_dataset,
                                 write_figure, write_table)
from contactlib.io.fretting import fretting_study_to_dataset, fretting_to_dataset
from contactlib.io.inputs import check_yaml, read_load_table
from contactlib.io.physical import physical_fretting_to_dataset, physical_to_dataset
from contactlib.io.records import read_records, write_records

__all__ = ["to_dataset", "scene_to_dataset", "set_provenance", "history_to_dataset",
           "stack_histories", "study_to_dataset", "study_from_dataset", "layer_study_to_dataset",
           "write_dataset",
           "read_dataset", "write_arrays", "read_arrays", "write_records", "read_records",
           "write_table", "write_figure", "check_writable", "check_yaml", "version",
           "cf_attrs", "DamagedFileError", "CONVENTIONS"]
__all__ += ["physical_to_dataset"]
# public before the split, outside __all__ (kept out of `import *` and the reference page)
_ALSO_PUBLIC = (COMPRESSION, fretting_to_dataset, fretting_study_to_dataset,
                physical_fretting_to_dataset, read_load_table)
