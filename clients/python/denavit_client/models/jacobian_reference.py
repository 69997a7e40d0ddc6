from enum import StrEnum


class JacobianReference(StrEnum):
    LOCAL = "local"
    WORLD = "world"
    WORLD_SPATIAL = "world_spatial"

    def __str__(self) -> str:
        return str(self.value)
