# SPDX-License-Identifier: GPL-3.0-or-later
"""lepp.refine: the same meshes as `lepp refine` on the paper's problems and the corpus,
every option passed through, guard stops as outcomes, the GIL released while it runs."""
import glob
import json
import os
import threading
import time

import numpy as np
import pytest

import lepp
from conftest import corpus, read_triangle_mesh, run_cli

PAPER = sorted(glob.glob(corpus("paper", "*.poly")))
HOSTILE = sorted(glob.glob(corpus("hostile", "*.poly")))


def cli_mesh(path, prefix, *options):
    r = run_cli("refine", path, "-o", prefix, "-q", "--json", *options)
    assert r.returncode in (0, 3), r.stderr
    return read_triangle_mesh(prefix), json.loads(r.stdout)


def assert_same(mesh, cli):
    (v, t, markers), stats = cli
    np.testing.assert_array_equal(mesh.vertices, v)  # exactly: both print and read shortest round-trip doubles
    np.testing.assert_array_equal(mesh.triangles, t)
    np.testing.assert_array_equal(mesh.vertex_markers, markers)
    assert mesh.outcome == stats["outcome"]
    assert mesh.statistics["steiner_points"] == stats["steiner_points"]
    assert mesh.statistics["min_angle"] == stats["min_angle"]


@pytest.mark.parametrize("path", PAPER, ids=os.path.basename)
@pytest.mark.parametrize("theta", [20, 30])
def test_paper_problems_same_mesh_as_cli(path, theta, workdir):
    mesh = lepp.refine(path, min_angle=theta)
    assert mesh.converged and mesh.vertices.dtype == np.float64 and mesh.triangles.dtype == np.int32
    assert mesh.vertices.shape[1] == 2 and mesh.triangles.shape[1] == 3
    assert_same(mesh, cli_mesh(path, str(workdir / "m"), "--min-angle", str(theta)))


@pytest.mark.parametrize("path", HOSTILE, ids=os.path.basename)
def test_corpus_same_mesh_as_cli(path, workdir):
    r = run_cli("refine", path, "-o", str(workdir / "m"), "-q", "--json", "--min-angle", "25")
    if r.returncode == 2:  # not a PSLG: lepp.refine says the same
        with pytest.raises(lepp.InputError) as e:
            lepp.refine(path, min_angle=25)
        assert "lepp refine: " + str(e.value) in r.stderr
        return
    mesh = lepp.refine(path, min_angle=25)
    assert_same(mesh, (read_triangle_mesh(str(workdir / "m")), json.loads(r.stdout)))
    assert mesh.warnings == json.loads(r.stdout)["warnings"]


def test_arrays_give_the_file_mesh():
    """The PSLG as arrays (what read_poly returns) refines to the mesh of the file."""
    path = corpus("paper", "A.poly")
    pslg = lepp.read_poly(path)
    assert pslg["vertices"].dtype == np.float64 and pslg["segments"].min() == 0  # 0-based
    a = lepp.refine(pslg["vertices"], pslg["segments"], pslg["holes"], min_angle=28)
    b = lepp.refine(path, min_angle=28)
    np.testing.assert_array_equal(a.vertices, b.vertices)
    np.testing.assert_array_equal(a.triangles, b.triangles)
    c = lepp.refine(pslg, min_angle=28)  # the dict itself
    np.testing.assert_array_equal(c.triangles, b.triangles)


@pytest.mark.parametrize("options,cli", [
    (dict(method="midpoint"), ["--method", "midpoint"]),
    (dict(order="lifo"), ["--order", "lifo"]),
    (dict(engine="reference"), ["--engine", "reference"]),
    (dict(max_area=20.0), ["--max-area", "20"]),
    (dict(convex_hull=True), ["--convex-hull"]),
    (dict(order="random", order_seed=7), ["--order", "random", "--order-seed", "7"]),
    (dict(order="batch"), ["--order", "batch"]),
    (dict(order="batch", engine="reference"), ["--order", "batch"]),
])
def test_options_as_the_cli(options, cli, workdir):
    path = corpus("paper", "A.poly")
    mesh = lepp.refine(path, min_angle=25, **options)
    assert_same(mesh, cli_mesh(path, str(workdir / "m"), "--min-angle", "25", *cli))


