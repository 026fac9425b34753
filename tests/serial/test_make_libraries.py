"""rosserial_arduino's make_libraries.py: ros_lib headers for every known type, compiled and run.

The headers are generated once per module (with the custom package
``tests/data/serial/lab_serial_msgs`` registered), compiled with g++ in one program
(``tests/data/serial/roundtrip.cpp``) against the stand-ins for the Arduino library's
``ros/msg.h``, ``ros/time.h`` and ``ros/duration.h`` in ``tests/data/serial/ros_lib_stub``,
and fed bytes from workbench's own ROS 1 serializer: every class must read them and
write the same bytes back, report workbench's md5sum, and hold the right field values.
"""

from __future__ import annotations

import random
import shutil
import subprocess
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from skipping import skip_or_fail

from workbench.errors import SerialError
from workbench.msgs import (
    Message,
    get_service,
    get_type,
    list_services,
    list_types,
    md5sum,
    serialize,
)
from workbench.msgs._fields import DTYPES
from workbench.serial.headers_sources import keyword_field, known_packages, register_package_dir
from workbench.serial.make_libraries import main, parse_arguments, write_libraries

DATA = Path(__file__).resolve().parents[1] / "data" / "serial"
STUB = DATA / "ros_lib_stub"
CUSTOM = DATA / "lab_serial_msgs"
TIME_TYPES = ("builtin_interfaces/msg/Time", "builtin_interfaces/msg/Duration")


# --- generation ---------------------------------------------------------------------------


