"""Preloaded by the forkserver of reachability builds: the forkserver dies with its parent.

:func:`app.workers.map_build._context` names this module first in
``set_forkserver_preload``, so the forkserver, started by the thread that runs a build in a
server worker, gets ``PR_SET_PDEATHSIG`` = SIGKILL: when that worker is killed, the kernel
kills the forkserver, and the build processes forked from it (which set the same signal
for their own parent, the forkserver) with it. By itself the forkserver would wait for
ever: every build process holds the write end of the pipe whose end-of-file tells it to
exit.

Importing this module does nothing in any other process (only in ``python -c`` with
``multiprocessing.forkserver`` loaded, i.e. the forkserver).
"""

from __future__ import annotations

import sys

from app.workers.procwatch import set_parent_death_signal

if sys.argv[:1] == ["-c"] and "multiprocessing.forkserver" in sys.modules:
    set_parent_death_signal()
