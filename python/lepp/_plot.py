# SPDX-License-Identifier: GPL-3.0-or-later
"""lepp.plot: a mesh drawn with matplotlib, as `lepp render` draws it (triangles coloured
by quality or smallest angle, constrained edges bold, bad triangles outlined), with a
colour bar. The values are the .vtu's measures, computed by the same C++ functions."""
import numpy as np

from . import _lepp
from ._convert import mesh_dict

# color= names: (the measure, the colour bar's label, its range).
_COLORS = {
    "quality": ("area_quality", "area quality q = (4/\u221a3)\u00b7area/longest\u00b2", (0.0, 1.0)),
    "angle": ("min_angle", "smallest angle (degrees)", (0.0, 60.0)),
}


def plot(mesh, ax=None, color="quality", *, min_angle=None, cmap="viridis", colorbar=True, linewidth=0.2):
    """Draws a mesh (a lepp.Mesh or a mesh dict) on the matplotlib Axes ax (a new figure's
    when None) and returns the Axes. color: 'quality' (area quality, 0 to 1, as `lepp render`),
    'angle' (smallest angle, 0 to 60 degrees), another of the .vtu's measures ('max_angle',
    'radius_ratio', 'edge_ratio', 'area_quality', 'min_angle') or an array of one value per
    triangle. Triangles with a smallest angle below min_angle (the mesh's target angle when
    it has one, else 30) are outlined in red; constrained edges are drawn bold."""
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection, PolyCollection

    arrays = mesh_dict(mesh)
    v, t = arrays["vertices"], arrays["triangles"]
    if t.shape[0] == 0:
        raise ValueError("plot: the mesh has no triangles")
    measures = _lepp.triangle_measures(arrays)
    if isinstance(color, str):
        name, label, limits = _COLORS.get(color, (color, color.replace("_", " "), (None, None)))
        if name not in measures:
            raise ValueError(f"plot: color {color!r} is none of {', '.join([*_COLORS, *measures])} "
                             "(or an array, one value per triangle)")
        values = measures[name]
    else:
        values = np.asarray(color, dtype=float).reshape(-1)
        if values.size != t.shape[0]:
            raise ValueError(f"plot: color has {values.size} values for {t.shape[0]} triangles")
        label, limits = None, (None, None)
    if min_angle is None:
        min_angle = mesh._target_angle() if hasattr(mesh, "_target_angle") else 30.0

    if ax is None:
        _, ax = plt.subplots()
    corners = v[t]
    faces = PolyCollection(corners, cmap=cmap, edgecolors="black", linewidths=linewidth)
    faces.set_array(values)
    faces.set_clim(*limits)
    ax.add_collection(faces)
    edges = arrays.get("edges")
    if edges is not None and len(edges):
        ax.add_collection(LineCollection(v[edges], colors="black", linewidths=1.5))
    bad = measures["min_angle"] < float(min_angle)
    if bad.any():
        ax.add_collection(PolyCollection(corners[bad], facecolors="none", edgecolors="red", linewidths=1.5,
                                         label=f"{int(bad.sum())} below {float(min_angle):g}\u00b0"))
    if colorbar:
        ax.figure.colorbar(faces, ax=ax, label=label)
    ax.autoscale_view()
    ax.set_aspect("equal")
    return ax
