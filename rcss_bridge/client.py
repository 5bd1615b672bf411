"""The client layer: one team's 11 players and its online coach in rcssserver, from one
Python process, in synchronous mode.

:meth:`TeamClient.connect` sends each player's ``(init TEAM (version 19))`` (the goalkeeper's
with ``(goalie)``) and the coach's, reads the parameters the server answers with
(:class:`~rcss_bridge.params.ServerParameters`, and the ``MatchConfig`` they make) and asks
every player for ``(synch_see)`` (a see at the start of the step it belongs to). Each step
(:meth:`TeamClient.next_step`) waits until every player has received ``(think)``, parses what
each received (:mod:`rcss_bridge.messages`) and builds the team's views
(:class:`~rcss_bridge.views_builder.ViewsBuilder`); :meth:`TeamClient.send_step` then sends
each player's commands and ``(done)`` in one datagram, the say quoted (an unquoted say
swallows what follows it in the datagram, the ``(done)`` included). :meth:`TeamClient.play`
runs that loop with a team's decisions until the match is over.

The step counter is the client's own (:attr:`Step.step`): the server's clock
(:attr:`Step.server_time`) stands still before kick-off, for 50 steps after a goal and at
some stoppages. Time-outs: the server's replies to ``init`` (``connect_timeout``), the
server's ``(think)`` (``step_timeout``: a server that stopped or left is an error, never a
hang) and a team's decisions (``decision_budget``: the server waits 1.25 s for every
``(done)`` and ends the match after 20 such steps in a row, so a slower team is stopped
with a :class:`~rcss_bridge.errors.TeamTooSlow` naming the player and the step).
"""

from __future__ import annotations

import queue
import select
import threading
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.perception.audio import AudioParams, check_message
from soccer_sim.perception.views import PlayerViews
from soccer_sim.state import PlayMode
from soccer_sim.team import TeamCommand, TeamError

from rcss_bridge.body_control import ServerRules
from rcss_bridge.commands import CommandTranslator, PlayerBodies, player_type_commands
from rcss_bridge.commands import warm_up as warm_up_commands
from rcss_bridge.connection import Connection, Recorder
from rcss_bridge.errors import BridgeError, CommandError, ProtocolError, ServerError, TeamFailure, TeamTooSlow
from rcss_bridge.localisation import warm_up
from rcss_bridge.messages import Message, SenseBody, Think, read_message
from rcss_bridge.orders import PlayerOrder
from rcss_bridge.params import ServerParameters
from rcss_bridge.sexpr import head
from rcss_bridge.views_builder import ViewsBuilder

PROTOCOL_VERSION = 19
"""The client protocol version the bridge speaks (rcssserver 19)."""

SERVER_WAIT_SECONDS = 1.25
"""How long rcssserver waits for every ``(done)`` of a step (``stadium.cpp``, 25 x 50 ms)."""


@dataclass(frozen=True)
class ClientSettings:
    """Where the server is and how long the client waits (seconds)."""

    host: str = "127.0.0.1"
    port: int = 6000
    """The players' port (rcssserver ``port``)."""
    coach_port: int | None = 6002
    """The online coach's port (rcssserver ``olcoach_port``); None: no coach."""
    players: int = 11
    """The team's size (rows of its views)."""
    connect: int | None = None
    """How many players to connect (None: the whole team); the server numbers them in the
    order they connect, the goalkeeper first (fewer: a partial team, the rest not present)."""
    goalie: int = 0
    """The goalkeeper's row (shirt number - 1); it connects first, with ``(goalie)``."""
    connect_timeout: float = 5.0
    step_timeout: float = 10.0
    """The longest wait for a step's ``(think)`` (steps before kick-off take 50 ms)."""
    decision_budget: float = 1.0
    """The longest a team may take to decide one step (under :data:`SERVER_WAIT_SECONDS`,
    leaving time to send)."""


