"""``ik.warmup``: "warmed" means every kernel is compiled. A caller that comes while another
thread compiles waits for all of them, so no query compiles inside its time budget."""

from __future__ import annotations

import threading

import pytest

from app.kinematics import analytic_ik, jit
from app.kinematics.ik import kernel, search_kernel, warmup

pytestmark = pytest.mark.skipif(not jit.available(), reason="Numba not installed")


def test_a_second_caller_waits_until_every_kernel_is_compiled(monkeypatch) -> None:
    monkeypatch.setattr(warmup, "_warmed", False)
    entered, release = threading.Event(), threading.Event()
    done: list[str] = []

    def search_warm_up() -> None:  # the search kernel compiles slowly
        entered.set()
        assert release.wait(timeout=60)
        done.append("search")

    monkeypatch.setattr(kernel, "warm_up", lambda: done.append("attempt"))
    monkeypatch.setattr(search_kernel, "warm_up", search_warm_up)
    monkeypatch.setattr(analytic_ik, "warm_up", lambda: done.append("closed forms"))
    first = threading.Thread(target=warmup.warm_up)
    first.start()
    try:
        assert entered.wait(timeout=60)
        # the attempt kernel is compiled, the search kernel is not: not warmed yet
        assert done == ["attempt"]
        assert not warmup.warmed()
        seen: list[list[str]] = []

        def second() -> None:
            warmup.warm_up()
            seen.append(list(done))  # what was compiled when warm_up returned

        other = threading.Thread(target=second)
        other.start()
    finally:
        release.set()
        first.join(timeout=60)
    other.join(timeout=60)
    assert seen == [["attempt", "search", "closed forms"]]
    assert warmup.warmed()
