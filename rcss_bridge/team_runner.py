"""One of the project's teams playing a match in rcssserver through the client layer.

:func:`play_team` connects the team's 11 players and online coach
(:class:`~rcss_bridge.client.TeamClient`), gives the team what a match of the simulator
gives it before kick-off (its :class:`~soccer_sim.team.SideInfo` with the server's player
types, the server's :class:`~soccer_sim.config.MatchConfig`: partial observation), sends the
types it chooses (:class:`~soccer_sim.team_hooks.ChoosesPlayerTypes`; all default for a team
that does not choose: without the coach's word the server would give the players types of
its own) and then, every step once every player has seen where it is (:func:`located`), calls the team's ``act`` on the step's
:class:`~soccer_sim.perception.views.PlayerViews` and sends its
:class:`~soccer_sim.team.TeamCommand` (:meth:`~rcss_bridge.client.TeamClient.send_command`),
aimed with where each player believes the ball is
(:class:`~soccer_sim.team_hooks.BelievesBall`, where the team tells it; between two sees a
player's view has no ball). The per-player pipeline runs unchanged.

The team's ``act`` runs in a worker thread with the client's ``decision_budget``: one that
raises ends the match with a :class:`~rcss_bridge.errors.TeamFailure`, one that overruns
with a :class:`~rcss_bridge.errors.TeamTooSlow`, both naming the step and the server's time.
A step the server went on without (it waited 1.25 s for our ``(done)`` in vain) after
kick-off is a :class:`~rcss_bridge.errors.TeamTooSlow` too.
"""

from __future__ import annotations

import queue
import threading
import time
from dataclasses import dataclass, replace

import numpy as np

from soccer_sim.state import PlayMode
from soccer_sim.team import SideInfo, Team, TeamCommand
from soccer_sim.team_hooks import BelievesBall, ChoosesPlayerTypes

from rcss_bridge.client import SERVER_WAIT_SECONDS, Step, TeamClient
from rcss_bridge.errors import CommandError, TeamFailure, TeamTooSlow


@dataclass
class TeamRun:
    """What one team's match through the bridge was like."""

    steps: int = 0
    """Steps the team decided (the client's own counter)."""
    slowest: float = 0.0
    """The longest ``act`` plus sending of a step (seconds)."""
    decide_seconds: float = 0.0
    """Wall time spent in ``act`` and the translation over the match."""
    missed_before_kick_off: int = 0
    """Server steps that went by without the team while it connected (not a fault)."""
    unlocated: int = 0
    """Steps at the start at which the team did not decide: a player had not yet seen where it
    is (:func:`located`)."""
    commands: dict[str, int] | None = None
    """The commands sent by the server's names (:attr:`~rcss_bridge.commands.CommandTranslator.sent`)."""


def play_team(team: Team, name: str, opponent_name: str, client: TeamClient, seed: int) -> TeamRun:
    """Play the match with ``team`` (named ``name`` in errors) through ``client`` (not yet
    connected; closed at the end, also on failure). Returns the run's figures."""
    with client:
        client.connect()
        assert client.parameters is not None and client.config is not None
        types = tuple(client.parameters.types)
        players = client.settings.players
        info = SideInfo(team=0 if client.side == "l" else 1, name=name, opponent_name=opponent_name,
                        players_per_team=players, goalie_index=client.settings.goalie, opponents=players,
                        opponent_goalie_index=0, player_types=types, own_types=(0,) * players)
        choice = [0] * players
        if isinstance(team, ChoosesPlayerTypes):
            try:
                choice = [int(t) for t in team.choose_player_types(types, info)]
            except Exception as exc:  # noqa: BLE001 - a team's failure, named
                raise TeamFailure(name, None, -1, 0, f"choose_player_types() raised {type(exc).__name__}: {exc}") from exc
        try:
            client.choose_player_types(choice)
        except CommandError as exc:
            raise TeamFailure(name, exc.player, -1, 0, f"bad player types: {exc.message}") from exc
        info = replace(info, own_types=tuple(choice))
        try:
            team.reset(info, client.config, np.random.default_rng(seed))
        except Exception as exc:  # noqa: BLE001
            raise TeamFailure(name, None, -1, 0, f"reset() raised {type(exc).__name__}: {exc}") from exc
        return _play(team, name, client)


def _play(team: Team, name: str, client: TeamClient) -> TeamRun:
    run = TeamRun()
    worker = _ActWorker(team)
    budget = client.settings.decision_budget
    kicked_off = False
    try:
        while True:
            step = client.next_step()
            if step.over:
                break
            kicked_off = kicked_off or step.views.play_mode != PlayMode.KICK_OFF or step.views.half > 0
            if step.missed:
                if kicked_off:
                    raise TeamTooSlow(name, None, step.step, step.server_time,
                                      f"the server went on without the team's (done) for {step.missed} step(s) "
                                      f"(it waits {SERVER_WAIT_SECONDS:g} s a step)")
                run.missed_before_kick_off += step.missed
            started = time.monotonic()
            if not located(step):
                client.send_step({})  # (done) alone until every player has seen where it is
                run.unlocated += 1
                continue
            command, ball = worker.act(step, budget, name)
            client.send_command(step, command, ball)
            spent = time.monotonic() - started
            run.decide_seconds += spent
            run.slowest = max(run.slowest, spent)
            run.steps += 1
    finally:
        worker.stop()
    run.commands = dict(client.translator.sent) if client.translator is not None else {}
    return run


def located(step: Step) -> bool:
    """Whether every present player of the step knows where it is and where it faces (from a
    see with flags, kept since). Until then the team is not asked: the simulator's views
    always hold a position, and a team's commands would be made of NaN (at most the first
    step or two before kick-off: every player sees at the start of its first steps)."""
    views = step.views
    present = views.present
    return bool(np.all(np.isfinite(views.position[present])) and np.all(np.isfinite(views.body_direction[present])))


class _ActWorker:
    """Runs the team's ``act`` in a daemon thread, so that one that never returns cannot hang
    the client: the caller stops waiting after the budget (the thread is abandoned, the client
    closed). Returns the command and the ball belief read right after it."""

    def __init__(self, team: Team) -> None:
        self.team = team
        self._jobs: queue.Queue = queue.Queue()
        self._results: queue.Queue = queue.Queue()
        self._thread = threading.Thread(target=self._loop, name="rcss-team-act", daemon=True)
        self._thread.start()

    def act(self, step: Step, budget: float, name: str) -> tuple[TeamCommand, np.ndarray | None]:
        self._jobs.put(step)
        try:
            command, ball, error = self._results.get(timeout=budget)
        except queue.Empty:
            raise TeamTooSlow(name, None, step.step, step.server_time,
                              f"act() took longer than {budget:g} s (the server waits {SERVER_WAIT_SECONDS:g} s "
                              "for a step)") from None
        if error is not None:
            raise TeamFailure(name, None, step.step, step.server_time,
                              f"act() raised {type(error).__name__}: {error}") from error
        return command, ball

    def _loop(self) -> None:
        while True:
            step = self._jobs.get()
            if step is None:
                return
            try:
                command = self.team.act(step.views)
                ball = self.team.believed_ball() if isinstance(self.team, BelievesBall) else None
                self._results.put((command, None if ball is None else np.array(ball, dtype=np.float64), None))
            except BaseException as exc:  # noqa: BLE001 - every failure of a team's code is reported
                self._results.put((None, None, exc))

    def stop(self) -> None:
        self._jobs.put(None)