def test_batch_threads_give_the_cli_mesh_of_one_thread(workdir):
    # Large enough that the rounds' windows run on two threads (about 5e4 triangles).
    path = corpus("paper", "square400.poly")
    mesh = lepp.refine(path, min_angle=30, max_area=0.15, order="batch", threads=2)
    assert_same(mesh, cli_mesh(path, str(workdir / "m"), "--min-angle", "30", "--max-area", "0.15", "--order", "batch",
                               "--threads", "1"))
    with pytest.raises(ValueError, match="threads"):
        lepp.refine(path, order="batch", threads=-1)


def test_batch_statistics_as_the_cli_json(workdir):
    # rounds and looks, as `lepp refine --json` prints them; None for the other orders.
    path = corpus("paper", "square400.poly")
    mesh = lepp.refine(path, min_angle=30, order="batch", threads=1)
    _, cli = cli_mesh(path, str(workdir / "m"), "--min-angle", "30", "--order", "batch", "--threads", "1")
    assert (mesh.statistics["rounds"], mesh.statistics["looks"]) == (cli["rounds"], cli["looks"])
    assert 0 < mesh.statistics["rounds"] <= mesh.statistics["looks"]
    fifo = lepp.refine(path, min_angle=30)
    assert fifo.statistics["rounds"] is None and fifo.statistics["looks"] is None


def test_statistics_are_the_cli_json_less_its_files(workdir):
    # The same keys and values as `lepp refine --json`, less the file names and the
    # phases that read and write files; only the timings differ.
    path = corpus("hostile", "duplicate-vertices.poly")
    mesh = lepp.refine(path, min_angle=25)
    _, cli = cli_mesh(path, str(workdir / "m"), "--min-angle", "25")
    assert cli["warnings"] and mesh.warnings == cli["warnings"]
    timings = ("seconds", "seconds_by_phase")
    ours = {k: v for k, v in mesh.statistics.items() if k not in timings}
    theirs = {k: v for k, v in cli.items() if k not in timings + ("input", "output")}
    assert ours == theirs
    assert set(mesh.statistics["seconds_by_phase"]) == {"cdt", "refine", "statistics"}


def test_random_order_seed_changes_the_mesh():
    # The seed is passed through: two seeds give two meshes (A at 25 degrees), one seed gives one.
    path = corpus("paper", "A.poly")
    a, b = (lepp.refine(path, min_angle=25, order="random", order_seed=s) for s in (1, 2))
    assert len(a.vertices) != len(b.vertices) or not np.array_equal(a.triangles, b.triangles)
    np.testing.assert_array_equal(lepp.refine(path, min_angle=25, order="random", order_seed=1).triangles, a.triangles)


def test_region_areas_as_the_cli(workdir):
    path = corpus("triangle-formats", "region-areas.poly")
    mesh = lepp.refine(path, min_angle=20, region_areas=True)
    assert_same(mesh, cli_mesh(path, str(workdir / "m"), "--min-angle", "20", "--region-areas"))
    assert mesh.statistics["area_refined"] > 0


def test_trace_is_the_cli_trace(workdir):
    path = corpus("paper", "A.poly")
    mesh = lepp.refine(path, min_angle=30, trace=True)
    run_cli("refine", path, "-o", str(workdir / "m"), "-q", "--trace")
    with open(str(workdir / "m") + ".trace") as f:
        points = np.array([[float(x) for x in l.split()[:2]] for l in f if l.strip() and not l.startswith("#")])
    np.testing.assert_array_equal(mesh.trace, points)
    assert len(mesh.trace_rules) == len(points) == mesh.statistics["steiner_points"]
    # Every Steiner point is a mesh vertex after the input's, in insertion order.
    np.testing.assert_array_equal(mesh.vertices[mesh.input_vertices:], mesh.trace)
    assert lepp.refine(path).trace is None


def test_guard_stop_is_an_outcome_not_an_exception():
    mesh = lepp.refine(corpus("paper", "A.poly"), min_angle=30, max_steiner=5)
    assert mesh.outcome == "steiner-budget" and not mesh.converged
    assert mesh.statistics["steiner_points"] == 5
    assert mesh.triangles.shape[0] > 0  # the mesh so far, a valid CDT
    assert lepp.certify(corpus("paper", "A.poly"), mesh).ok


