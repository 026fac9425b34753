"""The text of a rosserial ``ros_lib`` header: one message, or one service.

A message ``pkg/Name`` becomes ``class Name : public ros::Msg`` in ``namespace pkg``
(``ros_lib/pkg/Name.h``): its fields as public members, a constructor that zeroes
them, ``serialize``/``deserialize`` (see :mod:`workbench.serial.headers_fields`),
``getType()`` returning ``"pkg/Name"`` and ``getMD5()`` the type's md5sum.
Constants become ``enum { NAME = value };``.

A service ``pkg/Srv`` becomes one header ``ros_lib/pkg/Srv.h`` holding
``static const char SRV[] = "pkg/Srv";``, the classes ``SrvRequest`` and
``SrvResponse`` (their ``getType()`` returns ``SRV``, their ``getMD5()`` their own
md5sum, as the runtime's ServiceServer/ServiceClient expect) and ``class Srv`` with
the typedefs ``Request`` and ``Response``.

This is the layout rosserial_client's generator writes for the Arduino library,
with three differences so that every header compiles: a ``float`` or ``string``
constant (rosserial writes them as enums too, which C++ refuses) is a
``static constexpr`` member; a service's include guard carries its package
(``_ROS_SERVICE_pkg_Srv_h``), so two services of one name in different packages can
be included together; and variable arrays of messages decode in place (see
:mod:`workbench.serial.headers_fields`).
"""

from __future__ import annotations

import math
from typing import Any

from workbench.errors import SerialError
from workbench.msgs import Message, ServiceType, md5sum
from workbench.serial.headers_fields import PRIMITIVES, Field

_STD_INCLUDES = ["<stdint.h>", "<string.h>", "<stdlib.h>", '"ros/msg.h"']


def _c_string(text: str) -> str:
    """``text`` as a C string literal (UTF-8, non-printable bytes escaped)."""
    out = []
    for byte in text.encode():
        char = chr(byte)
        if char in '"\\':
            out.append("\\" + char)
        elif 32 <= byte < 127:
            out.append(char)
        else:
            out.append(f"\\{byte:03o}")
    return '"' + "".join(out) + '"'


def _c_float(value: float) -> str:
    if math.isnan(value):
        return '__builtin_nanf("")'
    if math.isinf(value):
        return "__builtin_huge_valf()" if value > 0 else "-__builtin_huge_valf()"
    return repr(float(value))


def constant_lines(constants: list[tuple[str, str, Any]]) -> list[str]:
    """The members for a type's constants ``(name, ros_type, value)``."""
    lines = []
    for name, ros_type, value in constants:
        if ros_type == "string":
            lines.append(f"static constexpr const char* {name} = {_c_string(str(value))};")
        elif ros_type in ("float32", "float64"):
            lines.append(f"static constexpr float {name} = {_c_float(value)};")
        elif ros_type in PRIMITIVES:
            lines.append(f"enum {{ {name} = {int(value)} }};")
        else:  # pragma: no cover - the .msg grammar allows only primitive constants
            raise AssertionError(f"constant {name} of type {ros_type}")
    return lines


def _constants(cls: type[Message]) -> list[tuple[str, str, Any]]:
    from workbench.msgs._store import store

    return list(store().ts.fielddefs[cls.__msgtype__][0])


def fields_of(cls: type[Message]) -> list[Field]:
    """The C++ fields of a message class, in wire order."""
    return [Field.of(spec) for spec in cls._specs]


def includes_of(classes: list[type[Message]]) -> list[str]:
    """The headers the fields of ``classes`` need, first use first, each once."""
    seen: list[str] = []
    for cls in classes:
        for field in fields_of(cls):
            seen += [name for name in field.includes() if name not in seen]
    return seen


def _indent(lines: list[str], spaces: int) -> list[str]:
    return [(" " * spaces + line) if line else "" for line in lines]


