"""The C++ of one message field in a rosserial ``ros_lib`` header.

Every field of a message class becomes a member of its C++ class, a line in the
constructor's initializer list, and the statements that write it to and read it
from the wire: ROS 1 serialization, little-endian, byte by byte, exactly as
``rosserial_client``'s generator has the Arduino library do it:

* unsigned integers and ``char``: shifted out and in, one byte at a time;
* signed integers, ``bool`` and ``float32``: the same through a union with the
  unsigned type of their size;
* ``float64``: a ``float`` on the board (AVR has no 64-bit double), converted by
  ``ros::Msg::serializeAvrFloat64`` / ``deserializeAvrFloat64`` to and from the
  8 wire bytes;
* ``string``: a ``const char*``; a ``uint32`` length, then the bytes; decoding
  moves the bytes one place down in the receive buffer to end them with a NUL;
* ``time`` / ``duration``: ``ros::Time`` / ``ros::Duration``, ``sec`` then ``nsec``;
* a message: its own ``serialize``/``deserialize``;
* ``T[n]``: a C array of ``n`` elements;
* ``T[]``: ``NAME_length``, a pointer ``NAME`` and a spare element ``st_NAME``; the
  length as ``uint32``, then the elements; decoding ``realloc``\\ s the array when
  the new length is larger.

One deviation makes variable arrays *of messages* correct: rosserial decodes every
element into ``st_NAME`` and copies it into place, so elements holding variable
arrays of their own end up sharing (or pointing at freed) buffers. Here elements
are decoded in place; new slots start as copies of the untouched ``st_NAME`` and
``NAME_allocated`` counts the slots that own their buffers. (Their ``realloc`` and
``memcpy`` cast the class pointer to ``void*``: the byte copy, virtual table pointer
included, is meant, and g++'s ``-Wclass-memaccess`` is told so.)
"""

from __future__ import annotations

from dataclasses import dataclass

from workbench.msgs._fields import FieldSpec

_TIME = "builtin_interfaces/msg/Time"
_DURATION = "builtin_interfaces/msg/Duration"

#: ROS primitive -> (C++ type on the board, bytes on the wire), as rosserial_arduino maps them.
PRIMITIVES: dict[str, tuple[str, int]] = {
    "bool": ("bool", 1),
    "byte": ("int8_t", 1),
    "int8": ("int8_t", 1),
    "char": ("uint8_t", 1),
    "uint8": ("uint8_t", 1),
    "int16": ("int16_t", 2),
    "uint16": ("uint16_t", 2),
    "int32": ("int32_t", 4),
    "uint32": ("uint32_t", 4),
    "int64": ("int64_t", 8),
    "uint64": ("uint64_t", 8),
    "float32": ("float", 4),
}
_UNSIGNED = {1: "uint8_t", 2: "uint16_t", 4: "uint32_t", 8: "uint64_t"}


@dataclass(frozen=True)
class Element:
    """How one value of a field's element type looks in C++.

    Attributes:
        kind: ``unsigned``, ``union`` (signed, bool, float32), ``float64``, ``string``,
            ``time`` or ``message``.
        cpp: The C++ type of a plain field (``int8_t``, ``const char*``, ``ros::Time``).
        element_cpp: The C++ type as an array element (``char*`` for strings).
        size: Bytes on the wire of an integer, bool or float32 (0 for the others).
        include: The header this type needs (``ros/time``, ``geometry_msgs/Point``), if any.
    """

    kind: str
    cpp: str
    element_cpp: str
    size: int = 0
    include: str | None = None


def element_of(spec: FieldSpec) -> Element:
    """The C++ element type of a field (for arrays: of one element)."""
    if spec.elem == _TIME:
        return Element("time", "ros::Time", "ros::Time", include="ros/time")
    if spec.elem == _DURATION:
        return Element("time", "ros::Duration", "ros::Duration", include="ros/duration")
    if spec.elem_is_msg:
        package, _, name = spec.elem.split("/")
        return Element(
            "message", f"{package}::{name}", f"{package}::{name}", 0, f"{package}/{name}"
        )
    if spec.elem == "string":
        return Element("string", "const char*", "char*")
    if spec.elem == "float64":
        return Element("float64", "float", "float")
    cpp, size = PRIMITIVES[spec.elem]
    kind = "unsigned" if cpp == _UNSIGNED[size] else "union"
    return Element(kind, cpp, cpp, size)


