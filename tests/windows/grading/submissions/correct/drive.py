from eye import *

VWStraight(400, 300)
VWWait()
LCDPrintf("done\n")
