"""The one error dh2urdf raises for a bad table or document: :class:`DHError`."""

from __future__ import annotations


class DHError(ValueError):
    """Invalid DH table; the message is ``"<field>: <reason>"``.

    Attributes
    ----------
    field : str or None
        Path of the offending field in the document (``joints[2].lower``, 0-based indices),
        or ``None`` when the document as a whole is at fault (unreadable YAML, ...).
    reason : str
        What is wrong, without the field path.
    """

    def __init__(self, field: str | None, reason: str) -> None:
        self.field = field
        self.reason = reason
        super().__init__(f"{field}: {reason}" if field else reason)
