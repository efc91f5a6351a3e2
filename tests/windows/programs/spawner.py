"""Windows test program: starts forever.exe from its own folder, waits until it runs and until the
test creates the file `release`, then keeps the robot busy for ever."""

import os
import subprocess
import sys
import time

# Before the first RoBIOS call, time.sleep is still the wall clock's.
child = subprocess.Popen([os.path.join(os.path.dirname(os.path.abspath(__file__)), "forever.exe")])
deadline = time.monotonic() + 60
while not os.path.exists("child-running"):
    if time.monotonic() > deadline or child.poll() is not None:
        sys.exit(f"forever.exe did not start (exit code {child.poll()})")
    time.sleep(0.02)
print(f"child {child.pid} running", flush=True)
while not os.path.exists("release"):  # the test looks at the processes meanwhile
    time.sleep(0.02)

from eye import *  # noqa: E402

LCDPrintf("looping\n")
while True:
    VWSetSpeed(100, 0)
    OSWait(100)
