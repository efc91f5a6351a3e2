"""The audio group: sounds take simulation time, WAV and MP3 lengths come from the file, the viewer
gets the sound; the microphone is analog channel 8."""

import io
import struct
import time
import wave

import pytest
from support.client import RemoteError
from support.connected import connected_program

from eyesim.core import robot_input
from eyesim.robot.sound_files import FRAMES_WALKED, WAV_CHUNKS, SoundError, sound_length


def wav_bytes(seconds: float, rate: int = 8000, channels: int = 1, width: int = 2) -> bytes:
    buffer = io.BytesIO()
    with wave.open(buffer, "wb") as file:
        file.setnchannels(channels)
        file.setsampwidth(width)
        file.setframerate(rate)
        file.writeframes(bytes(round(seconds * rate) * channels * width))
    return buffer.getvalue()


def mp3_bytes(frames: int, id3: bool = True) -> bytes:
    """MPEG-1 Layer III frames at 128 kbit/s, 44.1 kHz (417 bytes + padding), silent payload."""
    data = bytearray()
    if id3:  # an ID3v2 tag of 20 bytes first, then a few stray bytes
        data += b"ID3\x04\x00\x00\x00\x00\x00\x14" + bytes(20)
    for k in range(frames):
        padding = k % 3 == 0
        data += bytes([0xFF, 0xFB, 0x90 | (0x02 if padding else 0), 0x64]) + bytes(417 + padding - 4)
    return bytes(data + b"TAG" + bytes(125))  # an ID3v1 tag at the end


class Sounds:
    wants_lcd = True  # like a viewer: it gets the sound's bytes

    def __init__(self):
        self.events = []

    def on_event(self, message):
        if message["type"] == "audio":
            self.events.append(message)

    def on_snapshot(self, message):
        pass


def test_wav_and_mp3_lengths_are_read_from_their_headers():
    assert sound_length(wav_bytes(1.5)) == ("wav", 1.5)
    assert sound_length(wav_bytes(0.25, rate=44100, channels=2)) == ("wav", 0.25)
    kind, seconds = sound_length(mp3_bytes(100))
    assert kind == "mp3" and seconds == pytest.approx(100 * 1152 / 44100)
    assert sound_length(mp3_bytes(10, id3=False))[1] == pytest.approx(10 * 1152 / 44100)
    with pytest.raises(ValueError, match="not a WAV or MP3 file"):
        sound_length(b"just some text, no sound at all")


def test_a_beep_and_a_file_play_for_their_time_and_reach_the_viewer():
    with connected_program() as (sim, client):
        sounds = Sounds()
        sim.events.subscribe(sounds)
        assert client.call("AU_DONE") == (1,)
        client.call("AU_BEEP")
        assert client.call("AU_DONE") == (0,)
        client.call("OS_WAIT", 200)
        assert client.call("AU_DONE") == (1,)
        sound = wav_bytes(0.5)
        client.call("AU_PLAY", "hello.wav", sound)
        client.call("OS_WAIT", 490)
        assert client.call("AU_DONE") == (0,)
        client.call("OS_WAIT", 10)
        assert client.call("AU_DONE") == (1,)
        beep, played = sounds.events
        assert beep == {"type": "audio", "robot": 1, "sound": "beep", "duration": 0.2, "frequency": 1000}
        assert played["name"] == "hello.wav" and played["format"] == "wav" and played["duration"] == 0.5
        assert played["data"]  # base64 of the file, for the browser to play
        with pytest.raises(RemoteError, match="notes.txt: not a WAV or MP3 file"):
            client.call("AU_PLAY", "notes.txt", b"hello")


def test_the_microphone_hears_what_analog_channel_8_is_set_to():
    with connected_program() as (sim, client):
        assert client.call("AU_MICROPHONE") == (512,)  # silence: the middle of the 10-bit range
        sim.call(lambda s: robot_input.analog(s, 1, 8, 900))
        client.call("OS_WAIT", 1)
        assert client.call("AU_MICROPHONE") == (900,)
        assert client.call("ANALOG_READ", 8) == (900,)


def test_a_long_file_is_timed_from_its_first_frames():
    """Past FRAMES_WALKED frames the rest is timed at their rate: exact at a constant bit rate,
    and 8 MB of the smallest frames no longer walked frame by frame."""
    frames = FRAMES_WALKED * 5
    assert sound_length(mp3_bytes(frames))[1] == pytest.approx(frames * 1152 / 44100, rel=1e-3)
    smallest = bytes([0xFF, 0xF3, 0x14, 0xC4]) + bytes(20)  # MPEG-2 layer III at 8 kbit/s, 24 kHz: 24 bytes
    assert sound_length(smallest * 10)[1] == pytest.approx(10 * 576 / 24000)
    assert sound_length(smallest * (FRAMES_WALKED * 3))[1] == pytest.approx(3 * FRAMES_WALKED * 576 / 24000)


def test_a_wav_file_whose_data_chunk_is_not_among_its_first_chunks_is_refused():
    padding = (b"junk" + struct.pack("<I", 2) + b"..") * WAV_CHUNKS
    wav = wav_bytes(0.5)
    assert sound_length(wav[:12] + padding[: 10 * 10] + wav[12:])[1] == 0.5
    with pytest.raises(SoundError, match="'data' chunk"):
        sound_length(wav[:12] + padding + wav[12:])


def test_a_frame_header_right_after_a_stray_sync_byte_is_found():
    assert sound_length(b"\xff" + mp3_bytes(10, id3=False))[1] == pytest.approx(10 * 1152 / 44100)


def test_sound_files_cost_little_to_measure_and_are_at_most_8_mb():
    start = time.perf_counter()
    with pytest.raises(SoundError):
        sound_length(b"\xff\xfe" * (4 << 20))  # sync bits everywhere, no frame: seconds once
    assert time.perf_counter() - start < 0.5  # about 20 ms
    with connected_program() as (sim, client):
        with pytest.raises(RemoteError, match="too large"):
            client.call("AU_PLAY", "big.mp3", mp3_bytes(1) + bytes(8 << 20))
        assert client.call("AU_DONE") == (1,)
