"""The robot's camera: a pinhole or fisheye view from a point on the robot, optionally on pan and
tilt servos, read with CAMInit/CAMGet/CAMGetGray and shown in the viewer and the robot editor."""
