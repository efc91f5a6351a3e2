import faulthandler

from eye import *

VWStraight(400, 300)
VWWait()
print("about to crash", flush=True)
faulthandler._read_null()  # a native crash: an access violation (0xC0000005), as a C bug would give
LCDPrintf("done\n")
