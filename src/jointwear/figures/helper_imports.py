"""What the drawing helpers need, imported once by their fork server (``render.py``).

The helpers are forked from the server with these modules in memory. Their objects are set
apart from the garbage collector (``gc.freeze``): they live as long as the processes, and
collecting them would slow the drawing and each process's exit (about 0.4 s of it).
"""

import gc

from . import clearance, run, slider  # noqa: F401  (the plotting modules a Drawing names)

gc.freeze()
