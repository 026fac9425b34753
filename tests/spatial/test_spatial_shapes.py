"""The shape vocabulary and its Drake conversion."""

from __future__ import annotations

import numpy as np
import pytest
from pydrake.geometry import Box, Convex, Cylinder, Mesh, Sphere

from workbench import spatial


def test_make_shape_and_extents() -> None:
    box = spatial.make_shape("box", size=[0.2, 0.4, 0.6])
    np.testing.assert_allclose(box.half_extents(), [0.1, 0.2, 0.3])
    cylinder = spatial.make_shape("cylinder", radius=0.1, length=0.5)
    np.testing.assert_allclose(cylinder.half_extents(), [0.1, 0.1, 0.25])
    np.testing.assert_allclose(spatial.make_shape("sphere", radius=0.3).half_extents(), [0.3] * 3)
    mesh = spatial.make_shape("mesh", filename="a.obj", scale=[1, 2, 3])
    np.testing.assert_allclose(mesh.scale3(), [1, 2, 3])


@pytest.mark.parametrize(
    ("kind", "fields"),
    [
        ("cone", {"radius": 1}),
        ("box", {"size": [1, 2]}),
        ("box", {}),
        ("sphere", {"radius": -1}),
        ("cylinder", {"radius": 1, "length": 0}),
        ("mesh", {"filename": ""}),
        ("mesh", {"filename": "a.obj", "scale": [1, 2]}),
    ],
)
def test_bad_shapes(kind: str, fields: dict) -> None:
    with pytest.raises(spatial.SpatialError):
        spatial.make_shape(kind, **fields)


def test_drake_round_trip(tmp_path) -> None:
    shapes = [
        spatial.make_shape("box", size=[0.2, 0.4, 0.6]),
        spatial.make_shape("cylinder", radius=0.1, length=0.5),
        spatial.make_shape("sphere", radius=0.3),
        spatial.make_shape("mesh", filename=str(tmp_path / "m.obj"), scale=2.0),
    ]
    drake = [spatial.drake_shape(shape) for shape in shapes]
    assert [type(d) for d in drake] == [Box, Cylinder, Sphere, Mesh]
    assert drake[0].depth() == pytest.approx(0.4) and drake[1].length() == pytest.approx(0.5)
    assert [spatial.shape_from_drake(d) for d in drake] == shapes
    convex = spatial.drake_shape(shapes[3], convex_mesh=True)
    assert isinstance(convex, Convex)
    assert spatial.shape_from_drake(convex) == shapes[3]
