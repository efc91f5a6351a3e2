# Radio, the commander (robot 1; the Python version of radio_commander.c): tells robot 2 over the
# radio how to drive, one command at a time, and waits for its answer before sending the next.
# Runs with radio_driver.py (or radio_driver.c) on robot 2. From the examples folder:
#   eyesim run scenes/radio.sim --program 1=programs/radio_commander.py
from eye import *

DRIVER = 2  # the robot that drives
COMMANDS = ["forward 600", "left 90", "forward 400", "left 90", "forward 300", "stop"]

RADIOInit()
LCDPrintf("Commander: robot %d, driver: robot %d\n", RADIOGetID(), DRIVER)
for command in COMMANDS:
    RADIOSend(DRIVER, command)
    LCDPrintf("sent:  %s\n", command)
    sender, answer = RADIOReceive()
    LCDPrintf("robot %d: %s\n", sender, answer)
    print("robot %d answered: %s" % (sender, answer))
LCDPrintf("all %d commands done\n", len(COMMANDS))
