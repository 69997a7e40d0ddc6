"""Untrusted XML (URDF, SRDF) parsed the way Pinocchio's parsers see it, within limits.

Pinocchio reads a URDF with urdfdom (TinyXML2) and an SRDF with Boost.PropertyTree: both
are namespace-unaware and match elements and attributes by their *literal qualified
name*. ``<mesh xmlns="urn:x" filename="/etc/passwd"/>`` is a ``mesh`` to them, while a
namespace-aware parser (ElementTree) calls it ``{urn:x}mesh`` and a check looking for
``mesh`` would skip it. :func:`parse_literal_xml` therefore parses with expat *without*
namespace processing: every tag and attribute name is kept exactly as written
(``x:mesh`` stays ``x:mesh``, ``xmlns`` is an ordinary attribute), so checks read the
document as Pinocchio does.

It also refuses DTDs (hence entity declarations and external references) and bounds the
work a document may cause before any model is built: number of elements, attributes per
element (TinyXML2's duplicate-attribute check is quadratic in it: 100 000 attributes on one
element held the GIL for ~70 s), attributes in total, and nesting depth.
"""

from __future__ import annotations

from dataclasses import dataclass
from xml.etree.ElementTree import Element, TreeBuilder
from xml.parsers import expat

from app.kinematics.errors import InvalidInputError
from app.kinematics.text import SURROGATE_REASON, has_surrogate


@dataclass(frozen=True, slots=True)
class XmlLimits:
    """Bounds on one XML document (each refusal names the setting that raises it)."""

    max_elements: int = 20_000
    max_attributes: int = 50_000
    max_attributes_per_element: int = 64
    max_depth: int = 32


#: No bounds: for documents checked when they were uploaded, or built in.
TRUSTED = XmlLimits(10**9, 10**9, 10**9, 10**9)


class _Refused(Exception):
    """Raised from an expat handler to stop parsing; carries the message."""


def parse_literal_xml(text: str, field: str, limits: XmlLimits | None = None) -> Element:
    """Parse untrusted XML into an ElementTree with literal (namespace-unaware) names.

    Parameters
    ----------
    text
        The document.
    field
        Request field named by every error (``urdf``, ``srdf``).
    limits
        Work bounds; ``None``: the defaults of :class:`XmlLimits`.

    Raises
    ------
    InvalidInputError
        Not well-formed, a DTD, a NUL or a lone surrogate, or a limit exceeded; the message
        says which (and which ``DENAVIT_`` setting raises a limit).
    """
    limits = limits or XmlLimits()
    if "\x00" in text:
        raise InvalidInputError("XML must not contain NUL characters", field)
    if has_surrogate(text):
        raise InvalidInputError(SURROGATE_REASON, field)
    builder = TreeBuilder()
    counts = {"elements": 0, "attributes": 0, "depth": 0}

    def start(name: str, attrs: dict[str, str]) -> None:
        counts["elements"] += 1
        counts["depth"] += 1
        counts["attributes"] += len(attrs)
        if counts["elements"] > limits.max_elements:
            raise _Refused(
                f"more than {limits.max_elements} XML elements (DENAVIT_MAX_XML_ELEMENTS)"
            )
        if len(attrs) > limits.max_attributes_per_element:
            raise _Refused(
                f"<{name[:40]}> has {len(attrs)} attributes, more than "
                f"{limits.max_attributes_per_element} (DENAVIT_MAX_XML_ATTRIBUTES_PER_ELEMENT)"
            )
        if counts["attributes"] > limits.max_attributes:
            raise _Refused(
                f"more than {limits.max_attributes} XML attributes in total "
                "(DENAVIT_MAX_XML_ATTRIBUTES)"
            )
        if counts["depth"] > limits.max_depth:
            raise _Refused(
                f"XML nested deeper than {limits.max_depth} levels (DENAVIT_MAX_XML_DEPTH)"
            )
        builder.start(name, attrs)

    def end(name: str) -> None:
        counts["depth"] -= 1
        builder.end(name)

    def no_dtd(*_: object) -> None:
        raise _Refused("DTDs and entity declarations are not accepted")

    parser = expat.ParserCreate()  # no namespace_separator: names stay as written
    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = builder.data
    parser.StartDoctypeDeclHandler = no_dtd
    parser.EntityDeclHandler = no_dtd
    parser.UnparsedEntityDeclHandler = no_dtd
    parser.ExternalEntityRefHandler = no_dtd
    parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)
    parser.buffer_text = True
    try:
        parser.Parse(text, True)
        return builder.close()
    except _Refused as exc:
        raise InvalidInputError(str(exc), field) from None
    except expat.ExpatError as exc:
        raise InvalidInputError(
            f"not well-formed XML ({expat.ErrorString(exc.code)}: line {exc.lineno}, "
            f"column {exc.offset})",
            field,
        ) from None
    except (ValueError, RecursionError, AssertionError) as exc:
        raise InvalidInputError(f"not well-formed XML ({type(exc).__name__})", field) from None