def _tag(expr: str) -> str:
    """A C++ identifier for the temporaries of ``expr`` (``this->ranges[i]`` -> ``rangesi``)."""
    last = expr.removeprefix("this->").split(".")[-1]
    return "".join(c for c in last if c.isalnum() or c == "_")


def _shift_out(source: str, size: int) -> list[str]:
    return [f"*(outbuffer + offset + {i}) = ({source} >> (8 * {i})) & 0xFF;" for i in range(size)]


def _union(element: Element, tag: str) -> list[str]:
    return [
        "union {",
        f"  {element.cpp} real;",
        f"  {_UNSIGNED[element.size]} base;",
        f"}} u_{tag};",
    ]


def _integer_code(element: Element, expr: str) -> tuple[list[str], list[str]]:
    """An integer, bool or float32: shifted byte by byte, through a union unless unsigned."""
    tag, size, base = _tag(expr), element.size, _UNSIGNED[element.size]
    reads = [f"(({base}) (*(inbuffer + offset + {i}))) << (8 * {i})" for i in range(size)]
    if element.kind == "union":
        out = [*_union(element, tag), f"u_{tag}.real = {expr};"]
        out += _shift_out(f"u_{tag}.base", size)
        into = [*_union(element, tag), f"u_{tag}.base = 0;"]
        into += [f"u_{tag}.base |= {read};" for read in reads]
        into.append(f"{expr} = u_{tag}.real;")
    else:
        out = _shift_out(expr, size)
        into = [f"{expr} =  (({base}) (*(inbuffer + offset)));"]
        into += [f"{expr} |= {read};" for read in reads[1:]]
    advance = f"offset += sizeof({expr});"
    return [*out, advance], [*into, advance]


def _string_code(expr: str) -> tuple[list[str], list[str]]:
    """A string: uint32 length and bytes; decoded in place, NUL-ended one byte earlier."""
    length = f"length_{_tag(expr)}"
    out = [
        f"uint32_t {length} = strlen({expr});",
        f"varToArr(outbuffer + offset, {length});",
        "offset += 4;",
        f"memcpy(outbuffer + offset, {expr}, {length});",
        f"offset += {length};",
    ]
    into = [
        f"uint32_t {length};",
        f"arrToVar({length}, (inbuffer + offset));",
        "offset += 4;",
        f"for(unsigned int k= offset; k< offset+{length}; ++k){{",
        "    inbuffer[k-1]=inbuffer[k];",
        "}",
        f"inbuffer[offset+{length}-1]=0;",
        f"{expr} = (char *)(inbuffer + offset-1);",
        f"offset += {length};",
    ]
    return out, into


def value_code(element: Element, expr: str) -> tuple[list[str], list[str]]:
    """The statements that write ``expr`` at ``outbuffer + offset`` and that read it from
    ``inbuffer + offset``, each advancing ``offset``.

    Returns:
        (serialize statements, deserialize statements).
    """
    if element.kind == "message":
        return (
            [f"offset += {expr}.serialize(outbuffer + offset);"],
            [f"offset += {expr}.deserialize(inbuffer + offset);"],
        )
    if element.kind == "time":
        sec_out, sec_in = value_code(_SEC, f"{expr}.sec")
        nsec_out, nsec_in = value_code(_SEC, f"{expr}.nsec")
        return sec_out + nsec_out, sec_in + nsec_in
    if element.kind == "float64":
        return (
            [f"offset += serializeAvrFloat64(outbuffer + offset, {expr});"],
            [f"offset += deserializeAvrFloat64(inbuffer + offset, &({expr}));"],
        )
    if element.kind == "string":
        return _string_code(expr)
    return _integer_code(element, expr)


def serialize_value(element: Element, expr: str) -> list[str]:
    """Statements that append the value ``expr`` at ``outbuffer + offset`` and advance ``offset``."""
    return value_code(element, expr)[0]


def deserialize_value(element: Element, expr: str) -> list[str]:
    """Statements that read the value at ``inbuffer + offset`` into ``expr`` and advance ``offset``."""
    return value_code(element, expr)[1]


#: ``sec`` and ``nsec`` of ros::Time and ros::Duration: four bytes each, as rosserial writes them.
_SEC = Element("unsigned", "uint32_t", "uint32_t", 4)


