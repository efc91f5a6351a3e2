# Radio, the commander (robot 1; the Python version of radio_commander.c): tells robot 2 over the
# radio how to drive, one command at a time, and waits for its answer before sending the next.
# Runs with radio_driver.py on robot 2 (or with radio_driver.c: leave out --program 2=...). From
# the examples folder:
#   eyesim run scenes/radio.sim --program 1=programs/radio_commander.py --program 2=programs/radio_driver.py
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
