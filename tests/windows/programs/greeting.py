"""Windows test program: text beyond ASCII on the LCD and on stdout."""

from eye import *

LCDPrintf("Grüße 20°C\n")
print("Grüße 20°C", flush=True)