def test_write_triangle_is_the_cli_output(workdir):
    path = corpus("paper", "circles240.poly")
    lepp.refine(path, min_angle=25).write(workdir / "py")
    run_cli("refine", path, "-o", str(workdir / "cli"), "-q", "--min-angle", "25")
    for ext in (".node", ".ele", ".poly"):
        with open(str(workdir / "py") + ext) as a, open(str(workdir / "cli") + ext) as b:
            assert a.read() == b.read(), ext


def test_bad_options_raise_value_error():
    path = corpus("paper", "A.poly")
    for kwargs in (dict(min_angle=61), dict(method="bisect"), dict(order="depth-first"), dict(engine="triangle"),
                   dict(max_area=-1), dict(max_steiner=-5), dict(time_limit=-1)):
        with pytest.raises(ValueError):
            lepp.refine(path, **kwargs)


def test_the_gil_is_released_while_the_engine_runs():
    """Python code runs in another thread while refine is inside the engine (with the GIL held
    throughout, no tick could fall between the two instants the refining thread records)."""
    pslg = lepp.read_poly(corpus("paper", "square400.poly"))
    span, ticks, done = {}, [], threading.Event()

    def work():
        span["start"] = time.perf_counter()
        lepp.refine(pslg, min_angle=36, max_steiner=150000)  # a few tenths of a second in the engine
        span["end"] = time.perf_counter()
        done.set()

    t = threading.Thread(target=work)
    t.start()
    while not done.is_set():
        ticks.append(time.perf_counter())
    t.join()
    inside = [x for x in ticks if span["start"] < x < span["end"]]
    assert len(inside) > 0


def test_mesh_arrays_are_not_copies():
    """The arrays own the engine's vectors (a capsule as base), and can be kept after the Mesh."""
    mesh = lepp.refine(corpus("paper", "A.poly"))
    assert mesh.vertices.base is not None and not mesh.vertices.flags.owndata
    v = mesh.vertices
    del mesh
    assert np.isfinite(v).all()


def test_ctrl_c_stops_a_long_run():
    """SIGINT during a run of more than 65536 Steiner points raises KeyboardInterrupt (the
    engine checks at its progress calls); the interpreter goes on."""
    import signal

    pslg = lepp.read_poly(corpus("paper", "square400.poly"))
    timer = threading.Timer(0.05, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        lepp.refine(pslg, min_angle=36)  # 267 thousand points when left to finish
    timer.join()
    assert lepp.refine(corpus("paper", "A.poly")).converged


@pytest.mark.parametrize("format,files", [("vtu", [".vtu"]), ("msh2", [".msh"]), ("msh4", [".msh"]),
                                          ("triangle,vtu", [".node", ".ele", ".poly", ".vtu"])])
@pytest.mark.parametrize("binary", [False, True])
def test_write_formats_are_the_cli_output(format, files, binary, workdir):
    """Mesh.write(format=...) writes the bytes of lepp refine --format (labels from the input:
    boundary markers and regions)."""
    path = corpus("triangle-formats", "region-areas.poly")
    mesh = lepp.refine(path, min_angle=20, region_areas=True)
    mesh.write(workdir / "py", format=format, binary=binary)
    args = ["refine", path, "-o", str(workdir / "cli"), "-q", "--min-angle", "20", "--region-areas", "--format", format]
    assert run_cli(*args, *(["--binary"] if binary else [])).returncode == 0
    for ext in files:
        assert (workdir / ("py" + ext)).read_bytes() == (workdir / ("cli" + ext)).read_bytes(), ext
    assert (mesh.triangle_regions > 0).any() and mesh.triangle_regions.shape == (mesh.triangles.shape[0],)


def test_vtu_read_back_by_meshio(workdir):
    meshio = pytest.importorskip("meshio")
    mesh = lepp.refine(corpus("paper", "A.poly"), min_angle=30)
    mesh.write(workdir / "a", format="vtu")
    back = meshio.read(str(workdir / "a.vtu"))
    np.testing.assert_array_equal(back.points[:, :2], mesh.vertices)
    np.testing.assert_array_equal(back.cells_dict["triangle"], mesh.triangles)
    assert back.cell_data  # the per-triangle quality arrays
    with pytest.raises(ValueError, match="none of"):
        mesh.write(workdir / "a", format="stl")
    with pytest.raises(ValueError, match="msh2 and msh4"):
        mesh.write(workdir / "a", format=["msh2", "msh4"])
