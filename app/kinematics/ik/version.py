"""The IK solver's version, named by every IK, batch IK and path response.

Bump it whenever a change can alter an answer for the same request (another step, restart
order, tolerance, ranking or branch definition): with ``random_seed`` (and ``max_iterations``
with a generous ``timeout_ms``) the same request gives the same answer, bit for bit, on any
worker of the same ``SOLVER_VERSION``, on the same platform.
"""

from __future__ import annotations

#: Name and version of the solver (changes whenever answers may change).
SOLVER_VERSION = "denavit-ik 1.1"
