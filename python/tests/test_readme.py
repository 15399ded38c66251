# SPDX-License-Identifier: GPL-3.0-or-later
"""The README's Python example runs as shown (the first ```python block of its
"Python" section), in an empty directory, with only PYTHONPATH set to the package (and
MPLBACKEND=Agg from ctest: no display)."""
import os
import re
import subprocess
import sys

from conftest import SOURCE


def readme_example():
    with open(os.path.join(SOURCE, "README.md")) as f:
        text = f.read()
    section = text[text.index("\n## Python"):]
    m = re.search(r"```python\n(.*?)```", section, re.S)
    assert m, "no ```python block in the README's Python section"
    return m.group(1)


def test_readme_example_runs_as_shown(tmp_path):
    code = readme_example()
    for call in ("lepp.refine(", "lepp.certify(", "lepp.audit(", ".write(", "meshio.read(", ".to_meshio(",
                 "lepp.plot("):
        assert call in code, call
    r = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True,
                       env=dict(os.environ))
    assert r.returncode == 0, r.stdout + r.stderr
    assert "<lepp.Mesh" in r.stdout and "| certificate" in r.stdout
    assert (tmp_path / "square.svg").exists() and (tmp_path / "square.node").exists()
    vtu = (tmp_path / "square.vtu").read_bytes()
    assert vtu.startswith(b"<?xml") and b"UnstructuredGrid" in vtu
    assert (tmp_path / "square.msh").read_bytes().startswith(b"$MeshFormat\n4.1 ")
    assert "min_angle" in r.stdout and "area_quality" in r.stdout  # meshio's summary of the .vtu
    assert (tmp_path / "square.png").read_bytes().startswith(b"\x89PNG")
