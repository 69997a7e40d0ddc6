from enum import StrEnum


class PairOutKind(StrEnum):
    ENVIRONMENT = "environment"
    SELF = "self"

    def __str__(self) -> str:
        return str(self.value)
