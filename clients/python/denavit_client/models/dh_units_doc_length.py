from enum import StrEnum


class DHUnitsDocLength(StrEnum):
    CM = "cm"
    M = "m"
    MM = "mm"

    def __str__(self) -> str:
        return str(self.value)
