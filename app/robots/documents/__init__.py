"""Checks of untrusted documents: everything a client sends as a robot, before it is used.

- :mod:`app.robots.documents.dh` — DH table documents (JSON or YAML): size, nesting and YAML-event
  limits, no YAML aliases, then dh2urdf's validation (``parse_dh_document``); the API
  answers 400 for a document that is not JSON/YAML at all (:class:`MalformedDocumentError`)
  and 422 naming the field otherwise.
- :mod:`app.robots.documents.urdf` — uploaded URDF: resource URIs, numbers, joints, tree shape and
  the work limits (:class:`UrdfLimits`); ``check_documents`` runs the URDF and SRDF checks,
  ``build_checked_model`` turns checked text into a model.
- :mod:`app.robots.documents.srdf` — uploaded SRDF: a ``<robot>`` root and known links.

XML is parsed by :func:`app.kinematics.xmldoc.parse_literal_xml` (no DTD or entities,
bounded work, literal names), which stays in the core because the core parses URDF and
SRDF with it too. Every refusal is an :class:`~app.kinematics.errors.InvalidInputError`
naming the request field.
"""
