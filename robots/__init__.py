"""The robot catalog: example-robot-data entries and the course's DH tables (robots/dh/)."""

from __future__ import annotations

from pathlib import Path

HERE = Path(__file__).resolve().parent
#: The list of example-robot-data robots served as built-ins.
CATALOG_FILE = HERE / "example_robot_data.yaml"
#: Directory of built-in DH tables, one ``<id>.yaml`` per robot.
DH_DIR = HERE / "dh"


def dh_tables() -> dict[str, Path]:
    """Built-in DH tables by robot id (the file stem)."""
    return {p.stem: p for p in sorted(DH_DIR.glob("*.yaml"))}
