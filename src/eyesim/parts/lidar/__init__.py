"""A scanning lidar: a fan of beams in a plane over the robot's top, configured with LIDARSet and
read with LIDARGet (SIMLaserScan, EyeSim 6's), drawn as a scan in the viewer and the robot editor."""
