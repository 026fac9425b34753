"""The frame decoder: frames split across reads, garbage, resets mid-frame, damage of every kind.

Frames here are written out by hand (``_frame`` below follows the wire format of
rosserial's ``node_handle.h``), not with workbench's encoder, except where the
encoder itself is checked against them.
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest
from fuzz_helpers import fuzz_runs, fuzz_seed, report

from workbench.serial import framing
from workbench.serial.framing import Frame, FrameDecoder, FrameProblem
from workbench.serial.protocol import REQUEST_TOPICS, TX_STOP, encode_frame

BENCHMARKS = Path(__file__).resolve().parents[2] / "benchmarks"

#: "hello world!" as std_msgs/String on topic 125, byte by byte.
HELLO = bytes.fromhex("ff fe 10 00 ef 7d 00 0c 00 00 00") + b"hello world!" + bytes([0xF9])
TIME_REQUEST = bytes.fromhex("ff fe 00 00 ff 0a 00 f5")


def _frame(topic: int, payload: bytes) -> bytes:
    size = len(payload)
    body = bytes([topic & 0xFF, topic >> 8]) + payload
    return (
        bytes([0xFF, 0xFE, size & 0xFF, size >> 8, 255 - ((size & 0xFF) + (size >> 8)) % 256])
        + body
        + bytes([255 - sum(body) % 256])
    )


def _decode(*chunks: bytes, max_length: int = 0xFFFF) -> list:
    decoder = FrameDecoder(max_length)
    events = []
    for chunk in chunks:
        events += decoder.feed(chunk)
    return events + decoder.flush()


def _frames(events) -> list[tuple[int, bytes]]:
    return [(e.topic_id, e.payload) for e in events if isinstance(e, Frame)]


def _kinds(events) -> list[str]:
    return [e.kind for e in events if isinstance(e, FrameProblem)]


def test_encoder_writes_the_hand_written_bytes():
    assert _frame(125, b"\x0c\x00\x00\x00hello world!") == HELLO
    assert encode_frame(125, b"\x0c\x00\x00\x00hello world!") == HELLO
    assert encode_frame(10) == TIME_REQUEST
    assert bytes.fromhex("ff fe 00 00 ff 00 00 ff") == REQUEST_TOPICS
    assert bytes.fromhex("ff fe 00 00 ff 0b 00 f4") == TX_STOP


def test_a_frame_split_at_every_byte_is_decoded_once():
    stream = HELLO + TIME_REQUEST
    for cut in range(1, len(stream)):
        events = _decode(stream[:cut], stream[cut:])
        assert _frames(events) == [(125, HELLO[7:-1]), (10, b"")], cut
        assert _kinds(events) == []
    one_by_one = _decode(*(bytes([b]) for b in stream))
    assert _frames(one_by_one) == [(125, HELLO[7:-1]), (10, b"")]


def test_garbage_between_frames_is_skipped_and_reported_as_noise():
    events = _decode(b"\x00abc" + HELLO + b"\x01\x02" + TIME_REQUEST)
    assert _frames(events) == [(125, HELLO[7:-1]), (10, b"")]
    noise = [e for e in events if isinstance(e, FrameProblem)]
    assert [(e.kind, e.offset, e.length) for e in noise] == [
        ("noise", 0, 4),
        ("noise", 4 + len(HELLO), 2),
    ]


def test_a_device_reset_mid_frame_loses_only_that_frame():
    # the board restarts after 9 bytes of a frame and then sends two whole ones
    stream = HELLO[:9] + TIME_REQUEST + HELLO
    events = _decode(stream)
    assert _frames(events) == [(10, b""), (125, HELLO[7:-1])]
    assert _kinds(events)[0] in (framing.MESSAGE_CHECKSUM, framing.OVERLAP)


def test_a_frame_cut_at_the_end_is_reported_truncated_on_flush():
    decoder = FrameDecoder()
    assert decoder.feed(HELLO[:10]) == []
    assert decoder.pending == 10
    [problem] = decoder.flush()
    assert (problem.kind, problem.offset, problem.length) == (framing.TRUNCATED, 0, 16)
    assert decoder.pending == 0


def test_wrong_checksums_and_versions_are_reported_and_the_next_frame_comes_through():
    bad_length = bytearray(HELLO)
    bad_length[4] ^= 0x01
    bad_sum = bytearray(HELLO)
    bad_sum[-1] ^= 0x01
    rev0 = bytes.fromhex("ff ff 00 00 ff 0a 00 f5")
    future = bytes.fromhex("ff fd 00 00 ff 0a 00 f5")
    events = _decode(bytes(bad_length) + HELLO + bytes(bad_sum) + rev0 + future + TIME_REQUEST)
    assert _frames(events) == [(125, HELLO[7:-1]), (10, b"")]
    problems = [(e.kind, e.detail) for e in events if isinstance(e, FrameProblem)]
    problems = [p for p in problems if p[0] != framing.NOISE]
    assert problems[:2] == [(framing.LENGTH_CHECKSUM, 0), (framing.MESSAGE_CHECKSUM, 125)]
    versions = [detail for kind, detail in problems if kind == framing.VERSION]
    # a Rev 0 frame's two 0xff bytes are reported once; the later 0xff of each bad frame
    # (its length checksum) is a sync byte followed by a wrong version as well
    assert versions == [0xFF, 0x0A, 0xFD, 0x0A]


def test_a_length_beyond_the_device_buffer_is_dropped_without_waiting_for_it():
    lying = bytes.fromhex("ff fe 00 80 7f 7d 00")  # claims 32768 bytes, length checksum right
    decoder = FrameDecoder(max_length=272)
    events = decoder.feed(lying + HELLO)
    assert _kinds(events)[0] == framing.TOO_LONG
    assert _frames(events) == [(125, HELLO[7:-1])]


def test_a_checksum_passing_by_chance_does_not_swallow_the_frame_inside_it():
    # A truncated header claims 20 bytes; the frame that follows completes them and the
    # byte after makes the outer checksum pass: the inner, valid frame wins.
    head = bytes.fromhex("ff fe 14 00 eb 2a 00")
    inner = TIME_REQUEST
    filler = b"\x01" * (20 - len(inner))
    outer_sum = 255 - sum(head[5:] + inner + filler) % 256
    stream = head + inner + filler + bytes([outer_sum])
    events = _decode(stream)
    assert _frames(events) == [(10, b"")]
    assert _kinds(events)[0] == framing.OVERLAP


def test_chunking_never_changes_the_outcome():
    stream = b"xx" + HELLO[:12] + HELLO + b"\xff\xff" + TIME_REQUEST + HELLO[:5]
    whole = _decode(stream)
    for size in (1, 2, 3, 7, 13):
        chunks = [stream[i : i + size] for i in range(0, len(stream), size)]
        assert _decode(*chunks) == whole, size


@pytest.fixture(scope="module")
def fuzz():
    sys.path.insert(0, str(BENCHMARKS))
    try:
        spec = importlib.util.spec_from_file_location(
            "bench_serial_fuzz", BENCHMARKS / "serial_fuzz.py"
        )
        assert spec is not None and spec.loader is not None
        module = importlib.util.module_from_spec(spec)
        sys.modules[spec.name] = module  # its dataclasses look their module up
        spec.loader.exec_module(module)
        yield module
    finally:
        sys.modules.pop("bench_serial_fuzz", None)
        sys.path.remove(str(BENCHMARKS))


def test_seeded_fuzz_delivers_every_valid_frame_once_and_reports_the_damage(fuzz):
    runs = fuzz_runs(300)
    result = fuzz.fuzz(runs, seed=fuzz_seed(1000))
    assert result.crashes == 0
    assert result.wrong_streams == []
    assert result.delivered_once == result.valid_frames > 2000
    assert result.silently_dropped == 0
    assert result.spurious_frames == 0
    # what passes by chance is about 1/256 of the damage, never more than a few
    assert result.reported + result.passed_by_chance == result.damaged_frames
    assert result.passed_by_chance <= result.damaged_frames // 64
    report(
        "rosserial framing",
        runs,
        valid_frames=result.valid_frames,
        damaged_frames=result.damaged_frames,
        reported=result.reported,
        passed_by_chance=result.passed_by_chance,
    )


def test_the_fuzz_check_catches_a_decoder_that_drops_frames(fuzz, monkeypatch):
    original = FrameDecoder.feed

    def lossy(self, data):
        return [e for e in original(self, data) if not (isinstance(e, Frame) and e.topic_id == 10)]

    monkeypatch.setattr(FrameDecoder, "feed", lossy)
    result = fuzz.fuzz(20, seed=1000)
    assert result.wrong_streams


def test_a_frame_ending_in_0xff_waits_for_the_next_byte_or_settle():
    text = next("x" * k for k in range(256) if _frame(125, _string("x" * k))[-1] == 0xFF)
    ending_in_ff = _frame(125, _string(text))
    decoder = FrameDecoder()
    assert decoder.feed(ending_in_ff) == []  # held: its 0xff might start another frame
    assert decoder.pending == len(ending_in_ff)
    [held] = decoder.settle()  # the line went quiet: it was a frame
    assert (held.topic_id, held.payload) == (125, _string(text))
    assert decoder.feed(HELLO[:5]) == [] and decoder.settle() == []
    assert decoder.pending == 5  # a frame still arriving is kept, not given up
    assert _frames(decoder.feed(HELLO[5:])) == [(125, HELLO[7:-1])]
    # the byte after it, when already there, decides at once
    assert _frames(FrameDecoder().feed(ending_in_ff + HELLO[:1])) == [(125, _string(text))]
    # a device reads the host's frames without waiting
    assert _frames(FrameDecoder(patient=False).feed(bytes.fromhex("ff fe 00 00 ff 00 00 ff"))) == [
        (0, b"")
    ]


def _string(text: str) -> bytes:
    return len(text).to_bytes(4, "little") + text.encode()
