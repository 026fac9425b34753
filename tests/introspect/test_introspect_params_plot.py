"""rosparam's list/get/set/delete/dump/load, and rqt_plot's series to a PNG."""

from __future__ import annotations

import pytest

from workbench.bus.params import ParameterServer
from workbench.errors import BusError
from workbench.introspect import params
from workbench.introspect.plot import FieldSeries, plot_series
from workbench.msgs.turtlesim import Pose


@pytest.fixture
def server():
    s = ParameterServer()
    for channel, value in zip("rgb", (69, 86, 255), strict=True):
        s.set(f"/turtlesim/background_{channel}", value)
    s.set("/rosdistro", "noetic")
    return s


def test_list_get_set_delete(server):
    assert params.list_names(server) == [
        "/rosdistro", "/turtlesim/background_b", "/turtlesim/background_g", "/turtlesim/background_r",
    ]  # fmt: skip
    assert params.list_names(server, "/turtlesim")[0] == "/turtlesim/background_b"
    params.set_text(server, "/turtlesim/background_r", "150")
    assert params.get_text(server, "/turtlesim/background_r") == "150"
    assert params.get_text(server, "/").splitlines() == [
        "rosdistro: noetic", "turtlesim:", "  background_b: 255", "  background_g: 86",
        "  background_r: 150",
    ]  # fmt: skip
    params.delete(server, "/rosdistro")
    with pytest.raises(BusError, match=r"parameter \[/rosdistro\] is not set"):
        params.get_text(server, "/rosdistro")
    with pytest.raises(BusError, match="not valid YAML"):
        params.set_text(server, "/x", "[1, 2")


def test_dump_and_load(server, tmp_path):
    path = params.dump(server, tmp_path / "p.yaml", "/turtlesim")
    fresh = ParameterServer()
    fresh.set("/other/keep", 1)
    assert sorted(params.load(fresh, path, "/turtlesim")) == [
        "/turtlesim/background_b", "/turtlesim/background_g", "/turtlesim/background_r",
    ]  # fmt: skip
    assert fresh.get("/turtlesim/background_g") == 86 and fresh.get("/other/keep") == 1
    bad = tmp_path / "bad.yaml"
    bad.write_text("a: 1\nb: [1, 2\n")
    with pytest.raises(BusError) as info:
        params.load(fresh, bad)
    assert info.value.path == str(bad) and info.value.line is not None
    with pytest.raises(BusError, match="cannot read"):
        params.load(fresh, tmp_path / "missing.yaml")


def test_plot_series_png(tmp_path):
    series = [FieldSeries("/turtle1/pose/x", "/turtle1/pose", ["x"])]
    for i in range(20):
        series[0].add(i * 0.016, Pose(x=5.0 + 0.1 * i))
    assert series[0].values[-1] == pytest.approx(6.9)
    png = plot_series(series, tmp_path / "plot.png")
    assert png.read_bytes()[:4] == b"\x89PNG"
    with pytest.raises(BusError, match="no field 'z'"):
        FieldSeries("/turtle1/pose/z", "/turtle1/pose", ["z"]).add(0.0, Pose())
