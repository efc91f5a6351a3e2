"""How long a WAV or MP3 file plays, read from its headers (AUPlay reports it; the viewer plays the bytes)."""

from __future__ import annotations

import itertools
import re
import struct

# MPEG audio frame headers: bit rates in kbit/s by (MPEG-1?, layer) and index 1..14.
_BITRATES = {
    (True, 1): (32, 64, 96, 128, 160, 192, 224, 256, 288, 320, 352, 384, 416, 448),
    (True, 2): (32, 48, 56, 64, 80, 96, 112, 128, 160, 192, 224, 256, 320, 384),
    (True, 3): (32, 40, 48, 56, 64, 80, 96, 112, 128, 160, 192, 224, 256, 320),
    (False, 1): (32, 48, 56, 64, 80, 96, 112, 128, 144, 160, 176, 192, 224, 256),
    (False, 2): (8, 16, 24, 32, 40, 48, 56, 64, 80, 96, 112, 128, 144, 160),
    (False, 3): (8, 16, 24, 32, 40, 48, 56, 64, 80, 96, 112, 128, 144, 160),
}
_SAMPLE_RATES = {3: (44100, 48000, 32000), 2: (22050, 24000, 16000), 0: (11025, 12000, 8000)}  # by version bits
# Where a frame header may start: 11 sync bits, a version that exists and a layer that exists.
_SYNC = re.compile(rb"\xff(?=[\xe2-\xe7\xf2-\xf7\xfa-\xff])")
# Bytes after the ID3 tag searched for the first frame: real files start at once or after a little
# padding; searching a whole file of anything else cost seconds of the simulation thread.
FIRST_FRAME_WITHIN = 64 * 1024
CANDIDATES = 512  # of those places that look like a frame header: 32 768 in 64 KiB of b"\xff\xfe" cost 20-70 ms
# Frames walked one by one; a longer file's rest is timed at the average rate of those (exact at a
# constant bit rate). Walking 8 MB of the smallest frames cost 250 ms of the simulation thread.
FRAMES_WALKED = 2048
WAV_CHUNKS = 64  # chunks looked at for 'fmt ' and 'data' (real files have a handful)


class SoundError(ValueError):
    pass


def sound_length(data: bytes) -> tuple[str, float]:
    """('wav' or 'mp3', seconds of playing time) of a sound file's contents."""
    if data[:4] == b"RIFF" and data[8:12] == b"WAVE":
        return "wav", _wav_seconds(data)
    seconds = _mp3_seconds(data)
    if seconds is None:
        raise SoundError("not a WAV or MP3 file")
    return "mp3", seconds


def _wav_seconds(data: bytes) -> float:
    offset, byte_rate, data_size = 12, None, None
    for _ in range(WAV_CHUNKS):
        if offset + 8 > len(data) or (byte_rate and data_size is not None):
            break
        chunk, size = data[offset : offset + 4], struct.unpack_from("<I", data, offset + 4)[0]
        if chunk == b"fmt " and size >= 16:
            byte_rate = struct.unpack_from("<I", data, offset + 16)[0]
        elif chunk == b"data":
            data_size = min(size, len(data) - offset - 8)  # a truncated file plays what it has
        offset += 8 + size + (size & 1)
    if not byte_rate or data_size is None:
        raise SoundError("a WAV file without a usable 'fmt ' or 'data' chunk")
    return data_size / byte_rate


def _frame(data: bytes, offset: int) -> tuple[int, float] | None:
    """(length in bytes, seconds) of the MPEG audio frame at `offset`, or None if there is none."""
    if offset + 4 > len(data) or data[offset] != 0xFF or data[offset + 1] & 0xE0 != 0xE0:
        return None
    version, layer_bits = (data[offset + 1] >> 3) & 3, (data[offset + 1] >> 1) & 3
    bitrate_index, rate_index = data[offset + 2] >> 4, (data[offset + 2] >> 2) & 3
    padding = (data[offset + 2] >> 1) & 1
    if version == 1 or layer_bits == 0 or not 1 <= bitrate_index <= 14 or rate_index == 3:
        return None
    layer, mpeg1 = 4 - layer_bits, version == 3
    bitrate = _BITRATES[(mpeg1, layer)][bitrate_index - 1] * 1000
    rate = _SAMPLE_RATES[version][rate_index]
    if layer == 1:
        return (12 * bitrate // rate + padding) * 4, 384 / rate
    samples = 1152 if layer == 2 or mpeg1 else 576
    return samples // 8 * bitrate // rate + padding, samples / rate


def _mp3_seconds(data: bytes) -> float | None:
    offset = 0
    if data[:3] == b"ID3" and len(data) >= 10:  # an ID3v2 tag first: its size is 4 x 7 bits
        size = (data[6] & 0x7F) << 21 | (data[7] & 0x7F) << 14 | (data[8] & 0x7F) << 7 | (data[9] & 0x7F)
        offset = 10 + size + (10 if data[5] & 0x10 else 0)
    # The first frame: a header whose next frame starts with a header too (not stray sync bits).
    for candidate in itertools.islice(_SYNC.finditer(data, offset, offset + FIRST_FRAME_WITHIN + 2), CANDIDATES):
        offset = candidate.start()
        frame = _frame(data, offset)
        if frame and (offset + frame[0] >= len(data) or _frame(data, offset + frame[0])):
            break
    else:
        return None
    seconds, first = 0.0, offset
    for _ in range(FRAMES_WALKED):
        frame = _frame(data, offset)
        if frame is None or offset + frame[0] > len(data):
            return seconds
        seconds += frame[1]
        offset += frame[0]
    if _frame(data, offset) is None:
        return seconds
    return seconds * (len(data) - first) / (offset - first)  # the rest at the walked frames' rate