@pytest.fixture(scope="module")
def ros_lib(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """``ros_lib`` with a header for every known type, the custom package included."""
    assert register_package_dir(CUSTOM) == "lab_serial_msgs"
    out = tmp_path_factory.mktemp("arduino")
    written = write_libraries(out)
    assert written and all(path.is_file() for path in written)
    return out / "ros_lib"


def exportable_services() -> list[str]:
    """The services whose parts a header can declare (no field named after a C++ keyword:
    other tests of the session register such types)."""
    return [
        name
        for name in list_services()
        if not any(
            keyword_field(part) for part in (get_service(name).Request, get_service(name).Response)
        )
    ]


def exportable_types(services: list[str]) -> list[str]:
    everything = set(list_services())
    inner = {f"{name}{part}" for name in everything for part in ("Request", "Response")}
    return [
        name
        for name in list_types()
        if name not in inner
        and not name.startswith("builtin_interfaces/")
        and keyword_field(get_type(name)) is None
    ]


def header_classes() -> list[tuple[str, str]]:
    """(``pkg/Name`` as the table names it, C++ class) for every class the headers define."""
    services = exportable_services()
    inner = {f"{name}{part}" for name in services for part in ("Request", "Response")}
    found = exportable_types(services)
    found += sorted(inner)
    return [(name, name.replace("/", "::")) for name in sorted(found)]


def test_every_known_type_has_its_header(ros_lib: Path) -> None:
    written = {str(path.relative_to(ros_lib)) for path in ros_lib.rglob("*.h")}
    services = set(exportable_services())
    messages = set(exportable_types(list(services)))
    assert written == {f"{name}.h" for name in messages | services}
    assert {"std_msgs/String.h", "sensor_msgs/LaserScan.h", "turtlesim/Spawn.h"} <= written
    assert {"lab_serial_msgs/Reading.h", "lab_serial_msgs/Calibrate.h"} <= written
    assert "turtlesim/SpawnRequest.h" not in written
    assert not (ros_lib / "builtin_interfaces").exists()


def test_headers_have_rosserials_layout(ros_lib: Path) -> None:
    string = (ros_lib / "std_msgs" / "String.h").read_text()
    assert string.startswith("#ifndef _ROS_std_msgs_String_h\n#define _ROS_std_msgs_String_h\n")
    assert '#include "ros/msg.h"' in string and "namespace std_msgs\n{" in string
    assert "  class String : public ros::Msg\n" in string
    assert "typedef const char* _data_type;" in string
    assert 'virtual const char * getType() override { return "std_msgs/String"; };' in string
    assert f'getMD5() override {{ return "{md5sum("std_msgs/String")}"; }};' in string
    scan = (ros_lib / "sensor_msgs" / "LaserScan.h").read_text()
    assert '#include "std_msgs/Header.h"' in scan
    assert "uint32_t ranges_length;" in scan and "_ranges_type * ranges;" in scan
    header = (ros_lib / "std_msgs" / "Header.h").read_text()
    assert '#include "ros/time.h"' in header and "typedef ros::Time _stamp_type;" in header
    spawn = (ros_lib / "turtlesim" / "Spawn.h").read_text()
    assert 'static const char SPAWN[] = "turtlesim/Spawn";' in spawn
    assert "getType() override { return SPAWN; };" in spawn
    assert "typedef SpawnRequest Request;" in spawn and "typedef SpawnResponse Response;" in spawn
    log = (ros_lib / "rosserial_msgs" / "Log.h").read_text()
    assert "enum { ROSDEBUG = 0 };" in log and "enum { FATAL = 4 };" in log


def test_only_the_named_packages(tmp_path: Path) -> None:
    written = write_libraries(tmp_path, ["turtlesim", "std_srvs"])
    assert {path.parent.name for path in written} == {"turtlesim", "std_srvs"}
    assert (tmp_path / "ros_lib" / "turtlesim" / "Pose.h").is_file()
    assert [p.name for p in known_packages(["std_srvs"])] == ["std_srvs"]


# --- compiled ---------------------------------------------------------------------------


def entries_source(ros_lib: Path) -> str:
    """``entries.inc``: every header included, and the ENTRIES table of every class."""
    lines = [f'#include "{path.relative_to(ros_lib)}"' for path in sorted(ros_lib.rglob("*.h"))]
    classes = header_classes()
    for index, (_, cpp) in enumerate(classes):
        lines.append(f"static ros::Msg *make_{index}() {{ return new {cpp}(); }}")
    lines.append("static const Entry ENTRIES[] = {")
    lines += [f'  {{"{name}", make_{index}}},' for index, (name, _) in enumerate(classes)]
    lines.append("};")
    return "\n".join(lines) + "\n"


@pytest.fixture(scope="module")
def roundtrip(ros_lib: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The round-trip program, compiled once with every header in it."""
    gxx = shutil.which("g++")
    if gxx is None:
        skip_or_fail("g++ is not installed (apt-get install g++)")
    build = tmp_path_factory.mktemp("build")
    (build / "entries.inc").write_text(entries_source(ros_lib))
    program = build / "roundtrip"
    command = [gxx, "-std=c++11", "-O0", "-Wall", "-Wextra", "-Werror", "-pedantic"]
    command += [f"-I{build}", f"-I{STUB}", f"-I{ros_lib}"]
    command += [str(DATA / "roundtrip.cpp"), "-o", str(program)]
    done = subprocess.run(command, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr[-4000:]
    return program


def run_program(program: Path, items: list[tuple[str, bytes]]) -> list[list[str]]:
    """Feed ``(class name, bytes)`` lines; per line ``[name, type, md5, consumed, hex, fields]``."""
    text = "".join(f"{name} {data.hex() or '-'}\n" for name, data in items)
    done = subprocess.run([str(program)], input=text, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    rows = []
    for line in done.stdout.splitlines():
        head, _, fields = line.partition("|")
        rows.append([*head.split(" "), fields])
    assert len(rows) == len(items), done.stdout[-2000:]
    return rows


# --- random messages ------------------------------------------------------------------------


def random_value(spec: Any, rng: random.Random, depth: int) -> Any:
    """A random value for one element of a field (floats exact in float32, as on the board)."""
    elem = spec.elem
    if spec.elem_is_msg:
        return random_message(get_type(elem), rng, depth + 1)
    if elem == "string":
        return "".join(rng.choice("abcxyz_019 ") for _ in range(rng.randint(0, 6)))
    if elem == "bool":
        return rng.random() < 0.5
    if elem in ("float32", "float64"):
        return float(np.float32(rng.uniform(-1000.0, 1000.0)))
    bits = int(elem.lstrip("uint") or 8) if elem not in ("byte", "char") else 8
    if elem.startswith("u") or elem == "char":
        return rng.getrandbits(bits)
    return rng.randint(-(2 ** (bits - 1)), 2 ** (bits - 1) - 1)


def random_message(cls: type[Message], rng: random.Random, depth: int = 0) -> Message:
    """A message of ``cls`` with every field random; arrays shorter the deeper they are."""
    if cls.__msgtype__ in TIME_TYPES:
        low = 0 if cls.__msgtype__ == TIME_TYPES[0] else -(2**31)
        return cls(sec=rng.randint(low, 2**31 - 1), nanosec=rng.randint(0, 999_999_999))
    values = {}
    for spec in cls._specs:
        if spec.kind in ("base", "msg"):
            values[spec.name] = random_value(spec, rng, depth)
        else:
            count = spec.length or rng.randint(0, 3 if depth < 2 else 1 if depth < 4 else 0)
            items = [random_value(spec, rng, depth) for _ in range(count)]
            # a list of big uint64 would pass through float64: give the wire dtype
            values[spec.name] = np.array(items, DTYPES[spec.elem]) if spec.elem in DTYPES else items
    return cls(**values)


def check_rows(rows: list[list[str]], items: list[tuple[str, bytes]]) -> None:
    """Every class read every byte and wrote the same bytes back, with its type and md5sum."""
    for (name, data), row in zip(items, rows, strict=True):
        got_name, got_type, got_md5, consumed, written = row[:5]
        assert got_name == name
        service = name.removesuffix("Request").removesuffix("Response")
        is_part = service != name and service in list_services()
        assert got_type == (service if is_part else name), name
        assert got_md5 == md5sum(name), name
        assert int(consumed) == len(data), name
        assert written == (data.hex() or "-"), name


def test_every_class_round_trips_workbench_bytes(roundtrip: Path) -> None:
    rng = random.Random(18)
    items = []
    for _ in range(3):  # three messages per class into the same object, as a board receives them
        for name, _cpp in header_classes():
            items.append((name, serialize(random_message(get_type(name), rng))))
    check_rows(run_program(roundtrip, items), items)


# --- field values ---------------------------------------------------------------------------


def num(value: Any) -> str:
    """C's ``%.9g`` of a value the board holds as a float (or an integer)."""
    if isinstance(value, (bool, np.bool_)):
        return str(int(value))
    if isinstance(value, (int, np.integer)):
        return f"{int(value):.9g}"
    return f"{float(np.float32(value)):.9g}"


def stamp(time: Any) -> str:
    return f"{num(time.sec)}.{num(time.nanosec)}"


def header_fields(header: Any) -> list[str]:
    return [
        f"header.seq={num(header.seq)}",
        f"header.stamp={stamp(header.stamp)}",
        f"header.frame_id={header.frame_id}",
    ]


def sample_fields(prefix: str, sample: Any) -> list[str]:
    values = ",".join(num(v) for v in sample.values)
    return [
        f"{prefix}.id={num(sample.id)}",
        f"{prefix}.values={values}",
        f"{prefix}.grade={num(sample.grade)}",
    ]


def reading_fields(m: Any) -> list[str]:
    out = header_fields(m.header)
    out += [f"level={num(m.level)}", f"count={int(m.count)}", f"value={num(m.value)}"]
    out += [f"gains={','.join(num(v) for v in m.gains)}"]
    out += [f"deltas={','.join(num(v) for v in m.deltas)}"]
    out += [f"switches={','.join(num(v) for v in m.switches)}", f"label={m.label}"]
    out += [f"tags={','.join(m.tags)}", f"stamp={stamp(m.stamp)}", f"period={stamp(m.period)}"]
    out += [f"waits={','.join(stamp(w) for w in m.waits)}"]
    out += sample_fields("latest", m.latest)
    out += [f"history={num(len(m.history))}"]
    for index, item in enumerate(m.history):
        out += sample_fields(f"history{index}", item)
    out += sample_fields("pair0", m.pair[0]) + sample_fields("pair1", m.pair[1])
    return [*out, "LOW=-2", "HIGH=200", "SCALE=0.5", "UNIT=m/s"]


def expected_fields(name: str, m: Any) -> str:
    """What roundtrip.cpp prints for the fields of a message of class ``name``."""
    if name == "std_msgs/String":
        out = [f"data={m.data}"]
    elif name == "std_msgs/Bool":
        out = [f"data={num(m.data)}"]
    elif name == "std_msgs/Duration":
        out = [f"data.sec={num(m.data.sec)}", f"data.nsec={num(m.data.nanosec)}"]
    elif name == "geometry_msgs/Twist":
        out = [
            f"linear={num(m.linear.x)},{num(m.linear.y)},{num(m.linear.z)}",
            f"angular={num(m.angular.x)},{num(m.angular.y)},{num(m.angular.z)}",
        ]
    elif name == "sensor_msgs/LaserScan":
        out = header_fields(m.header)
        out += [f"angle_min={num(m.angle_min)}", f"angle_max={num(m.angle_max)}"]
        out += [f"range_max={num(m.range_max)}"]
        out += [f"ranges={','.join(num(v) for v in m.ranges)}"]
        out += [f"intensities={','.join(num(v) for v in m.intensities)}"]
    else:
        out = reading_fields(m)
    return "|".join(out)


def lab_reading(history: int, seed: int) -> Message:
    """A lab_serial_msgs/Reading with ``history`` samples, each with its own values."""
    Reading = get_type("lab_serial_msgs/Reading")
    Sample = get_type("lab_serial_msgs/Sample")
    Time = get_type("builtin_interfaces/Time")
    Duration = get_type("builtin_interfaces/Duration")
    rng = random.Random(seed)
    samples = [
        Sample(id=100 * seed + i, values=[i + 0.25 * k for k in range(i + 1)], grade=ord("A") + i)
        for i in range(history)
    ]
    return Reading(
        header={"seq": seed, "stamp": Time(sec=1_700_000_000, nanosec=5), "frame_id": "board"},
        level=-128 if seed % 2 else 127,
        count=2**64 - 1 - seed,
        value=-1234.5,
        gains=[0.5, -0.25, 0.125 * seed],
        deltas=[rng.randint(-(2**15), 2**15 - 1) for _ in range(seed % 4)],
        switches=[True, bool(seed % 2)],
        label="lab " + str(seed),
        tags=["t" * k for k in range(1, 1 + seed % 3)],
        stamp=Time(sec=12, nanosec=999_999_999),
        period=Duration(sec=-3, nanosec=500_000_000),
        waits=[Duration(sec=k, nanosec=k) for k in range(seed % 3)],
        latest=Sample(id=7, values=[1.5], grade=ord("z")),
        history=samples,
        pair=[Sample(id=1, values=[], grade=0), Sample(id=2, values=[2.0, 4.0], grade=255)],
    )


def representative() -> list[tuple[str, Message]]:
    String = get_type("std_msgs/String")
    Bool = get_type("std_msgs/Bool")
    Twist = get_type("geometry_msgs/Twist")
    LaserScan = get_type("sensor_msgs/LaserScan")
    Duration = get_type("std_msgs/Duration")
    return [
        ("std_msgs/String", String(data="hello world!")),
        ("std_msgs/String", String(data="")),
        ("std_msgs/Bool", Bool(data=True)),
        ("geometry_msgs/Twist", Twist(linear={"x": 2.0, "y": -0.5}, angular={"z": 1.25})),
        (
            "sensor_msgs/LaserScan",
            LaserScan(
                header={"seq": 42, "stamp": {"sec": 10, "nanosec": 20}, "frame_id": "base_scan"},
                angle_min=-1.5,
                angle_max=1.5,
                range_max=3.5,
                ranges=[0.25, 1.0, float("inf"), 3.0],
                intensities=[100.0, 0.0],
            ),
        ),
        ("sensor_msgs/LaserScan", LaserScan(ranges=[0.5])),
        ("std_msgs/Duration", Duration(data={"sec": -2, "nanosec": 750})),
        # the history grows, shrinks and grows again in one object, each sample with its own array
        ("lab_serial_msgs/Reading", lab_reading(3, 1)),
        ("lab_serial_msgs/Reading", lab_reading(1, 2)),
        ("lab_serial_msgs/Reading", lab_reading(4, 3)),
        ("lab_serial_msgs/Reading", lab_reading(0, 4)),
    ]


def test_representative_messages_keep_bytes_and_values(roundtrip: Path) -> None:
    cases = representative()
    items = [(name, serialize(message)) for name, message in cases]
    rows = run_program(roundtrip, items)
    check_rows(rows, items)
    for (name, message), row in zip(cases, rows, strict=True):
        assert row[5] == expected_fields(name, message), name


def test_float64_is_a_float_on_the_board(roundtrip: Path) -> None:
    """rosserial_arduino's float64: 8 bytes on the wire, a float in the class (AVR has no double)."""
    Twist = get_type("geometry_msgs/Twist")
    sent = Twist(linear={"x": 0.1, "y": 1e300})
    row = run_program(roundtrip, [("geometry_msgs/Twist", serialize(sent))])[0]
    back = Twist(linear={"x": float(np.float32(0.1)), "y": float("inf")})
    assert row[4] == serialize(back).hex()


def test_service_parts_round_trip(roundtrip: Path) -> None:
    Calibrate = get_type("lab_serial_msgs/Calibrate")
    Spawn = get_type("turtlesim/Spawn")
    items = [
        (
            "lab_serial_msgs/CalibrateRequest",
            serialize(Calibrate.Request(reading=lab_reading(2, 5), mode=3)),
        ),
        (
            "lab_serial_msgs/CalibrateResponse",
            serialize(Calibrate.Response(ok=True, message="done", offsets=[0.5, -2.0])),
        ),
        ("turtlesim/SpawnRequest", serialize(Spawn.Request(x=1.0, y=2.0, theta=0.5, name="t2"))),
        ("turtlesim/SpawnResponse", serialize(Spawn.Response(name="t2"))),
    ]
    rows = run_program(roundtrip, items)
    check_rows(rows, items)
    assert [row[1] for row in rows] == ["lab_serial_msgs/Calibrate"] * 2 + ["turtlesim/Spawn"] * 2


# --- the node and its errors ------------------------------------------------------------------


def test_workbench_run_make_libraries(run_cli, tmp_path: Path) -> None:
    done = run_cli(
        "run", "rosserial_arduino", "make_libraries.py", tmp_path, "--msgs", CUSTOM,
        "--package", "lab_serial_msgs", "--package", "std_msgs", "__name:=make_libraries",
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert f"Exporting to {tmp_path / 'ros_lib'}" in lines
    assert "Exporting lab_serial_msgs  Messages: Reading, Sample  Services: Calibrate" in lines
    assert any(line.startswith("Exporting std_msgs  Messages: Bool, Byte,") for line in lines)
    assert (
        f"Wrote 35 headers of 2 packages into {tmp_path / 'ros_lib'} (with lab_serial_msgs)."
        in lines
    )
    assert (tmp_path / "ros_lib" / "lab_serial_msgs" / "Calibrate.h").is_file()
    assert sorted(p.name for p in (tmp_path / "ros_lib").iterdir()) == [
        "lab_serial_msgs",
        "std_msgs",
    ]


def test_bad_command_lines_are_one_line_errors(run_cli, tmp_path: Path) -> None:
    done = run_cli("run", "rosserial_arduino", "make_libraries.py")
    assert done.returncode == 1 and done.stdout == ""
    assert done.stderr.strip().splitlines() == [
        "workbench run: error: make_libraries.py needs the folder to write ros_lib into "
        "(usage: make_libraries.py DIR [--msgs PKG_DIR]... [--package NAME]...)"
    ]
    done = run_cli(
        "run", "rosserial_arduino", "make_libraries.py", tmp_path, "--package", "std_msg"
    )
    assert done.returncode == 1
    assert "no message or service types in package 'std_msg' (did you mean std_msgs" in done.stderr
    assert len(done.stderr.strip().splitlines()) == 1


def test_arguments() -> None:
    options = parse_arguments(["out", "--msgs=a", "--msgs", "b", "--package", "p"])
    assert (options.directory, options.msgs, options.packages) == ("out", ["a", "b"], ["p"])
    assert parse_arguments(["-h"]).show_help
    for argv, text in [
        (["out", "--pkg", "x"], "unknown option '--pkg'"),
        (["out", "--package"], "--package needs a value"),
        (["a", "b"], "one output folder, not 'a' and 'b'"),
    ]:
        with pytest.raises(SerialError, match=text):
            parse_arguments(argv)


def test_help(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["-h"]) == 0
    assert capsys.readouterr().out.startswith("usage: make_libraries.py DIR")


def test_bad_folders_and_packages(tmp_path: Path) -> None:
    afile = tmp_path / "file"
    afile.write_text("x")
    with pytest.raises(SerialError, match="is a file, not a folder"):
        write_libraries(afile)
    with pytest.raises(SerialError, match="holds no msg/\\*.msg or srv/\\*.srv files"):
        register_package_dir(tmp_path)
    broken = tmp_path / "broken_msgs"
    (broken / "msg").mkdir(parents=True)
    (broken / "msg" / "Bad.msg").write_text("int8 x\nfloat64[ y\n")
    with pytest.raises(SerialError) as caught:
        register_package_dir(broken)
    assert str(caught.value) == (
        f"{broken / 'msg' / 'Bad.msg'}: cannot register broken_msgs/Bad: Could not parse "
        "(each line is 'type name' or 'type NAME=value')"
    )
    dangling = tmp_path / "dangling_msgs"
    (dangling / "msg").mkdir(parents=True)
    (dangling / "msg" / "Holder.msg").write_text("NotThere inner\n")
    assert register_package_dir(dangling) == "dangling_msgs"
    with pytest.raises(SerialError, match="cannot write the header of dangling_msgs/Holder"):
        write_libraries(tmp_path / "out", ["dangling_msgs"])


def test_a_field_named_after_a_cpp_keyword_leaves_its_type_out_with_one_warning(
    tmp_path: Path, caplog: pytest.LogCaptureFixture
) -> None:
    from workbench.msgs import register_message

    register_message("keyword_msgs/Reading", "float64 double\nint32 count\n")
    register_message("keyword_msgs/Fine", "float64 value\n")
    import logging

    log = logging.getLogger("workbench.serial")
    log.addHandler(caplog.handler)  # command-line tests may have stopped propagation
    try:
        with caplog.at_level("WARNING", logger="workbench.serial"):
            written = write_libraries(tmp_path, ["keyword_msgs"])
    finally:
        log.removeHandler(caplog.handler)
    assert [p.name for p in written] == ["Fine.h"]
    assert sorted({r.getMessage() for r in caplog.records}) == [
        "keyword_msgs/Reading left out: its field 'double' is a C++ keyword, which a header "
        "cannot declare"
    ]
