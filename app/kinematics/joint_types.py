"""Pinocchio joint models by kind, by their ``shortname()``: the one list every module that
asks "is this joint revolute / prismatic?" of a ``pin.Model`` reads."""

from __future__ import annotations

#: Revolute joints: about a principal axis, any axis, and their unbounded (continuous) forms.
REVOLUTE_MODELS = frozenset({
    "JointModelRX", "JointModelRY", "JointModelRZ", "JointModelRevoluteUnaligned",
    "JointModelRUBX", "JointModelRUBY", "JointModelRUBZ", "JointModelRevoluteUnboundedUnaligned",
})  # fmt: skip
#: Prismatic joints: along a principal axis or any axis.
PRISMATIC_MODELS = frozenset(
    {"JointModelPX", "JointModelPY", "JointModelPZ", "JointModelPrismaticUnaligned"}
)
