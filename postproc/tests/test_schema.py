"""The readers driven by the one description of the output:
rodyn_post.schema is generated from rodyn's own table (src/io/rodyn_output_schema.txt)
and up to date; the readers take the columns of every table from it, and check the
`units` attribute each HDF5 dataset carries against it instead of assuming them."""
import shutil
import subprocess
import sys

import h5py
import pytest

from designed import REPO
from rodyn_post import RodynResultsError, load_dynamic, load_static, schema
from rodyn_post import dynamic, environment, results


def test_schema_module_up_to_date():
    run = subprocess.run([sys.executable, str(REPO / "tools" / "gen_output_schema.py"),
                          "--check"], capture_output=True, text=True)
    assert run.returncode == 0, run.stdout + run.stderr


def test_readers_take_their_columns_from_the_schema():
    for module, names in ((results, ("NODES", "ELEMENTS", "LINES", "REACTIONS")),
                          (dynamic, ("NODES", "ELEMENTS", "LINES", "ENDS", "ENDS_STEP",
                                     "LOG"))):
        for name in names:
            file = getattr(module, f"{name}_CSV")
            assert getattr(module, f"{name}_HEADER") == schema.header(file)
    assert environment.ENVIRONMENT_HEADER == schema.header(environment.ENVIRONMENT_CSV)
    assert schema.unit("dynamic_log.csv", "px") == "kg m/s"
    assert schema.DATASETS["dynamic.h5"]["/dynamic/LINE/moment_1"][0] == "N m"
    with pytest.raises(KeyError):
        schema.unit("dynamic_log.csv", "no_such_column")


@pytest.mark.parametrize("file, dataset", [("dynamic.h5", "z"), ("dynamic.h5", "log/total"),
                                           ("results.h5", "node_xyz")])
def test_units_read_from_the_file(short_run, tmp_path, file, dataset):
    folder = tmp_path / "run"
    shutil.copytree(short_run, folder)
    load = load_dynamic if file == "dynamic.h5" else load_static
    load(folder / file)                                   # reads as written
    with h5py.File(folder / file, "r+") as f:
        group = f["dynamic" if file == "dynamic.h5" else "static"]
        line = next(k for k, v in group.items() if isinstance(v, h5py.Group) and k != "log")
        name = dataset if dataset.startswith("log/") else f"{line}/{dataset}"
        f[f"{group.name}/{name}"].attrs["units"] = "furlong"
    with pytest.raises(RodynResultsError, match="'furlong'"):
        load(folder / file)


def test_readers_read_only_what_the_schema_describes():
    """Every dataset, attribute and status.txt key the readers ask a file for is in the
    one description of the output (rodyn_post.schema): the HDF5 datasets of a line group
    and of the step log, the root and group attributes, the status keys."""
    static = schema.DATASETS["results.h5"]
    for name in {**results.H5_LINE_DATASETS, **results.H5_WATER_DATASETS}:
        assert f"/static/LINE/{name}" in static, name
    dyn = schema.DATASETS["dynamic.h5"]
    for name in {**dynamic.H5_LINE_DATASETS, **dynamic.H5_WATER_DATASETS}:
        assert f"/dynamic/LINE/{name}" in dyn, name
    for name in dynamic.H5_LOG_DATASETS:
        assert f"/dynamic/log/{name}" in dyn, name
    for file, objects in (("results.h5", {"/": results.H5_ROOT_ATTRIBUTES,
                                           "/static": results.H5_STATIC_ATTRIBUTES,
                                           "/static/LINE": ("name", "touchdown_s"),
                                           "/static/LINE/reactions": ("end_held",)}),
                          ("dynamic.h5", {"/": dynamic.H5_ROOT_ATTRIBUTES,
                                          "/dynamic": dynamic.H5_DYNAMIC_ATTRIBUTES,
                                          "/dynamic/LINE": ("name",),
                                          "/dynamic/LINE/reactions": ("end_held",),
                                          "/dynamic/sea": ("probes", "vessels",
                                                           "connections")})):
        for obj, names in objects.items():
            for name in names:
                assert f"{obj}:{name}" in schema.ATTRIBUTES[file], (file, obj, name)
    keys = {key for key, _, _ in schema.STATUS}
    for module in (results, dynamic):
        assert set(module.STATUS_KEYS) <= keys, set(module.STATUS_KEYS) - keys