def _loop(count: str, body: list[str]) -> list[str]:
    return [f"for( uint32_t i = 0; i < {count}; i++){{", *("  " + line for line in body), "}"]


@dataclass(frozen=True)
class Field:
    """One field of a message class and its C++."""

    spec: FieldSpec
    element: Element

    @classmethod
    def of(cls, spec: FieldSpec) -> Field:
        """The C++ field for a message field."""
        return cls(spec, element_of(spec))

    @property
    def name(self) -> str:
        return self.spec.name

    @property
    def kind(self) -> str:
        """``scalar``, ``array`` (``T[n]``) or ``seq`` (``T[]``)."""
        return self.spec.kind if self.spec.kind in ("array", "seq") else "scalar"

    def declaration(self) -> list[str]:
        """The class members."""
        name, cpp = self.name, self.element.element_cpp
        if self.kind == "array":
            return [f"{cpp} {name}[{self.spec.length}];"]
        if self.kind == "seq":
            lines = [
                f"uint32_t {name}_length;",
                f"typedef {cpp} _{name}_type;",
                f"_{name}_type st_{name};",
                f"_{name}_type * {name};",
            ]
            if self.element.kind == "message":
                lines.append(f"uint32_t {name}_allocated;")
            return lines
        return [f"typedef {self.element.cpp} _{name}_type;", f"_{name}_type {name};"]

    def initializer(self) -> str:
        """The constructor's initializer(s) of the members (without a trailing comma)."""
        name = self.name
        if self.kind == "seq":
            tail = f", {name}_allocated(0)" if self.element.kind == "message" else ""
            return f"{name}_length(0), st_{name}(), {name}(nullptr){tail}"
        if self.kind == "scalar" and self.element.kind == "string":
            return f'{name}("")'
        if self.kind == "scalar" and self.element.kind not in ("message", "time"):
            return f"{name}(0)"
        return f"{name}()"

    def serialize(self) -> list[str]:
        """Statements of ``serialize`` for this field."""
        member = f"this->{self.name}"
        if self.kind == "scalar":
            return serialize_value(self.element, member)
        each = serialize_value(self.element, f"{member}[i]")
        if self.kind == "array":
            return _loop(str(self.spec.length), each)
        return [
            *_shift_out(f"{member}_length", 4),
            f"offset += sizeof({member}_length);",
            *_loop(f"{self.name}_length", each),
        ]

    def deserialize(self) -> list[str]:
        """Statements of ``deserialize`` for this field."""
        member = f"this->{self.name}"
        if self.kind == "scalar":
            return deserialize_value(self.element, member)
        if self.kind == "array":
            return _loop(str(self.spec.length), deserialize_value(self.element, f"{member}[i]"))
        name, cpp = self.name, self.element.element_cpp
        lines = [f"uint32_t {name}_lengthT = ((uint32_t) (*(inbuffer + offset)));"]
        lines += [
            f"{name}_lengthT |= ((uint32_t) (*(inbuffer + offset + {i}))) << (8 * {i});"
            for i in range(1, 4)
        ]
        lines.append(f"offset += sizeof({member}_length);")
        if self.element.kind == "message":
            lines += [
                f"if({name}_lengthT > {name}_allocated){{",
                f"  {member} = ({cpp}*)realloc((void*){member}, {name}_lengthT * sizeof({cpp}));",
                f"  for( uint32_t i = {name}_allocated; i < {name}_lengthT; i++)",
                f"    memcpy( (void*)&({member}[i]), &(this->st_{name}), sizeof({cpp}));",
                f"  {name}_allocated = {name}_lengthT;",
                "}",
                f"{name}_length = {name}_lengthT;",
                *_loop(f"{name}_length", deserialize_value(self.element, f"{member}[i]")),
            ]
            return lines
        lines += [
            f"if({name}_lengthT > {name}_length)",
            f"  {member} = ({cpp}*)realloc({member}, {name}_lengthT * sizeof({cpp}));",
            f"{name}_length = {name}_lengthT;",
        ]
        each = deserialize_value(self.element, f"this->st_{name}")
        each.append(f"memcpy( &({member}[i]), &(this->st_{name}), sizeof({cpp}));")
        return [*lines, *_loop(f"{name}_length", each)]

    def includes(self) -> list[str]:
        """The headers the field's type needs."""
        return [self.element.include] if self.element.include else []
