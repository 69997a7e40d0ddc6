from enum import StrEnum


class CollisionBatchRequestGeometry(StrEnum):
    CONVEX = "convex"
    MESH = "mesh"

    def __str__(self) -> str:
        return str(self.value)
