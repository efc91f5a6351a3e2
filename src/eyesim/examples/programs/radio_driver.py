# Radio, the driver (robot 2; the Python version of radio_driver.c): waits for commands from robot 1
# over the radio ("forward <mm>", "left <degrees>", "right <degrees>", "stop"), carries each out and
# answers where it is now. Runs with radio_commander.py on robot 1. From the examples folder:
#   eyesim run scenes/radio.sim --program 1=programs/radio_commander.py --program 2=programs/radio_driver.py
from eye import *

RADIOInit()
LCDPrintf("Driver: robot %d, waiting for commands\n", RADIOGetID())
while True:
    sender, command = RADIOReceive()
    LCDPrintf("robot %d: %s\n", sender, command)
    print('got "%s" from robot %d' % (command, sender))
    if command == "stop":
        RADIOSend(sender, "stopped")
        break
    words = command.split()
    if len(words) == 2 and words[0] in ("forward", "left", "right") and words[1].lstrip("-").isdigit():
        amount = int(words[1])
        if words[0] == "forward":
            VWStraight(amount, 300)
        else:
            VWTurn(amount if words[0] == "left" else -amount, 90)
        VWWait()
        x, y, phi = VWGetPosition()
        RADIOSend(sender, "done %s, now at x %d y %d phi %d" % (command, x, y, phi))
    else:
        RADIOSend(sender, "unknown command: " + command)
LCDPrintf("stopped\n")
