"""A Ray cluster address that does not answer is one error line within a bounded time (Ray's
own client retries such an address for ever)."""

from __future__ import annotations

import os
import socket
import subprocess
import sys
from pathlib import Path

import pytest

from experiments.runner.ray_cluster import ADDRESS_PROBE_SECONDS, RayUnavailable, connect, probe_address

ROOT = Path(__file__).resolve().parents[2]

HANG_BOUND = 240.0
"""Seconds after which the command counts as hanging (a bound: it answers within seconds)."""


@pytest.fixture
def silent_port():
    """A port of 127.0.0.1 that nothing listens on (bound by this test, never listening)."""
    with socket.socket() as holder:
        holder.bind(("127.0.0.1", 0))
        yield holder.getsockname()[1]


class _RayThatMustNotBeCalled:
    """Stands in for the ``ray`` module: joining a cluster is not to be tried."""

    @staticmethod
    def is_initialized() -> bool:
        return False

    @staticmethod
    def init(**options) -> None:
        raise AssertionError(f"ray.init was called with {options}")


def test_the_tournament_gives_up_on_an_address_nobody_answers_at(silent_port, tmp_path) -> None:
    pytest.importorskip("ray")
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])}
    env.pop("RAY_ADDRESS", None)
    result = subprocess.run([sys.executable, "-m", "experiments.cli", "tournament", "--teams", "chaser,idle",
                             "--games", "2", "--cycles", "20", "--backend", "ray", "--address",
                             f"127.0.0.1:{silent_port}", "--out", str(tmp_path / "r.sqlite"), "--no-progress"],
                            capture_output=True, text=True, timeout=HANG_BOUND, cwd=ROOT, env=env)
    assert result.returncode == 2, result.stderr
    assert result.stderr.count("\n") == 1, result.stderr
    assert result.stderr.startswith(f"error: cannot reach the Ray cluster at 127.0.0.1:{silent_port}")


def test_the_address_ray_address_names_is_probed_before_ray_is_asked(silent_port, monkeypatch) -> None:
    monkeypatch.setenv("RAY_ADDRESS", f"127.0.0.1:{silent_port}")
    with pytest.raises(RayUnavailable, match=f"cannot reach the Ray cluster at 127.0.0.1:{silent_port}"):
        connect(_RayThatMustNotBeCalled(), 1, None, ship_code=False)


def test_an_address_that_never_answers_is_given_up_after_the_probe_time(monkeypatch) -> None:
    waited = []

    def no_answer(address, timeout):
        waited.append(timeout)
        raise TimeoutError("timed out")

    monkeypatch.setattr(socket, "create_connection", no_answer)
    with pytest.raises(RayUnavailable, match=f"ray://10.1.2.3:10001: no answer within {ADDRESS_PROBE_SECONDS:g} s"):
        probe_address("ray://10.1.2.3:10001")
    assert waited == [ADDRESS_PROBE_SECONDS]


def test_auto_and_unparsable_addresses_are_left_to_ray(monkeypatch) -> None:
    monkeypatch.setattr(socket, "create_connection", lambda *a, **k: pytest.fail("nothing is to be dialled"))
    for address in ("auto", "local", "host-without-port"):
        probe_address(address)
