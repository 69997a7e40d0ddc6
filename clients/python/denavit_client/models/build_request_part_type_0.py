from enum import StrEnum


class BuildRequestPartType0(StrEnum):
    FULL = "full"
    ROTATION = "rotation"
    TRANSLATION = "translation"

    def __str__(self) -> str:
        return str(self.value)
