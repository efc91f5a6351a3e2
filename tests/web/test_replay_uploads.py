"""`eyesim replay` keeps only the recording it shows: a rejected upload, and one replaced by the
next, are deleted at once (they used to stay until the server exited). Its folder for uploads is
made at the first upload, so a server killed before any leaves nothing in the temporary folder."""

from __future__ import annotations

import tempfile
from pathlib import Path

import aiohttp
from support.recordings import record_tour
from support.viewer import run_async

from eyesim.record import Recording
from eyesim.web.replay_server import ReplayServer


def kept_uploads(server: ReplayServer) -> list[Path]:
    return sorted(p for p in Path(server._uploads.name).rglob("*") if p.is_file())


def test_only_the_shown_upload_is_kept(tmp_path, monkeypatch):
    tour = record_tour(tmp_path)
    temp = tmp_path / "temp"
    temp.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(temp))

    async def scenario():
        with Recording(tour) as recording:
            server = ReplayServer(recording, port=0, require_token=False)
            await server.start()
            base = f"http://127.0.0.1:{server.port}"
            assert list(temp.iterdir()) == []  # nothing to leave behind if it is killed now
            try:
                async with aiohttp.ClientSession() as client:
                    async with client.post(f"{base}/recording?name=bad.mcap", data=b"not a recording") as response:
                        assert response.status == 400
                    assert kept_uploads(server) == []
                    for name in ("first.mcap", "second.mcap"):
                        async with client.post(f"{base}/recording?name={name}", data=tour.read_bytes()) as response:
                            assert response.status == 200, await response.text()
                    assert [p.name for p in kept_uploads(server)] == ["second.mcap"]
            finally:
                await server.stop()
        assert list(temp.iterdir()) == []

    run_async(scenario())