@dataclass
class Step:
    """What one step brought the team."""

    step: int
    """The client's own counter: 0 at the first step, +1 every step."""
    server_time: int
    """The server's clock (``sense_body``'s time)."""
    inboxes: dict[int, list[Message]]
    """Each connected player's row -> its parsed messages of the step (``(think)`` left out)."""
    views: PlayerViews
    coach_messages: list[str] = field(default_factory=list)
    """What the online coach received this step (texts)."""
    missed: int = 0
    """Server steps that went by since the last step without this team's ``(done)`` (the
    server waited for it in vain, or the team was still connecting)."""

    @property
    def over(self) -> bool:
        """Whether the match is over (``time_over``)."""
        return self.views.play_mode == PlayMode.TIME_OVER


Decide = Callable[[Step, int], PlayerOrder]
"""A team's decision: the order for the player in the given row at the given step."""


class TeamClient:
    """One team in the server (module docstring). Use as a context manager, or call
    :meth:`close`: every connection says ``(bye)``."""

    def __init__(self, team_name: str, settings: ClientSettings = ClientSettings(),
                 recorder: Recorder | None = None) -> None:
        if not team_name or any(c in team_name for c in ' ()"'):
            raise BridgeError(f"team name {team_name!r} must be non-empty, without spaces, parentheses or quotes")
        self.team_name = team_name
        self.settings = settings
        self._recorder = recorder
        self.players: dict[int, Connection] = {}
        """Row (shirt number - 1) -> the player's connection."""
        self.coach: Connection | None = None
        self.side = ""
        self.parameters: ServerParameters | None = None
        self.config: MatchConfig | None = None
        self.views: ViewsBuilder | None = None
        self.translator: CommandTranslator | None = None
        """The team's command translation (:mod:`rcss_bridge.commands`), made at :meth:`connect`."""
        self.step = -1
        self.server_time = 0
        self._worker: _DecisionWorker | None = None
        self._carry: dict[int, list[Message]] = {}
        """Per row, messages received after its last ``(think)``: the next step's."""

    def __enter__(self) -> TeamClient:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # ------------------------------------------------------------------------------ connect
    def connect(self) -> None:
        """Connect the players and the coach and read the server's parameters (the bridge's
        own compiled kernel is loaded first: nothing may compile once the server waits)."""
        warm_up()
        warm_up_commands()
        s = self.settings
        order = [s.goalie] + [row for row in range(s.players) if row != s.goalie]
        order = order[: s.players if s.connect is None else s.connect]
        try:
            for row in order:
                goalie = " (goalie)" if row == s.goalie else ""
                init = f"(init {self.team_name} (version {PROTOCOL_VERSION}){goalie})"
                conn = Connection.open(f"{self.team_name}-{row + 1}", s.host, s.port, init, s.connect_timeout,
                                       self._recorder)
                unum = conn.reply.unum
                if unum is None or not 1 <= unum <= s.players or unum - 1 in self.players:
                    conn.close()
                    raise ServerError(f"{conn.name}: the server gave shirt number {unum}, not one of the team's")
                conn.name = f"{self.team_name}-{unum}"
                self.players[unum - 1] = conn
                self.side = conn.reply.side
            if s.coach_port is not None:
                self.coach = Connection.open(f"{self.team_name}-coach", s.host, s.coach_port,
                                             f"(init {self.team_name} (version {PROTOCOL_VERSION}))",
                                             s.connect_timeout, self._recorder)
            self.parameters = self._read_parameters(self.players[s.goalie])
            self.config = self.parameters.match_config()
            first = self.players[s.goalie].reply
            self.views = ViewsBuilder(self.team_name, self.side, s.players,
                                      [t.player_decay for t in self.parameters.types], s.goalie,
                                      first.play_mode or "before_kick_off")
            self.translator = CommandTranslator(self.team_name, s.players,
                                                ServerRules.from_server(self.parameters.server),
                                                self.parameters.types, self.config, s.goalie)
            for conn in self.players.values():
                conn.send("(synch_see)")
        except BaseException:
            self.close()
            raise

    def _read_parameters(self, conn: Connection) -> ServerParameters:
        """The parameters from the messages that follow ``conn``'s init reply."""
        texts: dict[str, list[str]] = {"server_param": [], "player_param": [], "player_type": []}
        deadline = time.monotonic() + self.settings.connect_timeout
        expected = None
        while True:
            for text in conn.receive():
                kind = head(text)
                if kind in texts:
                    texts[kind].append(text)
                else:
                    conn.early.append(text)
            if texts["player_param"] and expected is None:
                expected = int(float(_value(texts["player_param"][0], "player_types")))
            if texts["server_param"] and expected is not None and len(texts["player_type"]) >= expected:
                return ServerParameters.from_messages(texts["server_param"][0], texts["player_param"][0],
                                                      texts["player_type"])
            if time.monotonic() > deadline:
                raise ServerError(f"{conn.name}: the server's parameters did not all arrive within "
                                  f"{self.settings.connect_timeout:g} s")
            select.select([conn.sock], [], [], 0.05)

    # ------------------------------------------------------------------------------ steps
    def next_step(self) -> Step:
        """Wait for every player's ``(think)`` and return the step (a :class:`ServerError`
        naming the players still waiting when it does not come within ``step_timeout``).

        Everything already waiting is read too: when the server went on without this team's
        ``(done)`` (a step it waited for in vain, or the steps before kick-off while the team
        was connecting), a player has several ``(think)`` queued, and the step is the last of
        them, so the team never decides on a stale step (:attr:`Step.missed` counts them)."""
        if self.views is None:
            raise BridgeError("connect() first")
        self.step += 1
        rows = sorted(self.players)
        received: dict[int, list[Message]] = {row: [] for row in rows}
        thinks = dict.fromkeys(rows, 0)

        def take(row: int, texts: Sequence[str] | None = None) -> None:
            conn = self.players[row]
            for message in _read_all(conn.receive() if texts is None else texts, conn.name):
                if isinstance(message, Think):
                    thinks[row] += 1
                    received[row].extend(self._carry[row])
                    self._carry[row] = []
                else:
                    self._carry[row].append(message)

        for row in rows:
            self.players[row].step = self.step
            self._carry.setdefault(row, [])
            take(row, self.players[row].early)  # what arrived while connecting
            self.players[row].early.clear()
        deadline = time.monotonic() + self.settings.step_timeout
        while waiting := [row for row in rows if thinks[row] == 0]:
            socks = {self.players[row].sock: row for row in waiting}
            ready, _, _ = select.select(list(socks), [], [], max(deadline - time.monotonic(), 0.0))
            if not ready:
                shirts = ", ".join(str(row + 1) for row in waiting)
                raise ServerError(f"team {self.team_name!r}: no (think) for shirt(s) {shirts} at step {self.step} "
                                  f"within {self.settings.step_timeout:g} s (server time {self.server_time}): "
                                  "the server stopped or left")
            for sock in ready:
                take(socks[sock])
        for row in rows:
            take(row)
        times = [m.time for box in received.values() for m in box if isinstance(m, SenseBody)]
        self.server_time = max(times, default=self.server_time)
        coach_messages: list[str] = []
        if self.coach is not None:
            self.coach.step = self.step
            coach_messages = self.coach.receive()
        views = self.views.update(self.step, received)
        return Step(self.step, self.server_time, received, views, coach_messages, max(thinks.values()) - 1)

    def send_step(self, orders: Mapping[int, PlayerOrder]) -> None:
        """Send each connected player its order and ``(done)`` in one datagram (a player
        without an order sends ``(done)`` alone). A say is checked as the simulator checks
        one (:func:`soccer_sim.perception.audio.check_message`) and sent quoted."""
        for row, datagram in self._datagrams(orders).items():
            self.players[row].send(datagram)

    def _datagrams(self, orders: Mapping[int, PlayerOrder]) -> dict[int, str]:
        """Each connected player's datagram (:func:`command_datagram`)."""
        audio = self.config.observation.audio if self.config is not None else AudioParams()
        return {row: command_datagram(orders.get(row, PlayerOrder()), audio, self.team_name, row)
                for row in self.players}

    def send_command(self, step: Step, command: TeamCommand, ball: np.ndarray | None = None) -> None:
        """Send the team's ``command`` for ``step`` (:class:`~soccer_sim.team.TeamCommand`,
        team frame) as each player's one body command, ``turn_neck`` and say
        (:class:`~rcss_bridge.commands.CommandTranslator`). ``ball``: where each player
        believes the ball is ((n, 2), team frame; None: where it saw it this step). A command
        the bridge cannot translate, or a say the server would not take, is a
        :class:`TeamFailure` naming the player and the step."""
        if self.translator is None or self.views is None:
            raise BridgeError("connect() first")
        try:
            bodies = PlayerBodies.from_views(step.views, self.views.necks, ball, self.views.ball_unseen)
            orders = self.translator.translate(command, bodies, self.views.referee.server_mode)
            datagrams = self._datagrams(orders)
            self.views.turned(self.translator.turns)
        except (CommandError, TeamError) as exc:
            raise TeamFailure(self.team_name, exc.player, step.step, step.server_time,
                              f"bad command: {exc.message}") from exc
        for row, datagram in datagrams.items():
            self.players[row].send(datagram)

    def choose_player_types(self, choice: Sequence[int]) -> None:
        """Give the players the types of a team's ``choose_player_types`` (type ids by row,
        of the server's types) through the online coach, one ``(change_player_type UNUM
        TYPE)`` per player (:func:`~rcss_bridge.commands.player_type_commands`); a
        :class:`~rcss_bridge.errors.CommandError` for a choice the server would refuse."""
        if self.parameters is None or self.config is None:
            raise BridgeError("connect() first")
        for text in player_type_commands(choice, self.parameters.types, self.settings.players,
                                         self.config.player_types.pt_max, self.team_name):
            self.coach_command(text)

    def coach_command(self, text: str) -> None:
        """Send one command of the online coach (``(change_player_type 2 5)``)."""
        if self.coach is None:
            raise BridgeError("this team has no online coach (ClientSettings.coach_port is None)")
        self.coach.send(text)

    def play(self, decide: Decide, steps: int | None = None, on_step: Callable[[Step], None] | None = None) -> int:
        """Run the match: each step ``decide(step, row)`` for every connected player in row
        order (in a worker thread, within ``decision_budget``), then :meth:`send_step`, until
        ``time_over`` or ``steps`` steps; returns the steps played. A decision that raises
        or overruns ends the match with :class:`TeamFailure` / :class:`TeamTooSlow` naming
        the player and the step (the connections say ``(bye)``)."""
        worker = self._worker = self._worker or _DecisionWorker()
        played = 0
        try:
            while steps is None or played < steps:
                step = self.next_step()
                if on_step is not None:
                    on_step(step)
                if step.over:
                    break
                orders = self._decide(worker, step, decide)
                try:
                    datagrams = self._datagrams(orders)
                except TeamError as exc:  # command_datagram names the player
                    raise TeamFailure(self.team_name, exc.player if exc.player is not None else -1, step.step,
                                      step.server_time, f"bad order: {exc.message}") from exc
                for row, datagram in datagrams.items():
                    self.players[row].send(datagram)
                played += 1
        except BaseException:
            self.close()
            raise
        return played

    def _decide(self, worker: _DecisionWorker, step: Step, decide: Decide) -> dict[int, PlayerOrder]:
        rows = sorted(self.players)
        try:
            return worker.run(step, rows, decide, self.settings.decision_budget)
        except _Overran as over:
            raise TeamTooSlow(self.team_name, over.row, step.step, step.server_time,
                              f"deciding took longer than {self.settings.decision_budget:g} s (the server waits "
                              f"{SERVER_WAIT_SECONDS:g} s for a step)") from None
        except _Raised as raised:
            error = raised.error
            raise TeamFailure(self.team_name, raised.row, step.step, step.server_time,
                              f"the decision raised {type(error).__name__}: {error}") from error

    def close(self) -> None:
        """Every connection says ``(bye)`` and closes (again: nothing)."""
        for conn in list(self.players.values()) + ([self.coach] if self.coach is not None else []):
            conn.close()
        if self._worker is not None:
            self._worker.stop()
            self._worker = None


