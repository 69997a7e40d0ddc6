from enum import StrEnum


class CollisionPairKind(StrEnum):
    ENVIRONMENT = "environment"
    SELF = "self"

    def __str__(self) -> str:
        return str(self.value)
