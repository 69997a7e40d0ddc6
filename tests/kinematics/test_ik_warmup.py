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


def test_registered_callers_compile_before_the_solver_is_warmed(monkeypatch) -> None:
    """A kernel module that calls the solver's kernels (the paths' compiled point) registers
    its warm-up with the solver's: a chain is prepared only once it is compiled too, so no
    query's budget competes with its compiler (a fresh process once answered a 1 s query
    ``timeout`` after 0 iterations while the paths' point compiled beside it)."""
    from app.kinematics import kernels  # imports every kernel module, as the service does
    from app.kinematics.paths import point_kernel

    assert kernels.KERNEL_MODULES and point_kernel.warm_up in warmup._CALLERS
    done: list[str] = []
    monkeypatch.setattr(warmup, "_warmed", False)
    monkeypatch.setattr(warmup, "_CALLERS", [])
    for name in ("attempt", "search", "closed forms", "annotation"):
        module = {"attempt": kernel, "search": search_kernel, "closed forms": analytic_ik}
        target = module.get(name, warmup.annotate)
        monkeypatch.setattr(target, "warm_up", lambda name=name: done.append(name))
    warmup.register(lambda: done.append("paths"))
    assert not warmup.warmed()
    warmup.warm_up()
    assert done == ["attempt", "search", "closed forms", "annotation", "paths"]
    assert warmup.warmed()
    warmup.register(lambda: done.append("later"))  # registered after: due at the next one
    assert not warmup.warmed()
    warmup.warm_up()
    assert done[-1] == "later" and warmup.warmed()
