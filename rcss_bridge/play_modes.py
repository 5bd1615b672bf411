"""The referee as a player hears it: rcssserver's play modes and calls mapped to the
project's :class:`~soccer_sim.state.PlayMode`, with the half and the score.

Every player hears the referee (``(hear T referee MESSAGE)``) whenever the play mode changes
and at some events; ``init`` tells the mode at connection. :class:`RefereeState` follows
those messages for one team (its side ``l`` or ``r``) and says, in the project's terms, the
play mode, whether it is this team's (``mode_ours``), the half and the score (ours, theirs).

:data:`MODE_MAP` is the one table from the server's modes to the project's, with who owns
the set play: ``"same"`` the side in the mode's name, ``"other"`` its opponents (a foul,
an offside, a back pass by ``l`` gives ``r`` the free kick). Referee calls that are not
modes: ``goal_X_N`` (side X has N goals: the mode becomes ``goal_X``), ``goalie_catch_ball_X``
(X's goalkeeper holds the ball: the free kick the server then gives X is
:attr:`PlayMode.GOALIE_HOLDS` until play goes on), ``half_time`` (the next half begins
with ``before_kick_off``; the sides do not swap: measured, ``docs/bridge.md``),
``yellow_card_X_U`` / ``red_card_X_U``, ``time_up``, ``time_extended`` and the like, kept
as :attr:`RefereeState.last_call`. ``before_kick_off`` belongs to the side that kicks off
the half: left in the first half (and third), right in the second.
"""

from __future__ import annotations

import re

from soccer_sim.state import PlayMode

from rcss_bridge.errors import ProtocolError

MODE_MAP: dict[str, tuple[PlayMode, str | None]] = {
    "before_kick_off": (PlayMode.KICK_OFF, "half"),
    "time_over": (PlayMode.TIME_OVER, None),
    "play_on": (PlayMode.PLAY_ON, None),
    "drop_ball": (PlayMode.PLAY_ON, None),
    "first_half_over": (PlayMode.KICK_OFF, "half"),
    "pause": (PlayMode.TIME_OVER, None),
    "human_judge": (PlayMode.TIME_OVER, None),
    "kick_off": (PlayMode.KICK_OFF, "same"),
    "kick_in": (PlayMode.KICK_IN, "same"),
    "free_kick": (PlayMode.FREE_KICK, "same"),
    "indirect_free_kick": (PlayMode.FREE_KICK, "same"),
    "corner_kick": (PlayMode.CORNER_KICK, "same"),
    "goal_kick": (PlayMode.GOAL_KICK, "same"),
    "goal": (PlayMode.AFTER_GOAL, "other"),
    "offside": (PlayMode.FREE_KICK, "other"),
    "foul_charge": (PlayMode.FREE_KICK, "other"),
    "foul_push": (PlayMode.FREE_KICK, "other"),
    "foul_multiple_attack": (PlayMode.FREE_KICK, "other"),
    "foul_ballout": (PlayMode.FREE_KICK, "other"),
    "back_pass": (PlayMode.FREE_KICK, "other"),
    "free_kick_fault": (PlayMode.FREE_KICK, "other"),
    "catch_fault": (PlayMode.FREE_KICK, "other"),
    "illegal_defense": (PlayMode.FREE_KICK, "other"),
    "penalty_kick": (PlayMode.FREE_KICK, "same"),
    "penalty_setup": (PlayMode.FREE_KICK, "same"),
    "penalty_ready": (PlayMode.FREE_KICK, "same"),
    "penalty_taken": (PlayMode.FREE_KICK, "same"),
    "penalty_miss": (PlayMode.FREE_KICK, "other"),
    "penalty_score": (PlayMode.FREE_KICK, "other"),
}
"""rcssserver's play mode (without its ``_l`` / ``_r``) -> (the project's mode, whose it is:
``"same"`` the side named, ``"other"`` its opponents, ``"half"`` the side kicking off this
half, None nobody's)."""

