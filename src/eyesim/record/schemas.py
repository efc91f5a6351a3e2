"""The channels of an EyeSim recording and their JSON Schemas (docs/recording.md).

Where Foxglove has a well-known schema for the data (poses, images, laser scans, log lines) the
channel uses it, written here from Foxglove's documented field lists, so the file opens
meaningfully in Foxglove; EyeSim's own data has `eyesim.*` schemas. Every message is JSON."""

from __future__ import annotations

import json

PROFILE = ""  # no ROS profile: plain JSON channels
LIBRARY = "eyesim"

# -- topics --------------------------------------------------------------------------------------
SCENE = "/scene"
TRANSFORMS = "/tf"
RAYS = "/rays"
EVENTS = "/events"
LOG = "/log"
EDITS = "/edits"
ROBOT_CHANNELS = ("state", "lcd", "camera", "lidar", "psd", "command", "input")


def robot_topic(robot_id: int, channel: str) -> str:
    return f"/robot/{robot_id}/{channel}"


# Foxglove frame ids of the things in the world (children of WORLD_FRAME).
WORLD_FRAME = "world"


def robot_frame(robot_id: int) -> str:
    return f"robot/{robot_id}"


def object_frame(object_id: int) -> str:
    return f"object/{object_id}"


def body_frame(body_id: int) -> str:
    return f"body/{body_id}"


# -- Foxglove schemas ----------------------------------------------------------------------------
_NUMBER = {"type": "number"}
_TIME = {
    "type": "object",
    "title": "time",
    "properties": {
        "sec": {"type": "integer", "minimum": 0},
        "nsec": {"type": "integer", "minimum": 0, "maximum": 999_999_999},
    },
}
_VECTOR3 = {"type": "object", "title": "foxglove.Vector3", "properties": {"x": _NUMBER, "y": _NUMBER, "z": _NUMBER}}
_QUATERNION = {
    "type": "object",
    "title": "foxglove.Quaternion",
    "properties": {"x": _NUMBER, "y": _NUMBER, "z": _NUMBER, "w": _NUMBER},
}
_POSE = {"type": "object", "title": "foxglove.Pose", "properties": {"position": _VECTOR3, "orientation": _QUATERNION}}
_FRAME_TRANSFORM = {
    "type": "object",
    "title": "foxglove.FrameTransform",
    "properties": {
        "timestamp": _TIME,
        "parent_frame_id": {"type": "string"},
        "child_frame_id": {"type": "string"},
        "translation": _VECTOR3,
        "rotation": _QUATERNION,
    },
}

FOXGLOVE = {
    "foxglove.FrameTransforms": {
        "type": "object",
        "title": "foxglove.FrameTransforms",
        "description": "An array of FrameTransform messages",
        "properties": {"transforms": {"type": "array", "items": _FRAME_TRANSFORM}},
    },
    "foxglove.CompressedImage": {
        "type": "object",
        "title": "foxglove.CompressedImage",
        "description": "A compressed image",
        "properties": {
            "timestamp": _TIME,
            "frame_id": {"type": "string"},
            "data": {"type": "string", "contentEncoding": "base64"},
            "format": {"type": "string"},
        },
    },
    "foxglove.LaserScan": {
        "type": "object",
        "title": "foxglove.LaserScan",
        "description": "A single scan from a planar laser range-finder",
        "properties": {
            "timestamp": _TIME,
            "frame_id": {"type": "string"},
            "pose": _POSE,
            "start_angle": _NUMBER,
            "end_angle": _NUMBER,
            "ranges": {"type": "array", "items": _NUMBER},
            "intensities": {"type": "array", "items": _NUMBER},
        },
    },
    "foxglove.Log": {
        "type": "object",
        "title": "foxglove.Log",
        "description": "A log message",
        "properties": {
            "timestamp": _TIME,
            "level": {
                "type": "integer",
                "description": "0 unknown, 1 debug, 2 info, 3 warning, 4 error, 5 fatal",
                "oneOf": [
                    {"const": n, "title": t}
                    for n, t in enumerate(("UNKNOWN", "DEBUG", "INFO", "WARNING", "ERROR", "FATAL"))
                ],
            },
            "message": {"type": "string"},
            "name": {"type": "string"},
            "file": {"type": "string"},
            "line": {"type": "integer", "minimum": 0},
        },
    },
}
LOG_INFO, LOG_WARNING, LOG_ERROR = 2, 3, 4

# -- EyeSim schemas ------------------------------------------------------------------------------
_ROBOT = {"type": "integer", "minimum": 1}
_NULLABLE_NUMBER = {"type": ["number", "null"]}

