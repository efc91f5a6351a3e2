# Push a crate (the Python version of push_crate.c): the Trolley (the built-in Trolley) drives up to
# the crate ahead and pushes it 600 mm further, then backs off. It is robot 3 of the drive-types
# scene; from the examples folder, with the other two:
#   eyesim run scenes/drive_types.sim --program 1=programs/car_slalom.py --program 2=programs/omni_square.py --program 3=programs/push_crate.py
from eye import *

LCDPrintf("Pushing the crate\n")
while PSDGet(PSD_FRONT) > 40:
    VWSetSpeed(200, 0)
    OSWait(20)
VWStraight(600, 150)
VWWait()
VWStraight(-200, 200)
VWWait()
x, y, z, phi = SIMGetObject(1)
LCDPrintf("crate now at %d %d\n", x, y)
print("crate", x, y)