def _unused(parameter: str, fields: list[Field]) -> list[str]:
    """``(void)parameter;`` for a class without fields, which never touches its buffer."""
    return [] if fields else [f"(void){parameter};"]


def class_lines(cls: type[Message], name: str, type_expr: str) -> list[str]:
    """``class name : public ros::Msg { ... };`` for a message class, indented two spaces.

    Args:
        cls: The message class.
        name: The C++ class name (``String``, ``SpawnRequest``).
        type_expr: The C++ expression ``getType()`` returns (a string literal or a constant).
    """
    fields = fields_of(cls)
    lines = [f"  class {name} : public ros::Msg", "  {", "    public:"]
    members = [line for field in fields for line in field.declaration()]
    lines += _indent(members + constant_lines(_constants(cls)), 6)
    lines += ["", f"    {name}(){':' if fields else ''}"]
    initializers = [field.initializer() for field in fields]
    lines += _indent([text + "," for text in initializers[:-1]] + initializers[-1:], 6)
    lines += ["    {", "    }", ""]
    lines += ["    virtual int serialize(unsigned char *outbuffer) const override", "    {"]
    body = ["int offset = 0;", *(line for field in fields for line in field.serialize())]
    lines += _indent([*body, *_unused("outbuffer", fields), "return offset;"], 6)
    lines += ["    }", ""]
    lines += ["    virtual int deserialize(unsigned char *inbuffer) override", "    {"]
    body = ["int offset = 0;", *(line for field in fields for line in field.deserialize())]
    lines += _indent([*body, *_unused("inbuffer", fields), "return offset;"], 6)
    lines += ["    }", ""]
    lines += [
        f"    virtual const char * getType() override {{ return {type_expr}; }};",
        f'    virtual const char * getMD5() override {{ return "{type_md5(cls)}"; }};',
        "",
        "  };",
    ]
    return lines


def _include_lines(includes: list[str]) -> list[str]:
    return [f"#include {name}" for name in _STD_INCLUDES] + [
        f'#include "{name}.h"' for name in includes
    ]


def message_header(cls: type[Message]) -> str:
    """The text of ``ros_lib/pkg/Name.h`` for a message class."""
    package, name = cls._type.split("/")
    guard = f"_ROS_{package}_{name}_h"
    lines = [f"#ifndef {guard}", f"#define {guard}", ""]
    lines += _include_lines(includes_of([cls]))
    lines += ["", f"namespace {package}", "{", ""]
    lines += class_lines(cls, name, f'"{cls._type}"')
    lines += ["", "}", "#endif", ""]
    return "\n".join(lines)


def service_header(service: type[ServiceType]) -> str:
    """The text of ``ros_lib/pkg/Srv.h`` for a service type."""
    package, name = service._type.split("/")
    constant = name.upper()
    guard = f"_ROS_SERVICE_{package}_{name}_h"
    lines = [f"#ifndef {guard}", f"#define {guard}"]
    lines += _include_lines(includes_of([service.Request, service.Response]))
    lines += ["", f"namespace {package}", "{", ""]
    lines += [f'static const char {constant}[] = "{service._type}";', ""]
    lines += class_lines(service.Request, f"{name}Request", constant)
    lines += [""]
    lines += class_lines(service.Response, f"{name}Response", constant)
    lines += [
        "",
        f"  class {name} {{",
        "    public:",
        f"    typedef {name}Request Request;",
        f"    typedef {name}Response Response;",
        "  };",
        "",
        "}",
        "#endif",
        "",
    ]
    return "\n".join(lines)


def type_md5(cls: type[Message]) -> str:
    """The md5sum of a message class (its dependencies resolved in the store now).

    Raises:
        SerialError: A type it uses is not registered.
    """
    try:
        return md5sum(cls._type)
    except Exception as error:  # the typestore's own error for a missing dependency
        raise SerialError(
            f"cannot write the header of {cls._type}: {error}",
            hint="register the message types it uses first",
        ) from None
