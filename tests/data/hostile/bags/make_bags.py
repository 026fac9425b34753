"""Write the damaged bags of this folder (deterministic; run from anywhere).

``python tests/data/hostile/bags/make_bags.py`` rewrites every ``*.bag`` here from one intact
bag made with workbench's writer, each damaged in one way that a real file meets: a chunk
whose bytes are garbage, a chunk info whose start time is 2^32 - 1 s (the year 2106) or 0,
a record length past the end, a type whose definition does not parse, a file cut short.
"""

from __future__ import annotations

import struct
from pathlib import Path

HERE = Path(__file__).resolve().parent
T0 = 1638598185.0


def intact(path: Path, compression: str = "none", chunk_size: int = 600) -> bytes:
    from workbench.bag import BagWriter
    from workbench.msgs.geometry_msgs import Twist, Vector3
    from workbench.msgs.std_msgs import String

    with BagWriter(path, compression=compression, chunk_size=chunk_size) as bag:
        for i in range(30):
            bag.write("/cmd_vel", Twist(linear=Vector3(x=0.1 * i)), T0 + 0.01 * i)
            bag.write("/chatter", String(data=f"hello {i}"), T0 + 0.01 * i + 0.005)
    return path.read_bytes()


def chunk_positions(data: bytes) -> list[int]:
    """Offsets of the chunk records: the writer puts ``op`` first, after the header length."""
    out, at = [], data.find(b"\x04\x00\x00\x00op=\x05")
    while at != -1:
        out.append(at - 4)
        at = data.find(b"\x04\x00\x00\x00op=\x05", at + 1)
    return out


def chunk_info_offsets(data: bytes) -> list[int]:
    out, at = [], data.find(b"op=\x06")
    while at != -1:
        out.append(at)
        at = data.find(b"op=\x06", at + 1)
    return out


def set_field(data: bytearray, after: int, name: bytes, value: bytes) -> None:
    """Overwrite the value of the first field ``name=`` after byte ``after``."""
    at = data.index(name + b"=", after) + len(name) + 1
    data[at : at + len(value)] = value


def main() -> None:
    scratch = HERE / "intact.tmp.bag"
    base = intact(scratch)
    chunks = chunk_positions(base)
    infos = chunk_info_offsets(base)
    assert len(chunks) >= 3, len(chunks)
    out: dict[str, bytes] = {}

    damaged = bytearray(base)  # the second chunk's messages overwritten with garbage
    body = base.index(b"hello", chunks[1])
    damaged[body - 40 : body + 40] = bytes((i * 37 + 11) % 256 for i in range(80))
    out["garbage_in_a_chunk.bag"] = bytes(damaged)

    far = bytearray(base)  # a chunk info starting in 2106 (rosbags reads it as 2^63 - 1 ...)
    set_field(far, infos[0], b"start_time", struct.pack("<II", 0xFFFFFFFF, 0))
    out["chunk_start_2106.bag"] = bytes(far)

    zero = bytearray(base)  # ... or at 0: a player waiting from 1970 on would never start
    set_field(zero, infos[1], b"start_time", struct.pack("<II", 0, 0))
    out["chunk_start_1970.bag"] = bytes(zero)

    long_record = bytearray(base)  # the first chunk's header length past the end of the file
    long_record[chunks[0] : chunks[0] + 4] = struct.pack("<I", 0x7FFFFFF0)
    out["record_length_past_the_end.bag"] = bytes(long_record)

    huge = bytearray(base)  # a chunk claiming 4 GiB once decompressed
    set_field(huge, chunks[2], b"size", struct.pack("<I", 0xFFFFFFF0))
    out["chunk_claims_4_gib.bag"] = bytes(huge)

    counts = bytearray(base)  # a header counting four billion connections
    set_field(counts, 0, b"conn_count", struct.pack("<I", 0xFFFFFFFF))
    out["header_counts_4e9_connections.bag"] = bytes(counts)

    out["cut_in_half.bag"] = base[: len(base) // 2]

    bz2 = bytearray(intact(scratch, "bz2", chunk_size=600))
    bz2_chunks = chunk_positions(bytes(bz2))
    middle = bz2_chunks[1] + 120
    bz2[middle : middle + 16] = b"\x00" * 16
    out["bz2_chunk_damaged.bag"] = bytes(bz2)

    lz4 = bytearray(intact(scratch, "lz4", chunk_size=600))
    lz4_chunks = chunk_positions(bytes(lz4))
    middle = lz4_chunks[1] + 120
    lz4[middle : middle + 16] = b"\xff" * 16
    out["lz4_chunk_damaged.bag"] = bytes(lz4)

    foreign = bytearray(base)  # a type workbench lacks, with a definition that is not one
    for at in range(len(foreign)):
        at = foreign.find(b"type=std_msgs/String", at)
        if at == -1:
            break
        foreign[at : at + 20] = b"type=xx_msgs/Strange"
    for at in range(len(foreign)):
        at = foreign.find(b"message_definition=string data", at)
        if at == -1:
            break
        foreign[at + 19 : at + 30] = b"in@lid )(%!"
    out["unknown_type_bad_definition.bag"] = bytes(foreign)

    flipped = bytearray(base)  # a message's string length flipped: the bytes do not decode
    at = base.index(b"hello 3") - 4
    flipped[at : at + 4] = struct.pack("<I", 0x7FFFFFFF)
    out["message_does_not_decode.bag"] = bytes(flipped)

    scratch.unlink()
    for name, data in out.items():
        (HERE / name).write_bytes(data)
        print(f"wrote {name} ({len(data)} bytes)")


if __name__ == "__main__":
    main()
