"""Hypothesis strategies: random but valid DH table documents in random units."""

from __future__ import annotations

from typing import Any

from hypothesis import strategies as st

SPECIAL_DEG = (0.0, 90.0, -90.0, 180.0, -180.0, 45.0)
LENGTH_SCALE = {"m": 1.0, "cm": 100.0, "mm": 1000.0}


@st.composite
def angles(draw: st.DrawFn, unit: str) -> float:
    """An angle in the table unit; often a special value (gimbal cases), else uniform."""
    deg = draw(
        st.one_of(
            st.sampled_from(SPECIAL_DEG),
            st.floats(-360.0, 360.0, allow_nan=False, allow_infinity=False),
        )
    )
    return deg if unit == "deg" else deg * 3.141592653589793 / 180.0


@st.composite
def lengths(draw: st.DrawFn, unit: str) -> float:
    """A length in the table unit, metres in [-1.5, 1.5], often exactly 0."""
    metres = draw(
        st.one_of(st.just(0.0), st.floats(-1.5, 1.5, allow_nan=False, allow_infinity=False))
    )
    return metres * LENGTH_SCALE[unit]


@st.composite
def transforms(draw: st.DrawFn, length_unit: str, angle_unit: str) -> dict[str, Any]:
    return {
        "xyz": [draw(lengths(length_unit)) for _ in range(3)],
        "rpy": [draw(angles(angle_unit)) for _ in range(3)],
    }


@st.composite
def table_docs(
    draw: st.DrawFn,
    conventions: tuple[str, ...] = ("standard", "modified"),
    joint_types: tuple[str, ...] = ("revolute", "prismatic", "continuous"),
    max_joints: int = 7,
) -> dict[str, Any]:
    """A valid DH table document (table units), with optional base and tool."""
    length_unit = draw(st.sampled_from(("m", "cm", "mm")))
    angle_unit = draw(st.sampled_from(("rad", "deg")))
    n = draw(st.integers(1, max_joints))
    rows = []
    for _ in range(n):
        jtype = draw(st.sampled_from(joint_types))
        row: dict[str, Any] = {
            "type": jtype,
            "a": draw(lengths(length_unit)),
            "alpha": draw(angles(angle_unit)),
            "d": draw(lengths(length_unit)),
            "theta": draw(angles(angle_unit)),
        }
        if jtype == "prismatic":
            row["lower"] = -0.5 * LENGTH_SCALE[length_unit]
            row["upper"] = 0.5 * LENGTH_SCALE[length_unit]
        rows.append(row)
    doc: dict[str, Any] = {
        "name": "random_arm",
        "convention": draw(st.sampled_from(conventions)),
        "units": {"length": length_unit, "angle": angle_unit},
        "joints": rows,
    }
    if draw(st.booleans()):
        doc["base"] = draw(transforms(length_unit, angle_unit))
    if draw(st.booleans()):
        doc["tool"] = draw(transforms(length_unit, angle_unit))
    return doc
