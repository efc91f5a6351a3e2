"""PSD infrared distance sensors: a beam from a point on the robot, read with PSDGet (mm) and
PSDGetRaw (the 10-bit sensor curve), and shown as rays in the viewer and the robot editor."""