def command_datagram(order: PlayerOrder, audio: AudioParams = AudioParams(), team_name: str = "?",
                     row: int | None = None) -> str:
    """One player's datagram for a step: its commands, its say quoted, then ``(done)``. The
    commands must not say or end the step themselves, and the message must be one the server
    accepts (each a :class:`~soccer_sim.team.TeamError` naming the player)."""
    commands = order.commands.strip()
    if "(say" in commands or "(done" in commands or "(bye" in commands:
        raise TeamError(team_name, f"commands {commands!r} may not contain say, done or bye (the say goes "
                        "in PlayerOrder.say)", row)
    if order.say is not None:
        check_message(order.say, audio, team_name, row)
        commands += f'(say "{order.say}")'
    return commands + "(done)"


def _read_all(texts: Sequence[str], name: str) -> list[Message]:
    """The records of ``texts``; a message the bridge cannot read names the connection."""
    out: list[Message] = []
    for text in texts:
        try:
            out.append(read_message(text))
        except ProtocolError as exc:
            raise ProtocolError(f"{name}: {exc}") from None
    return out


def _value(text: str, name: str) -> str:
    """The value of ``(name value)`` inside a parameter message."""
    start = text.find(f"({name} ")
    if start < 0:
        raise ProtocolError(f"no {name} in {text[:60]!r}...")
    return text[start + len(name) + 2: text.index(")", start)]


