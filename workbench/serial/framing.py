"""Turning a rosserial byte stream into frames, whatever the stream does.

:class:`FrameDecoder` takes bytes as they come (a frame may be split across any
number of reads, several frames may come in one) and returns, in stream order,
the frames it found (:class:`Frame`) and what it dropped (:class:`FrameProblem`).
It never raises on input and never loses a frame to a neighbour's damage:

* bytes before a sync byte are skipped and reported as noise;
* a wrong version byte, a wrong length checksum, a length above ``max_length`` or a
  wrong message checksum drops that candidate only: scanning resumes at the byte after
  its sync byte, so a frame that starts inside a damaged one (a device that reset
  mid-frame, a truncated frame followed by the next) is still found; what that second
  look finds wrong inside bytes already reported is not reported again;
* a candidate whose checksum passes by chance (one in 256 for random bytes) but which
  contains the start of another complete, valid frame is not a frame: real frames
  never overlap, so the inner one wins;
* a candidate still waiting for bytes is held until they come or :meth:`flush` says
  no more will (end of stream, or the line went quiet); then it is reported as
  truncated and scanning resumes inside it; a complete frame held only to see the byte
  after it is decided by :meth:`settle` as soon as the line is quiet.

Problems carry the stream offset of their first byte, so a caller (or the fuzz in
``benchmarks/serial.py``) can tell which damaged frame each one stands for.
"""

from __future__ import annotations

from dataclasses import dataclass

from workbench.serial.protocol import (
    FRAME_OVERHEAD,
    HEADER_SIZE,
    MAX_PAYLOAD,
    PROTOCOL_VER,
    PROTOCOL_VER1,
    SYNC,
)

_START = bytes((SYNC, PROTOCOL_VER))

# Kinds of FrameProblem.
NOISE = "noise"
VERSION = "version"
LENGTH_CHECKSUM = "length_checksum"
TOO_LONG = "too_long"
MESSAGE_CHECKSUM = "message_checksum"
OVERLAP = "overlap"
TRUNCATED = "truncated"


@dataclass(frozen=True)
class Frame:
    """One valid frame.

    Attributes:
        topic_id: The frame's topic id.
        payload: The serialized message.
        offset: Stream offset of its sync byte (bytes fed before it).
    """

    topic_id: int
    payload: bytes
    offset: int


@dataclass(frozen=True)
class FrameProblem:
    """Bytes the decoder dropped, and why.

    Attributes:
        kind: ``noise`` (bytes outside any frame), ``version`` (a sync byte followed by
            another version than Rev 1), ``length_checksum``, ``too_long`` (a length above
            the decoder's ``max_length``), ``message_checksum``, ``overlap`` (a checksum
            that passed by chance over the start of another valid frame) or ``truncated``
            (the stream ended, or went quiet, inside a frame).
        offset: Stream offset of the first byte concerned.
        length: The payload length the frame claimed (for ``noise``: the bytes skipped).
        detail: The version byte (``version``) or the topic id (``message_checksum``,
            ``overlap``), else 0.
    """

    kind: str
    offset: int
    length: int = 0
    detail: int = 0


Event = Frame | FrameProblem


