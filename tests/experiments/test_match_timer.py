"""The match timer of the runner and `play`: it raises MatchTimeout in the main thread, strikes
again when a raise was swallowed (as inside a garbage collector's finaliser), and stays silent
once disarmed."""

from __future__ import annotations

import time

import pytest

from experiments.runner.worker import TIMER_RESTRIKE_SECONDS, MatchTimeout, arm_timer, disarm_timer


def test_a_swallowed_timeout_strikes_again() -> None:
    swallowed = 0
    alarm = arm_timer(0.05)
    try:
        with pytest.raises(MatchTimeout, match="0.05 s"):
            deadline = time.monotonic() + 30  # a bound, not a timing assertion: the loop must end by a raise
            while time.monotonic() < deadline:
                try:
                    time.sleep(0.005)
                except MatchTimeout:
                    if swallowed:
                        raise
                    swallowed += 1  # a guarded callback prints and drops the first raise
    finally:
        disarm_timer(alarm)
    assert swallowed == 1


def test_a_disarmed_timer_does_not_strike() -> None:
    alarm = arm_timer(0.05)
    with pytest.raises(MatchTimeout):
        time.sleep(30)
    disarm_timer(alarm)
    time.sleep(2 * TIMER_RESTRIKE_SECONDS)  # the re-strike scheduled by the raise was cancelled
