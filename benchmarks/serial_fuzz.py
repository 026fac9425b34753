"""Seeded random rosserial byte streams, and the check that decodes them (used by serial.py).

A stream mixes valid frames with noise and damaged frames: one flipped bit
(anywhere, the sync byte included), a frame cut short (a device reset mid-frame),
a wrong final checksum, a bogus length (0..65535, with a length checksum that
matches it) and a wrong version byte. The stream is fed to a
:class:`~workbench.serial.framing.FrameDecoder` in random chunks (1..64 bytes),
then flushed. The check:

* no exception escapes (a crash is counted, with its stream);
* the frames delivered are exactly the valid frames, in order, each once;
* every damaged frame is either reported (a problem overlaps its bytes) or, when its
  damage left bytes whose two 8-bit checksums pass by chance, delivered as (part of) a
  frame; this happens with probability about 1/256 per damaged frame whose claimed
  extent holds no valid frame, and is inherent to rosserial's format. Such a frame
  never hides a valid one (the decoder prefers the valid frame that starts inside it);
* no frame is delivered that is neither valid nor damaged (``spurious``).
"""

from __future__ import annotations

import random
from dataclasses import dataclass, field

from workbench.serial.framing import Frame, FrameDecoder, FrameProblem
from workbench.serial.protocol import encode_frame

#: The device buffer the fuzz decoder assumes (an Arduino's default ros_lib: 512 bytes).
DEVICE_BUFFER = 512
MAX_PAYLOAD = DEVICE_BUFFER - 8
DAMAGE = ("flip", "truncate", "checksum", "length", "version")


@dataclass
class Stream:
    """One generated stream and what it holds."""

    data: bytes = b""
    valid: list[tuple[int, int, bytes]] = field(default_factory=list)  # (offset, id, payload)
    damaged: list[tuple[str, int, int]] = field(default_factory=list)  # (kind, start, end)


def _frame(rng: random.Random) -> bytes:
    topic = rng.choice((0, 1, 7, 10, rng.randrange(100, 150), rng.randrange(0, 65536)))
    size = rng.choice((0, 1, 4, 16, rng.randrange(0, 64), rng.randrange(0, MAX_PAYLOAD + 1)))
    return encode_frame(topic, rng.randbytes(size))


def _damage(kind: str, frame: bytes, rng: random.Random) -> bytes:
    data = bytearray(frame)
    if kind == "flip":
        data[rng.randrange(len(data))] ^= 1 << rng.randrange(8)
    elif kind == "truncate":
        data = data[: rng.randrange(1, len(data))]
    elif kind == "checksum":
        data[-1] = (data[-1] + rng.randrange(1, 256)) & 0xFF
    elif kind == "length":
        length = rng.randrange(65536)
        while length == len(frame) - 8:
            length = rng.randrange(65536)
        lo, hi = length & 0xFF, length >> 8
        data[2:5] = bytes((lo, hi, 255 - ((lo + hi) & 0xFF)))
    else:
        data[1] = rng.choice([b for b in range(256) if b != 0xFE])
    return bytes(data)


def make_stream(seed: int, pieces: int = 24) -> Stream:
    """A stream of ``pieces`` parts: about half valid frames, a quarter noise, a quarter damage."""
    rng = random.Random(seed)
    stream = Stream()
    out = bytearray()
    for _ in range(pieces):
        roll = rng.random()
        if roll < 0.5:
            frame = _frame(rng)
            stream.valid.append((len(out), frame[5] | frame[6] << 8, frame[7:-1]))
            out += frame
        elif roll < 0.75:
            out += rng.randbytes(rng.randrange(1, 24))
        else:
            kind = rng.choice(DAMAGE)
            damaged = _damage(kind, _frame(rng), rng)
            stream.damaged.append((kind, len(out), len(out) + len(damaged)))
            out += damaged
    stream.data = bytes(out)
    return stream


@dataclass
class FuzzResult:
    """What decoding the streams gave."""

    streams: int = 0
    bytes: int = 0
    valid_frames: int = 0
    delivered_once: int = 0
    damaged_frames: int = 0
    reported: int = 0
    passed_by_chance: int = 0
    silently_dropped: int = 0
    spurious_frames: int = 0
    crashes: int = 0
    wrong_streams: list[int] = field(default_factory=list)


def decode(stream: Stream, seed: int) -> list[Frame | FrameProblem]:
    """Feed ``stream`` in random chunks (seeded) and flush; the events."""
    rng = random.Random(seed ^ 0x5EED)
    decoder = FrameDecoder(max_length=MAX_PAYLOAD)
    events: list[Frame | FrameProblem] = []
    data, at = stream.data, 0
    while at < len(data):
        step = rng.randrange(1, 65)
        events += decoder.feed(data[at : at + step])
        at += step
    return events + decoder.flush()


def check(stream: Stream, events: list[Frame | FrameProblem], result: FuzzResult) -> bool:
    """Add one stream's outcome to ``result``; True when its valid frames came exactly once."""
    frames = [e for e in events if isinstance(e, Frame)]
    problems = [e for e in events if isinstance(e, FrameProblem)]
    valid = set(stream.valid)
    delivered = [(f.offset, f.topic_id, f.payload) for f in frames]
    exact = [d for d in delivered if d in valid] == stream.valid
    result.valid_frames += len(stream.valid)
    result.delivered_once += len(stream.valid) if exact else 0
    unexpected = [(d[0], d[0] + 8 + len(d[2])) for d in delivered if d not in valid]
    for _kind, start, end in stream.damaged:
        result.damaged_frames += 1
        if any(p.offset < end and p.offset + _extent(p) > start for p in problems):
            result.reported += 1
        elif any(first < end and last > start for first, last in unexpected):
            result.passed_by_chance += 1
        else:
            result.silently_dropped += 1
    inside = [o for o, _ in unexpected if any(s <= o < e for _, s, e in stream.damaged)]
    result.spurious_frames += len(unexpected) - len(inside)
    return exact


def _extent(problem: FrameProblem) -> int:
    """How many bytes a problem stands for: the noise skipped, or the candidate frame's extent."""
    if problem.kind == "noise":
        return problem.length
    if problem.kind == "version":
        return 2
    if problem.kind in ("length_checksum", "too_long"):
        return 5
    return 8 + problem.length


def fuzz(streams: int, seed: int = 0) -> FuzzResult:
    """Generate and decode ``streams`` streams (stream ``k`` from seed ``seed + k``)."""
    result = FuzzResult()
    for k in range(streams):
        stream = make_stream(seed + k)
        result.streams += 1
        result.bytes += len(stream.data)
        try:
            events = decode(stream, seed + k)
        except Exception:  # the count the fuzz exists for
            result.crashes += 1
            result.wrong_streams.append(seed + k)
            continue
        if not check(stream, events, result):
            result.wrong_streams.append(seed + k)
    return result
