"""State kept across requests and processes: user-added robots and their files (``store``),
obstacle scenes (``scenes``), reachability maps (``maps``) and their build jobs
(``build_jobs``, ``job_table``)."""
