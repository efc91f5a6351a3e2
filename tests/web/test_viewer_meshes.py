"""The viewer draws .obj models: the real simulator serves the stop sign's and S4blue's triangles
at their scene-message URLs, and headless Chromium draws them where the physics bodies are."""

import json
import sys
import urllib.error
import urllib.request
from pathlib import Path

import numpy as np
import pytest
from browser import open_viewer

from eyesim.physics.meshes import read_obj
from eyesim.protocol.channel_schema import mesh_body_validator

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from support.corpus import CORPUS  # noqa: E402
from support.programs import simulator_with_viewer  # noqa: E402
from support.rooms import write_scene  # noqa: E402

pytestmark = pytest.mark.browser

STOP_SIGN = CORPUS / "NoahWMueller__Eyesim/Sims/Objects/StopSign/stopsign.esObj"
S4BLUE = CORPUS / "NoahWMueller__Eyesim/Sims/Updated_Robots/S4blue.robi"


def fetch(url: str):
    with urllib.request.urlopen(url, timeout=30) as response:
        return json.loads(response.read())


def placed_box(mesh: dict, pose: dict) -> tuple[np.ndarray, np.ndarray]:
    """The bounding box (world, m) of a mesh message's body-frame vertices at a snapshot pose."""
    w, x, y, z = pose["quat"]
    rotation = np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )
    points = np.concatenate([np.reshape(p["vertices"], (-1, 3)) for p in mesh["parts"]]) @ rotation.T + pose["pos"]
    return points.min(axis=0), points.max(axis=0)


def test_the_viewer_draws_the_models_where_the_bodies_are(browser_context, tmp_path):
    scene = write_scene(
        tmp_path,
        ["floor 2000 2000"],
        ["S4blue 500 1000 30", "StopSign 1000 1000 0"],
        extra=[f'obj "{STOP_SIGN}"', f'robi "{S4BLUE}"'],
    )
    with simulator_with_viewer(str(scene), cwd=tmp_path) as (_, url):
        base = url.rstrip("/")
        viewer = open_viewer(browser_context, url)
        page = viewer.page
        page.wait_for_function("() => window.eyesimViewer.meshesDrawn() === 2")

        sign = fetch(f"{base}/scene/mesh/object/1")
        assert len(sign["parts"]) == 3
        assert sorted(tuple(p["color"]) for p in sign["parts"]) == [(190, 200, 212), (204, 204, 204), (209, 218, 211)]
        robot = fetch(f"{base}/scene/mesh/robot/1")
        in_file = sum(len(p.triangles) for p in read_obj(S4BLUE.with_suffix(".obj")).parts)
        assert sum(len(p["triangles"]) for p in robot["parts"]) == 3 * in_file  # every triangle
        for body in (sign, robot):  # as interface/viewer.schema.json describes the route
            assert [error.message for error in mesh_body_validator().iter_errors(body)] == []
        for missing in ("object/2", "robot/0", "robot/x", "wall/1"):
            with pytest.raises(urllib.error.HTTPError) as error:
                urllib.request.urlopen(f"{base}/scene/mesh/{missing}", timeout=30)
            assert error.value.code == 404

        # the robot stands still and the sign has settled: what is drawn matches the physics pose
        page.wait_for_function("() => window.eyesimViewer.objectPose(1)?.time >= 1.5")
        for kind, mesh, pose_of in (("object", sign, "objectPose"), ("robot", robot, "robotPose")):
            pose = viewer.state(pose_of, 1)
            low, high = placed_box(mesh, pose)
            drawn = viewer.state("meshBox", kind, 1)
            assert np.allclose(drawn["min"], low, atol=0.002), (kind, drawn, low)
            assert np.allclose(drawn["max"], high, atol=0.002), (kind, drawn, high)
        assert viewer.state("meshBox", "object", 2) is None
        assert viewer.errors == []
