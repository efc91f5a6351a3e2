"""Scene files (.sim .wld .maz .robi .esObj and their JSON forms) -> immutable scene description."""

from eyesim.scene.builtins import DEFAULT_SCENE
from eyesim.scene.description import (ArmSpec, BuoyancySpec, CameraSpec, Collider, Diagnostic, DragSpec,
                                      GripperSpec, JointSpec, LidarSpec, Location, Marker, ObjectPlacement,
                                      ObjectType, Pose, PsdSpec, RobotPlacement, RobotType, Scene, Settings,
                                      StartPosition, SteeringSpec, ThrusterSpec, Wall, WheelSpec, World)
from eyesim.scene.diagnostics import SceneError
from eyesim.scene.loader import load_object_type, load_robot_type, load_scene, load_world

__all__ = [
    "DEFAULT_SCENE", "SceneError", "load_scene", "load_world", "load_robot_type", "load_object_type",
    "ArmSpec", "BuoyancySpec", "CameraSpec", "Collider", "Diagnostic", "DragSpec", "GripperSpec", "JointSpec",
    "LidarSpec", "Location", "Marker", "ObjectPlacement", "ObjectType", "Pose", "PsdSpec", "RobotPlacement",
    "RobotType", "Scene", "Settings", "StartPosition", "SteeringSpec", "ThrusterSpec", "Wall", "WheelSpec", "World",
]