_SIDED = re.compile(r"^(.*)_([lr])(?:_(\d+))?$")
"""``kick_in_l``, ``goal_r_2``, ``yellow_card_l_5``: a name, a side and a number."""

CARDS = ("yellow_card", "red_card")
"""Referee calls that name a player (``yellow_card_l_5``) without changing the mode."""


def other(side: str) -> str:
    """The other side's letter."""
    return "r" if side == "l" else "l"


class RefereeState:
    """One team's reading of the referee (module docstring). ``side``: ``"l"`` or ``"r"``."""

    def __init__(self, side: str, mode: str = "before_kick_off") -> None:
        if side not in ("l", "r"):
            raise ProtocolError(f"a team's side is 'l' or 'r', got {side!r}")
        self.side = side
        self.server_mode = "before_kick_off"
        """The server's current play mode (as named in its messages, ``goal_l`` for a goal)."""
        self.half = 0
        """0 for the first half, 1 for the second, 2.. for extra halves."""
        self.goals = {"l": 0, "r": 0}
        self.goalie_holds = False
        """This team's goalkeeper holds the ball (it caught it and play has not gone on)."""
        self.opponent_goalie_holds = False
        self.last_call = ""
        """The last referee message heard."""
        self.cards: list[tuple[str, str, int]] = []
        """(card, side, shirt number) of every card shown so far."""
        self.hear(mode)

    def hear(self, call: str) -> None:
        """Take in one referee message (or the mode of the ``init`` reply)."""
        self.last_call = call
        match = _SIDED.match(call)
        name, side, count = (match.group(1), match.group(2), match.group(3)) if match else (call, None, None)
        if name == "goalie_catch_ball" and side:
            self.goalie_holds = side == self.side
            self.opponent_goalie_holds = side != self.side
            return
        if name in CARDS and side and count:
            self.cards.append((name, side, int(count)))
            return
        if name == "half_time":
            self.half += 1
            return
        if name == "goal" and side and count:
            self.goals[side] = int(count)
            call = f"goal_{side}"
        if (name if side else call) not in MODE_MAP:
            return  # time_up, time_extended, penalty_winner_l, ...: no change of mode
        holder = self.side if self.goalie_holds else other(self.side) if self.opponent_goalie_holds else None
        if call != f"free_kick_{holder}":  # the free kick the server awards a catch keeps the hold
            self.goalie_holds = self.opponent_goalie_holds = False
        self.server_mode = call

    @property
    def _parts(self) -> tuple[str, str | None]:
        match = _SIDED.match(self.server_mode)
        if match and match.group(1) in MODE_MAP:
            return match.group(1), match.group(2)
        return self.server_mode, None

    @property
    def play_mode(self) -> PlayMode:
        """The project's play mode for the server's (:data:`MODE_MAP`)."""
        if self.goalie_holds or self.opponent_goalie_holds:
            return PlayMode.GOALIE_HOLDS
        name, _ = self._parts
        return MODE_MAP[name][0] if name in MODE_MAP else PlayMode.PLAY_ON

    @property
    def owner(self) -> str | None:
        """The side whose set play (or keeper's hold) it is; None for nobody's."""
        if self.goalie_holds:
            return self.side
        if self.opponent_goalie_holds:
            return other(self.side)
        name, side = self._parts
        rule = MODE_MAP.get(name, (PlayMode.PLAY_ON, None))[1]
        if rule == "half":
            return "l" if self.half % 2 == 0 else "r"
        if rule is None or side is None:
            return None
        return side if rule == "same" else other(side)

    @property
    def mode_ours(self) -> bool:
        """Whether the current set play belongs to this team."""
        return self.owner == self.side

    @property
    def score(self) -> tuple[int, int]:
        """(ours, theirs)."""
        return self.goals[self.side], self.goals[other(self.side)]
