"""The HTTP layer: routes (:mod:`app.api.routes`), wire models (:mod:`app.api.schemas`) and
the plumbing they share beside them: typed dependencies (``deps``), errors as RFC 9457
problem details (``errors``), body decoding (``body``), the compute pools (``offload``),
responses, security, untrusted-file answers."""
