"""rcssserver's ``say`` / ``hear`` channel between the players of a match.

The rules, all from rcssserver (file and parameter names cited so they can be checked):

* **Say.** A player says at most one message per cycle (soccer-sim's command carries one per
  player). rcssserver's parser (``player.cpp``, the ``(say ...`` branch) accepts only the
  characters of the ``sscanf`` set ``[-0-9a-zA-Z ().+*/?<>_]`` (:data:`SAY_CHARACTERS`), at
  least one of them, and ``Player::say`` drops a message longer than ``say_msg_size``. The
  server ignores such a message silently; here it is a :class:`~soccer_sim.team.TeamError`
  naming the team, the player and what is wrong, so a team's bug cannot go unnoticed.
* **Who receives it.** ``Stadium::sendPlayerAudio`` offers the message to every player at the
  moment it is said; ``AudioSenderPlayerv8::nonSelfPlayerPredicate`` keeps it for listeners
  within ``audio_cut_dist`` of the speaker (``distance2 <= audio_cut_dist ** 2``, positions
  of the cycle it is said in), team-mates and opponents alike. The cached messages are sent
  at the start of the next cycle (``AudioSenderPlayerv8::newCycle``): said at cycle ``t``,
  heard at ``t + 1``. The speaker gets its own message back as ``(hear t self ...)``
  (``sendSelfAudio``), which costs no capacity.
* **How many are heard.** Each player has two integer capacities, for team-mates and for
  opponents (``player.cpp``: ``M_hear_capacity_from_teammate`` / ``_opponent``), starting at
  ``hear_max``; each cycle both grow by ``hear_inc`` up to ``hear_max``
  (``Player::updateCapacity``, before the delivery). At delivery the cached messages are
  taken in a uniformly random order (``Unfocused::getMsg``: ``irand`` over what is left); one
  is heard in full when the capacity of its speaker's side is at least ``hear_decay``
  (``canHearFullFrom``), which then drops by ``hear_decay`` (``decrementHearCapacity``); the
  others are lost (the partial ``(hear t our unum)`` notices are off by default). With the
  defaults (1, 1, 1) a player hears one team-mate and one opponent per cycle, each chosen
  uniformly among those in range who spoke. A listener may attend to one player
  (``attentionto``; ``Focused::getMsg``): that player's message is then taken first.
* **The hear message** names a team-mate speaker's number but not an opponent's
  (``serializeAllyAudioFull`` / ``serializeOppAudioFull``); :meth:`Heard.for_listener` keeps
  that asymmetry. Both give the speaker's direction from the listener's body at delivery in
  whole degrees (``Rad2IDeg``, truncated): :attr:`Heard.direction`.

The random order is drawn from the ``numpy.random.Generator`` the caller passes, one uniform
per (listener, speaker) pair on every delivery, so the stream never depends on who spoke.
Everything is vectorised over listeners x speakers (22 x 22 at most).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from soccer_sim.config_checks import ConfigError
from soccer_sim.config_ranges import check_ranges
from soccer_sim.perception.coded import SILENT_CODE, CodedMessages, allowed_codes, first_bad_row
from soccer_sim.perception.audio_kernels import arrivals, choose_heard, join_said
from soccer_sim.team import TeamError

SAY_CHARACTERS: str = ("-0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                       " ().+*/?<>_")
"""The characters rcssserver's ``say`` parser accepts (``player.cpp``: the ``sscanf`` set
``[-0-9a-zA-Z ().+*/?<>_]``): 74 characters."""


@dataclass(frozen=True)
class AudioParams:
    """The say/hear channel's parameters; every default is rcssserver's (``serverparam.cpp``)."""

    say_msg_size: int = 10
    """``say_msg_size`` (characters): the longest message a player may say."""
    audio_cut_dist: float = 50.0
    """``audio_cut_dist`` (m; ``AUDIO_CUT_OFF_DIST``): a message reaches only listeners at most
    this far from the speaker when it is said."""
    hear_max: int = 1
    """``hear_max``: the most hearing capacity a player holds per side (team-mates, opponents)."""
    hear_inc: int = 1
    """``hear_inc``: capacity regained per cycle per side (never above ``hear_max``)."""
    hear_decay: int = 1
    """``hear_decay``: capacity one message heard in full costs; a message is heard only while
    the capacity is at least this (0: unlimited hearing)."""
    characters: str = SAY_CHARACTERS
    """The characters a message may use (:data:`SAY_CHARACTERS`, the server's set)."""

    def __post_init__(self) -> None:
        if not isinstance(self.characters, str) or not self.characters:
            raise ConfigError(f"AudioParams.characters must be a non-empty str, got {self.characters!r}")
        check_ranges(self)  # every number against its range (soccer_sim.config_ranges)


def check_message(message: object, params: AudioParams = AudioParams(), team_name: str = "?",
                  player: int | None = None) -> None:
    """Raise :class:`TeamError` (naming ``team_name`` and ``player``) unless ``message`` is a
    message the server accepts: a non-empty ``str`` of at most ``say_msg_size`` characters,
    all from ``params.characters``. ``None`` (saying nothing) is not a message: check it first."""
    if not isinstance(message, str):
        raise TeamError(team_name, f"say message must be a str or None, got {type(message).__name__}", player)
    if not message:
        raise TeamError(team_name, "say message is empty (say None to say nothing)", player)
    if len(message) > params.say_msg_size:
        raise TeamError(team_name, f"say message {_echo(message)} has {len(message)} characters, more than "
                                   f"say_msg_size {params.say_msg_size}", player)
    bad = sorted(set(message) - set(params.characters))
    if bad:
        raise TeamError(team_name, f"say message {_echo(message)} has characters the server refuses: "
                                   f"{_echo(''.join(bad))} (allowed: {params.characters!r})", player)


ECHOED_CHARACTERS = 20
"""How much of a refused message its error repeats: enough to recognise it, never a screenful
(a message of a thousand escape characters would print four thousand)."""


def _echo(text: str) -> str:
    """``text`` quoted as Python writes it (control characters escaped: one line), cut to its
    first :data:`ECHOED_CHARACTERS` characters with the count of the rest."""
    if len(text) <= ECHOED_CHARACTERS:
        return repr(text)
    return f"{text[:ECHOED_CHARACTERS]!r}... (+{len(text) - ECHOED_CHARACTERS} more)"


def check_team_messages(messages: Sequence[str | None], size: int, params: AudioParams = AudioParams(),
                        team_name: str = "?", allowed: frozenset[str] | None = None) -> None:
    """Raise :class:`TeamError` unless ``messages`` holds ``size`` entries, each None or a
    message :func:`check_message` accepts (the usual good message passes a fast test first;
    ``allowed``: ``frozenset(params.characters)``, given by callers that check every cycle;
    a :class:`~soccer_sim.perception.coded.CodedMessages` goes to :func:`check_coded_messages`)."""
    if type(messages) is CodedMessages:
        check_coded_messages(messages, size, params, team_name)
        return
    if len(messages) != size:
        raise TeamError(team_name, f"{len(messages)} say messages for {size} players")
    limit = params.say_msg_size
    allowed = frozenset(params.characters) if allowed is None else allowed
    said = [msg for msg in messages if msg is not None]
    if all(type(msg) is str and 0 < len(msg) <= limit for msg in said) and allowed.issuperset("".join(said)):
        return  # (every cycle: the usual good messages at once)
    for i, msg in enumerate(messages):
        if msg is not None and not (type(msg) is str and 0 < len(msg) <= limit and allowed.issuperset(msg)):
            check_message(msg, params, team_name, i)


def check_coded_messages(messages: CodedMessages, size: int, params: AudioParams = AudioParams(),
                         team_name: str = "?") -> None:
    """:func:`check_team_messages` for messages held as codes: one look-up per character in the
    table of ``params.characters`` (:func:`~soccer_sim.perception.coded.allowed_codes`)."""
    if len(messages) != size:
        raise TeamError(team_name, f"{len(messages)} say messages for {size} players")
    speaks = messages.speaks
    if 0 < messages.width <= params.say_msg_size:
        bad = first_bad_row(messages.codes, speaks, allowed_codes(params.characters))
    else:  # (every message of this width is refused: the first speaker's)
        bad = int(np.argmax(speaks)) if speaks.any() else -1
    if bad >= 0:
        check_message(messages[bad], params, team_name, bad)  # (raises, saying what is wrong)


@dataclass(frozen=True)
class Heard:
    """What every player hears at ``cycle`` (messages said at ``cycle - 1``). Players are
    numbered across the match: the first team's ``0 .. n0 - 1``, then the second team's."""

    cycle: int
    """The cycle the messages are heard in."""
    messages: tuple[str | None, ...]
    """The message each player said at ``cycle - 1`` (None: said nothing)."""
    arrived: np.ndarray
    """(listeners, speakers) bool: the message reached the listener (within
    ``audio_cut_dist``; never the speaker itself)."""
    heard: np.ndarray
    """(listeners, speakers) bool: heard in full (a subset of ``arrived`` within capacity)."""
    team: np.ndarray
    """(players,) int: each player's team (0 or 1)."""
    direction: np.ndarray | None = None
    """(listeners, speakers) whole degrees: where each heard speaker is, relative to the
    listener's body direction, at delivery (``Rad2IDeg(angleFromBody)``: truncated towards
    zero, in (-180, 180]); NaN where nothing was heard; None when :meth:`AudioChannel.hear`
    got no positions."""

    def for_listener(self, listener: int) -> tuple[tuple[tuple[int, str], ...], tuple[str, ...], str | None]:
        """What ``listener`` hears, as the server reports it: the team-mates' messages as
        ``(speaker's index within the team, message)`` pairs, the opponents' messages (speaker
        not named), and its own message (``self``; None if it said nothing)."""
        team = self.team
        first = int(np.count_nonzero(team < team[listener]))
        mates: list[tuple[int, str]] = []
        opponents: list[str] = []
        for s in np.flatnonzero(self.heard[listener]).tolist():
            msg = self.messages[s]
            assert msg is not None
            if team[s] == team[listener]:
                mates.append((s - first, msg))
            else:
                opponents.append(msg)
        return tuple(mates), tuple(opponents), self.messages[listener]


class AudioChannel:
    """The say/hear channel of one match (module docstring for the rules).

    Per cycle ``t``: :meth:`hear` ``(t, ...)`` delivers what was said at ``t - 1``, then
    :meth:`say` ``(t, ...)`` records what the players say at ``t``, with their positions at
    ``t`` (m, one frame for both teams)."""

    def __init__(self, team_sizes: tuple[int, int], team_names: tuple[str, str] = ("home", "away"),
                 params: AudioParams = AudioParams()) -> None:
        sizes = tuple(int(n) for n in team_sizes)
        if len(sizes) != 2 or any(n < 0 or n > 11 for n in sizes):
            raise ValueError(f"AudioChannel: team_sizes must be two numbers of players 0..11, got {team_sizes!r}")
        self.params = params
        self.team_sizes = sizes
        self.team_names = tuple(team_names)
        self.team = np.repeat(np.array([0, 1], dtype=np.int64), sizes)
        n = len(self.team)
        self._cap = np.full((n, 2), params.hear_max, dtype=np.int64)  # [:, 0] team-mates, [:, 1] opponents
        self._cap_cycle: int | None = None
        self._said_cycle: int | None = None
        self._messages: Sequence[str | None] = (None,) * n
        self._arrived = np.zeros((n, n), dtype=bool)
        self._spoke = False
        """Whether anybody said anything in the last say."""
        self._allowed = frozenset(params.characters)

    @property
    def players(self) -> int:
        """Players of both teams (rows of ``positions``)."""
        return len(self.team)

    def reset_capacity(self) -> None:
        """Refill every capacity to ``hear_max`` (rcssserver's ``Player::recoverAll``, at
        half time)."""
        self._cap[:] = self.params.hear_max

    def say(self, cycle: int, messages: Sequence[Sequence[str | None]], positions: np.ndarray,
            checked: bool = False) -> None:
        """Record what the players say at ``cycle``: ``messages[k][i]`` is player ``i`` of team
        ``k``'s message or None; ``positions`` (players, 2) m at ``cycle``. A bad message is a
        :class:`TeamError` naming its team and player. ``checked``: the caller has checked the
        messages (:func:`check_team_messages`) and vouches for the positions (a match checks the
        messages as it reads the commands, and the positions are its own state), so neither is
        checked twice."""
        if self._said_cycle is not None and cycle <= self._said_cycle:
            raise ValueError(f"AudioChannel.say: cycle {cycle} is not after the last say cycle {self._said_cycle}")
        if len(messages) != 2:
            raise ValueError(f"AudioChannel.say: messages must hold one sequence per team (2), got {len(messages)}")
        if not checked:
            for k, (team_msgs, size) in enumerate(zip(messages, self.team_sizes)):
                check_team_messages(team_msgs, size, self.params, self.team_names[k], self._allowed)
        pos = np.asarray(positions, dtype=np.float64)
        if pos.shape != (self.players, 2) or not (checked or np.all(np.isfinite(pos))):
            raise ValueError(f"AudioChannel.say: positions must be finite, shape ({self.players}, 2); got {pos.shape}")
        self._said_cycle = int(cycle)
        coded = _as_coded_pair(messages)
        if coded is not None:  # (the usual case: one compiled call)
            first, second = coded
            n = self.players
            codes, speaks = np.empty((n, first.width), dtype=np.uint8), np.empty(n, dtype=bool)
            self._arrived = np.empty((n, n), dtype=bool)
            self._spoke = join_said(first.codes, first.speaks, second.codes, second.speaks, pos,
                                    float(self.params.audio_cut_dist), SILENT_CODE, codes, speaks, self._arrived)
            self._messages = CodedMessages.of_arrays(codes, speaks)
            return
        flat: list[str | None] = []
        for team_msgs in messages:
            flat.extend(team_msgs)
        self._messages = tuple(flat)
        spoke = np.array([m is not None for m in flat], dtype=bool)
        self._spoke = bool(np.count_nonzero(spoke))
        if not self._spoke:  # a silent cycle: nothing arrives anywhere
            self._arrived = np.zeros((self.players, self.players), dtype=bool)
            return
        self._arrived = np.empty((self.players, self.players), dtype=bool)
        arrivals(pos, spoke, float(self.params.audio_cut_dist), self._arrived)

    def hear(self, cycle: int, rng: np.random.Generator, attention: np.ndarray | None = None,
             positions: np.ndarray | None = None, body_dirs: np.ndarray | None = None) -> Heard:
        """Deliver at ``cycle`` what was said at ``cycle - 1`` (anything older is lost, as the
        server delivers every cycle), after regaining ``hear_inc`` capacity per cycle since the
        last delivery. ``attention[l]`` (players,) is the player listener ``l`` attends to
        (-1: none). With ``positions`` (players, 2) m and ``body_dirs`` (players,) degrees at
        ``cycle``, :attr:`Heard.direction` says where each heard speaker is. Draws one uniform per
        (listener, speaker) from ``rng``."""
        arrived, heard, messages = self.deliver(cycle, rng, attention)
        direction = None
        if positions is not None or body_dirs is not None:
            direction = self._directions(heard, positions, body_dirs)
        return Heard(cycle=int(cycle), messages=tuple(messages), arrived=arrived, heard=heard, team=self.team,
                     direction=direction)

    def deliver(self, cycle: int, rng: np.random.Generator,
                attention: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray, Sequence[str | None]]:
        """:meth:`hear`'s delivery without its :class:`Heard` record (a match's every-cycle
        path): the ``arrived`` and ``heard`` (listeners, speakers) bool arrays and the messages
        said at ``cycle - 1``, one per player (None: said nothing; a
        :class:`~soccer_sim.perception.coded.CodedMessages` when both teams said theirs so)."""
        p = self.params
        n = self.players
        cap = self._cap
        regained = 0
        if self._cap_cycle is not None:
            if cycle <= self._cap_cycle:
                raise ValueError(f"AudioChannel.hear: cycle {cycle} is not after the last hear cycle {self._cap_cycle}")
            regained = p.hear_inc * (cycle - self._cap_cycle)
        self._cap_cycle = int(cycle)
        key = rng.random((n, n))
        current = self._said_cycle == cycle - 1
        arrived = self._arrived if current else np.zeros((n, n), dtype=bool)
        messages = self._messages if current else (None,) * n
        if attention is not None:
            att = np.asarray(attention, dtype=np.int64).reshape(-1)
            if att.shape != (n,) or np.any((att < -1) | (att >= n)):
                raise ValueError(f"AudioChannel.hear: attention must be {n} player indices or -1")
            rows = np.flatnonzero(att >= 0)
            key[rows, att[rows]] = -1.0  # taken before every other message
        heard = np.zeros((n, n), dtype=bool)
        choose_heard(arrived, key, self.team, cap, regained, p.hear_max, p.hear_decay, current and self._spoke, heard)
        return arrived, heard, messages

    def _directions(self, heard: np.ndarray, positions: np.ndarray | None,
                    body_dirs: np.ndarray | None) -> np.ndarray:
        """Whole degrees from each listener's body to each heard speaker (NaN elsewhere)."""
        n = self.players
        pos = np.asarray(positions, dtype=np.float64) if positions is not None else None
        body = np.asarray(body_dirs, dtype=np.float64).reshape(-1) if body_dirs is not None else None
        if pos is None or pos.shape != (n, 2) or body is None or body.shape != (n,) \
                or not np.all(np.isfinite(pos)) or not np.all(np.isfinite(body)):
            raise ValueError(f"AudioChannel.hear: positions ({n}, 2) m and body_dirs ({n},) degrees must "
                             "both be given, finite")
        diff = pos[None, :, :] - pos[:, None, :]
        rel = np.degrees(np.arctan2(diff[..., 1], diff[..., 0])) - body[:, None]
        rel = 180.0 - (180.0 - rel) % 360.0  # folded into (-180, 180]
        return np.where(heard, np.trunc(rel), np.nan)


def _as_coded_pair(messages: Sequence[Sequence[str | None]]) -> tuple[CodedMessages, CodedMessages] | None:
    """Both teams' messages as two :class:`CodedMessages` of one width, the channel's stored
    form, when each team gave one of a common width, or one gave one and the other says
    nothing; else None (the messages are kept as texts)."""
    first, second = messages
    if type(first) is CodedMessages and type(second) is CodedMessages:
        return (first, second) if first.width == second.width else None
    coded, other = (first, second) if type(first) is CodedMessages else (second, first)
    if type(coded) is not CodedMessages or any(m is not None for m in other):
        return None
    silent = CodedMessages.of_arrays(np.empty((len(other), coded.width), dtype=np.uint8),
                                     np.zeros(len(other), dtype=bool))
    return (coded, silent) if coded is first else (silent, coded)
