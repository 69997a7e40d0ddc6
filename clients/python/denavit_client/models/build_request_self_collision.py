from enum import StrEnum


class BuildRequestSelfCollision(StrEnum):
    CONVEX = "convex"
    IGNORE = "ignore"
    MESH = "mesh"

    def __str__(self) -> str:
        return str(self.value)
