from enum import StrEnum


class IKStatus(StrEnum):
    CONVERGED = "converged"
    NOT_CONVERGED = "not_converged"
    TIMEOUT = "timeout"

    def __str__(self) -> str:
        return str(self.value)
