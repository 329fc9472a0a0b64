"""The staging journal of a run being written: one checksummed frame per finished point.

A frame is ``MAGIC``, the header length [bytes] (uint32), the body length [bytes] (uint64) and the
CRC-32 of header and body (uint32), then the header - UTF-8 JSON with the point's index, its
scalars with their units, its counters and its channels' metadata - and the body, the channels'
samples as little-endian float64 one channel after the other. JSON writes a float as its
shortest repr, which reads back to the same double, so a frame holds a point exactly.

A frame is appended with one ``write`` call; a process killed in the middle leaves at most a
torn last frame, which :func:`scan` recognises (short or with a wrong checksum) and cuts off, so
a point is in the journal exactly when its frame is complete.
"""

from __future__ import annotations

import json
import struct
import zlib
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from rig.logbook.content import Channel, Counter, CounterReadings, PointRecord, Quantity

MAGIC = b"RIGP"
_PREFIX = struct.Struct("<4sIQI")  # magic, header length, body length, crc32
SAMPLE_DTYPE = np.dtype("<f8")


@dataclass(frozen=True)
class Entry:
    """One point as the journal and the columnar log see it: ``header`` (JSON-able) and channels."""

    header: dict
    channels: dict[str, np.ndarray]

    @property
    def index(self) -> int:
        return int(self.header["index"])


def _rows(values: Mapping[str, Quantity]) -> list[list]:
    return [[name, q.value, q.unit] for name, q in values.items()]


def entry_of(point: PointRecord, truth: Mapping[str, Quantity]) -> Entry:
    """The journal entry of a complete point and its truth."""
    counters = None
    if point.counters is not None:
        counters = {"gate_time_s": point.counters.gate_time_s,
                    "counters": [[n, c.count, c.marks_per_rev] for n, c in point.counters.counters.items()]}
    header = {
        "index": point.index,
        "settings": _rows(point.settings),
        "readings": _rows(point.readings),
        "calibration": [[rec, name, q.value, q.unit] for rec, fields in point.calibration.items()
                        for name, q in fields.items()],
        "records": list(point.calibration),
        "truth": _rows(truth),
        "counters": counters,
        "channels": [[name, ch.unit, ch.sample_rate_Hz, ch.start_time_s, int(ch.samples.size)]
                     for name, ch in point.channels.items()],
    }
    return Entry(header, {name: ch.samples for name, ch in point.channels.items()})


def record_of(entry: Entry) -> tuple[PointRecord, dict[str, Quantity]]:
    """The PointRecord and truth of an entry (checked again by the content classes)."""
    h = entry.header
    calibration: dict[str, dict[str, Quantity]] = {rec: {} for rec in h["records"]}
    for rec, name, value, unit in h["calibration"]:
        calibration.setdefault(rec, {})[name] = Quantity(value, unit)
    counters = None
    if h["counters"] is not None:
        counters = CounterReadings(h["counters"]["gate_time_s"],
                                   {n: Counter(c, m) for n, c, m in h["counters"]["counters"]})
    channels = {name: Channel(entry.channels[name], unit, rate, start) for name, unit, rate, start, _ in h["channels"]}
    point = PointRecord(h["index"], {n: Quantity(v, u) for n, v, u in h["settings"]}, channels, counters,
                        {n: Quantity(v, u) for n, v, u in h["readings"]}, calibration)
    return point, {n: Quantity(v, u) for n, v, u in h["truth"]}


def encode(entry: Entry) -> bytes:
    """The frame of ``entry``."""
    header = json.dumps(entry.header, separators=(",", ":")).encode()
    body = b"".join(np.ascontiguousarray(entry.channels[c[0]], dtype=SAMPLE_DTYPE).tobytes()
                    for c in entry.header["channels"])
    crc = zlib.crc32(body, zlib.crc32(header))
    return _PREFIX.pack(MAGIC, len(header), len(body), crc) + header + body


@dataclass(frozen=True)
class Frame:
    """Where a complete frame lies in the journal: byte offset and total length, and its index."""

    index: int
    offset: int
    length: int


def _parse(data: bytes) -> Entry:
    _, header_len, _, _ = _PREFIX.unpack_from(data)
    header = json.loads(data[_PREFIX.size:_PREFIX.size + header_len])
    body = np.frombuffer(data, dtype=SAMPLE_DTYPE, offset=_PREFIX.size + header_len)
    channels, at = {}, 0
    for name, _, _, _, n in header["channels"]:
        channels[name] = body[at:at + n]
        at += n
    return Entry(header, channels)


def scan(path: Path) -> tuple[list[Frame], int]:
    """The complete frames of the journal ``path`` and the byte length they span (the rest, a
    torn last frame of a killed writer, is to be cut off). Frames after a damaged one are not
    trusted either: the journal is valid up to its first bad frame."""
    frames, end = [], 0
    with open(path, "rb") as handle:
        while True:
            prefix = handle.read(_PREFIX.size)
            if len(prefix) < _PREFIX.size:
                break
            magic, header_len, body_len, crc = _PREFIX.unpack(prefix)
            if magic != MAGIC:
                break
            rest = handle.read(header_len + body_len)
            if len(rest) < header_len + body_len or zlib.crc32(rest) != crc:
                break
            try:
                index = int(json.loads(rest[:header_len])["index"])
            except (ValueError, KeyError, TypeError):
                break
            frames.append(Frame(index, end, _PREFIX.size + header_len + body_len))
            end += frames[-1].length
    return frames, end


def read_frame(handle, frame: Frame) -> Entry:
    """The entry stored in ``frame`` of the open journal ``handle`` (binary)."""
    handle.seek(frame.offset)
    return _parse(handle.read(frame.length))
