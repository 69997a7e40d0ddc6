from enum import StrEnum


class ManipulabilityRequestReference(StrEnum):
    LOCAL = "local"
    WORLD = "world"
    WORLD_SPATIAL = "world_spatial"

    def __str__(self) -> str:
        return str(self.value)
