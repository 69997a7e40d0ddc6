from enum import StrEnum


class IKResponseStatus(StrEnum):
    CONVERGED = "converged"
    NOT_CONVERGED = "not_converged"
    TIMEOUT = "timeout"

    def __str__(self) -> str:
        return str(self.value)