EYESIM = {
    "eyesim.Scene": {
        "type": "object",
        "title": "eyesim.Scene",
        "description": "The scene at the start: the viewer's `scene` message (docs/viewer-channel.md) and the "
        "loaded scene description",
        "properties": {"viewer": {"type": "object"}, "description": {"type": "object"}},
        "required": ["viewer", "description"],
    },
    "eyesim.RobotState": {
        "type": "object",
        "title": "eyesim.RobotState",
        "description": "What a robot knows about itself: odometry (m, rad), measured speed (m/s, rad/s), "
        "encoder ticks by encoder number, battery voltage, signals of its parts",
        "properties": {
            "robot": _ROBOT,
            "odometry": {"type": ["object", "null"], "properties": {"x": _NUMBER, "y": _NUMBER, "phi": _NUMBER}},
            "speed": {"type": ["object", "null"], "properties": {"v": _NUMBER, "w": _NUMBER}},
            "encoders": {"type": "object", "additionalProperties": {"type": "integer"}},
            "battery": _NULLABLE_NUMBER,
            "signals": {
                "type": "object",
                "description": "what the robot's parts give to plot (a bumper's bumper.<id>): [value, unit] by name",
                "additionalProperties": {"type": "array", "prefixItems": [_NUMBER, {"type": "string"}]},
            },
        },
        "required": ["robot"],
    },
    "eyesim.PsdReading": {
        "type": "object",
        "title": "eyesim.PsdReading",
        "description": "A PSD reading the program asked for: PSDGet (distance_mm) or PSDGetRaw (raw)",
        "properties": {
            "robot": _ROBOT,
            "psd": {"type": "integer"},
            "distance_mm": {"type": "integer"},
            "raw": {"type": "integer"},
        },
        "required": ["robot", "psd"],
    },
    "eyesim.Command": {
        "type": "object",
        "title": "eyesim.Command",
        "description": "A drive, motor or servo command the program gave (RoBIOS units: mm, degrees, percent)",
        "properties": {"robot": _ROBOT, "op": {"type": "string"}, "args": {"type": "object"}},
        "required": ["robot", "op", "args"],
    },
    "eyesim.Input": {
        "type": "object",
        "title": "eyesim.Input",
        "description": "Input from outside the robot: key, touch, irtv, serial, digital or analog",
        "properties": {"robot": _ROBOT, "input": {"enum": ["key", "touch", "irtv", "serial", "digital", "analog"]}},
        "required": ["robot", "input"],
    },
    "eyesim.SceneEdit": {
        "type": "object",
        "title": "eyesim.SceneEdit",
        "description": "A change made to the world from the viewer: `place` a robot or object at x, y (m), phi (rad)",
        "properties": {
            "edit": {"const": "place"},
            "robot": _ROBOT,
            "object": {"type": "integer"},
            "x": _NUMBER,
            "y": _NUMBER,
            "phi": _NUMBER,
        },
        "required": ["edit", "x", "y", "phi"],
    },
    "eyesim.ViewerEvent": {
        "type": "object",
        "title": "eyesim.ViewerEvent",
        "description": "A viewer channel event (docs/viewer-channel.md): menu, console, program, serial, io, audio, reset",
        "properties": {"type": {"enum": ["menu", "console", "program", "serial", "io", "audio", "reset"]}},
        "required": ["type"],
    },
    "eyesim.SensorRays": {
        "type": "object",
        "title": "eyesim.SensorRays",
        "description": "With the scene setting VIS: the `rays` of the viewer's snapshots (docs/viewer-channel.md)",
        "properties": {"rays": {"type": "array", "items": {"type": "object"}}},
        "required": ["rays"],
    },
}

SCHEMAS = {**FOXGLOVE, **EYESIM}

# Which schema each topic uses; robot topics by their last part.
TOPIC_SCHEMAS = {
    SCENE: "eyesim.Scene",
    TRANSFORMS: "foxglove.FrameTransforms",
    RAYS: "eyesim.SensorRays",
    EVENTS: "eyesim.ViewerEvent",
    LOG: "foxglove.Log",
    EDITS: "eyesim.SceneEdit",
}
ROBOT_SCHEMAS = {
    "state": "eyesim.RobotState",
    "lcd": "foxglove.CompressedImage",
    "camera": "foxglove.CompressedImage",
    "lidar": "foxglove.LaserScan",
    "psd": "eyesim.PsdReading",
    "command": "eyesim.Command",
    "input": "eyesim.Input",
}


def schema_of(topic: str) -> str:
    if topic in TOPIC_SCHEMAS:
        return TOPIC_SCHEMAS[topic]
    parts = topic.split("/")
    if len(parts) == 4 and parts[1] == "robot" and parts[3] in ROBOT_SCHEMAS:
        return ROBOT_SCHEMAS[parts[3]]
    raise KeyError(f"{topic}: no message schema is declared for this recording topic")


def schema_bytes(name: str) -> bytes:
    return json.dumps(SCHEMAS[name], separators=(",", ":")).encode()


def stamp(time_us: int) -> dict:
    """A Foxglove time from simulation microseconds."""
    return {"sec": time_us // 1_000_000, "nsec": time_us % 1_000_000 * 1000}
