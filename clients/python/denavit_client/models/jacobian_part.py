from enum import StrEnum


class JacobianPart(StrEnum):
    FULL = "full"
    ROTATION = "rotation"
    TRANSLATION = "translation"

    def __str__(self) -> str:
        return str(self.value)
