"""Wire models, one module per area (``fk``, ``ik``, ``paths``, …); the shared wire types in
:mod:`.common`. No routes here, no computation."""
