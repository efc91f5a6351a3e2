# Pick and place (the Python version of pick_and_place.c): the Reacher arm (the built-in Reacher)
# takes the can 300 mm to its left and puts it down about 300 mm ahead of it (and 80 mm to the
# right). Servos: 1 lift (0..250 mm), 2 shoulder, 3 elbow (each -150..150 deg over 0..255),
# 4 gripper (0 closed, 255 open). From the examples folder:
#   eyesim run scenes/workshop.sim --program 1=programs/pick_and_place.py
from eye import *


def servos(lift, shoulder, elbow, ms):
    SERVOSet(1, lift)
    SERVOSet(2, shoulder)
    SERVOSet(3, elbow)
    OSWait(ms)


LCDPrintf("Pick and place\n")
SERVOSet(4, 255)  # open
servos(153, 128, 128, 2000)  # lift above the can, 150 mm
servos(153, 169, 197, 3000)  # over the can, to the left: shoulder 49, elbow 82 degrees
servos(41, 169, 197, 2000)  # down to the can's middle
SERVOSet(4, 0)  # grip
OSWait(1500)
servos(153, 169, 197, 2000)  # lift
servos(153, 80, 197, 3000)  # swing round: shoulder -31 degrees, the can ahead
servos(43, 80, 197, 2000)  # down to the floor
SERVOSet(4, 255)  # let go
OSWait(1500)
servos(153, 80, 197, 2000)  # up and away
x, y, z, phi = SIMGetObject(1)
LCDPrintf("can at %d %d\n", x, y)
print("can", x, y, z)