class FrameDecoder:
    """Incremental rosserial Rev 1 frame decoder with resynchronisation.

    Args:
        max_length: Longest payload accepted, in bytes (a device cannot send more than
            its buffer holds); longer claims are dropped as ``too_long`` at once
            instead of waiting for that many bytes.
        patient: A frame whose checksum byte is 0xff and ends what has arrived waits
            for the next byte (or :meth:`flush`), since that 0xff may start a frame the
            candidate overlaps. The host is patient (its input can be damaged; about one
            frame in 256 waits, until the next byte or the line goes quiet); a device
            reading only the host's well-formed frames need not be, and is not kept
            waiting by the topic request (``ff fe 00 00 ff 00 00 ff``).
    """

    def __init__(self, max_length: int = MAX_PAYLOAD, patient: bool = True) -> None:
        self.max_length = max_length
        self.patient = patient
        self._buf = bytearray()
        self._pos = 0  # where scanning resumes, in _buf
        self._base = 0  # stream offset of _buf[0]
        self._covered = 0  # stream offset up to which bytes belong to a reported problem
        self._quiet_version_at = -1  # stream offset whose version problem is not repeated
        self._noise_start = -1  # stream offset of the current run of noise, or -1
        self._noise_count = 0
        #: Candidates dropped inside bytes already reported, so not reported again.
        self.quiet_problems = 0
        self._settling = False

    @property
    def pending(self) -> int:
        """Bytes held back: the start of a frame still waiting for the rest."""
        return len(self._buf) - self._pos

    def feed(self, data: bytes | bytearray | memoryview) -> list[Event]:
        """Add bytes; return the frames and problems now decided, in stream order."""
        events: list[Event] = []
        if data:
            self._buf += data
            self._scan(events, final=False)
            self._compact()
        return events

    def flush(self) -> list[Event]:
        """Decide everything held back as if no more bytes will come; empties the decoder."""
        events: list[Event] = []
        self._scan(events, final=True)
        self._end_noise(events)
        self._base += len(self._buf)
        self._buf.clear()
        self._pos = 0
        return events

    def settle(self) -> list[Event]:
        """Decide a complete frame held back only for the bytes after it, as if none follow.

        A frame still missing bytes of its own stays held (unlike :meth:`flush`). The host
        calls this once the line has been quiet for a moment.
        """
        events: list[Event] = []
        self._settling = True
        try:
            self._scan(events, final=False)
        finally:
            self._settling = False
        self._compact()
        return events

    def reset(self) -> None:
        """Forget every byte held (after the port was reopened)."""
        self._base += len(self._buf)
        self._buf.clear()
        self._pos = 0
        self._noise_start, self._noise_count = -1, 0

    # --- scanning ---------------------------------------------------------------------

    def _scan(self, events: list[Event], final: bool) -> None:
        buf = self._buf
        n = len(buf)
        base = self._base
        while True:
            pos = self._pos
            i = buf.find(SYNC, pos)
            if i < 0:
                self._skip(pos, n)
                self._pos = n
                return
            if i > pos:
                self._skip(pos, i)
            if n - i < 2:
                if not final:
                    self._pos = i
                    return
                self._problem(events, TRUNCATED, i, i + 1)
                continue
            version = buf[i + 1]
            if version != PROTOCOL_VER:
                if base + i != self._quiet_version_at:
                    self._problem(events, VERSION, i, i + 2, detail=version)
                else:
                    self._pos = i + 1
                if version == PROTOCOL_VER1:
                    # Rev 0's second 0xff may be a sync byte: look at it again, but a
                    # Rev 0 frame is reported once, not twice.
                    self._quiet_version_at = base + i + 1
                continue
            if n - i < HEADER_SIZE:
                if not final:
                    self._pos = i
                    return
                self._problem(events, TRUNCATED, i, n)
                continue
            length = buf[i + 2] | (buf[i + 3] << 8)
            if (buf[i + 2] + buf[i + 3] + buf[i + 4]) & 0xFF != 0xFF:
                self._problem(events, LENGTH_CHECKSUM, i, i + 5, length)
                continue
            if length > self.max_length:
                self._problem(events, TOO_LONG, i, i + 5, length)
                continue
            end = i + FRAME_OVERHEAD + length
            if end > n:
                if not final:
                    self._pos = i
                    return
                self._problem(events, TRUNCATED, i, n, length)
                continue
            topic_id = buf[i + 5] | (buf[i + 6] << 8)
            if sum(buf[i + 5 : end]) & 0xFF != 0xFF:
                self._problem(events, MESSAGE_CHECKSUM, i, end, length, topic_id)
                continue
            inner = self._inner_frame(i, end, final)
            if inner is None:  # wait for the bytes that decide it
                self._pos = i
                return
            if inner:
                self._problem(events, OVERLAP, i, end, length, topic_id)
                continue
            self._end_noise(events)
            events.append(Frame(topic_id, bytes(buf[i + HEADER_SIZE : end - 1]), base + i))
            self._covered = max(self._covered, base + end)
            self._pos = end

    def _inner_frame(self, start: int, end: int, final: bool) -> bool | None:
        """Whether a complete valid frame starts inside ``buf[start:end]`` (None: not known yet)."""
        buf = self._buf
        n = len(buf)
        final = final or self._settling
        if self.patient and n == end and buf[end - 1] == SYNC and not final:
            return None  # the checksum byte may be the sync byte of an overlapping frame
        j = buf.find(_START, start + 1, end + 1)
        while j >= 0:
            if n - j < HEADER_SIZE:
                if not final:
                    return None
            elif (buf[j + 2] + buf[j + 3] + buf[j + 4]) & 0xFF == 0xFF:
                length = buf[j + 2] | (buf[j + 3] << 8)
                inner_end = j + FRAME_OVERHEAD + length
                if length <= self.max_length:
                    if inner_end > n:
                        if not final:
                            return None
                    elif sum(buf[j + 5 : inner_end]) & 0xFF == 0xFF:
                        return True
            j = buf.find(_START, j + 1, end + 1)
        return False

    def _problem(
        self,
        events: list[Event],
        kind: str,
        i: int,
        span_end: int,
        length: int = 0,
        detail: int = 0,
    ) -> None:
        """Report the candidate at ``i`` (covering ``buf[i:span_end]``); resume after its sync.

        A candidate that starts inside bytes already reported (a sync byte in the payload
        of a damaged frame, scanned again) is the same damage: it is counted, not reported.
        """
        self._pos = i + 1
        if self._base + i < self._covered:
            self.quiet_problems += 1
            return
        self._end_noise(events)
        events.append(FrameProblem(kind, self._base + i, length, detail))
        self._covered = self._base + span_end

    def _skip(self, start: int, stop: int) -> None:
        """Bytes ``buf[start:stop]`` hold no sync byte: count those no problem covered as noise."""
        first = max(self._base + start, self._covered)
        last = self._base + stop
        if last <= first:
            return
        if self._noise_start < 0:
            self._noise_start = first
        self._noise_count += last - first

    def _end_noise(self, events: list[Event]) -> None:
        if self._noise_count:
            events.append(FrameProblem(NOISE, self._noise_start, self._noise_count))
        self._noise_start, self._noise_count = -1, 0

    def _compact(self) -> None:
        if self._pos:
            del self._buf[: self._pos]
            self._base += self._pos
            self._pos = 0
