"""Every marker type shows in a real headless Chromium render of a snapshot."""

from __future__ import annotations

import numpy as np
import pytest
from rviz_helpers import marker

from workbench.msgs.visualization_msgs import Marker
from workbench.rviz.marker_draw import draw_marker
from workbench.rviz.rviz import resolve_mesh

_KEPT: list = []


def _meshcat(meshcat_class, params_class):
    """A Meshcat kept for the process's life (one must be destroyed on its own thread)."""
    if not _KEPT:
        _KEPT.append(meshcat_class(params_class(host="127.0.0.1")))
    _KEPT[0].Delete()
    return _KEPT[0]


@pytest.mark.browser
def test_each_marker_type_changes_the_render(require_program, tmp_path):
    from PIL import Image, ImageChops
    from pydrake.geometry import Meshcat, MeshcatParams

    from workbench.spatial import rigid_transform
    from workbench.viz.render import render_png

    require_program("chromium")
    meshcat = _meshcat(Meshcat, MeshcatParams)
    meshcat.SetCameraPose([2.0, 2.0, 2.0], [0.0, 0.0, 0.0])
    meshcat.SetProperty("/Grid", "visible", False)
    meshcat.SetProperty("/Axes", "visible", False)
    (tmp_path / "empty.html").write_text(meshcat.StaticHtml())
    empty = Image.open(
        render_png(tmp_path / "empty.html", tmp_path / "empty.png", width=240, height=180)
    )
    empty = empty.convert("RGB")
    changed = {}
    for kind in range(12):
        if kind == Marker.MESH_RESOURCE:
            m = marker(kind, kind, mesh_resource="package://workbench_urdf/meshes/l_finger.obj")
            m.scale.x = m.scale.y = m.scale.z = 10.0
        else:
            m = marker(kind, kind)
        m.scale.x = m.scale.y = m.scale.z = max(m.scale.x, 0.5)
        m.color.g = 0.8
        path = f"/rviz/Marker/test/{kind}"
        draw_marker(meshcat, path, m, resolve_mesh)
        meshcat.SetTransform(path, rigid_transform([0.0, 0.0, 0.0]))
        html = tmp_path / f"{kind}.html"
        html.write_text(meshcat.StaticHtml())
        png = Image.open(render_png(html, tmp_path / f"{kind}.png", width=240, height=180)).convert(
            "RGB"
        )
        difference = np.asarray(ImageChops.difference(empty, png)).max(axis=2)
        changed[kind] = float((difference > 40).mean())
        meshcat.Delete(path)
    # more than ~20 of the 43,200 pixels: a one-pixel line 1 m long passes, nothing fails
    assert all(value > 0.0005 for value in changed.values()), changed