class _Overran(Exception):
    def __init__(self, row: int) -> None:
        self.row = row


class _Raised(Exception):
    def __init__(self, row: int, error: BaseException) -> None:
        self.row, self.error = row, error


class _DecisionWorker:
    """Runs a step's decisions in a daemon thread, so that a decision that never returns
    cannot hang the client: the caller stops waiting after the budget and knows which
    player was being decided (the thread is abandoned; the client is closed)."""

    def __init__(self) -> None:
        self._jobs: queue.Queue = queue.Queue()
        self._results: queue.Queue = queue.Queue()
        self.current = -1
        self._thread = threading.Thread(target=self._loop, name="rcss-bridge-decisions", daemon=True)
        self._thread.start()

    def run(self, step: Step, rows: list[int], decide: Decide, budget: float) -> dict[int, PlayerOrder]:
        self._jobs.put((step, rows, decide))
        try:
            orders, row, error = self._results.get(timeout=budget)
        except queue.Empty:
            raise _Overran(self.current) from None
        if error is not None:
            raise _Raised(row, error)
        return orders

    def _loop(self) -> None:
        while True:
            job = self._jobs.get()
            if job is None:
                return
            step, rows, decide = job
            orders: dict[int, PlayerOrder] = {}
            try:
                for row in rows:
                    self.current = row
                    order = decide(step, row)
                    if not isinstance(order, PlayerOrder):
                        raise TeamError("?", f"decide must return a PlayerOrder, got {type(order).__name__}", row)
                    orders[row] = order
                self._results.put((orders, -1, None))
            except BaseException as exc:  # noqa: BLE001 - every failure of a team's code is reported
                self._results.put((None, self.current, exc))

    def stop(self) -> None:
        self._jobs.put(None)
