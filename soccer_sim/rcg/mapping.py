"""How a soccer-sim match is told in rcssserver's terms: sides, coordinates, play modes,
player state flags.

**Sides and coordinates.** rcssserver's teams keep their sides for the whole match: the left
team attacks +x in both halves. Its y axis points down the monitor's screen (+y is to the
right of a left-team player facing the opponents' goal) and its angles, in degrees, turn
from +x towards +y. soccer-sim's home team is the left team; its absolute frame has +y up
the pictures, and, as in rcssserver 19, no team changes ends at half time. A position (x, y)
in soccer-sim's frame is (s x, -s y) in the log, with s = ``WorldState.home_attacks`` (+1
unless a scenario starts home attacking -x, when the field is turned by 180 degrees so that
home still attacks +x, as the tools expect of the left team): the y flip keeps the picture
as soccer-sim draws it. Velocities and directions turn the same way.

**Play modes.** See :func:`play_mode_name`; the referee's calls that rcssserver shows as a
play mode of their own before the restart (offside, back pass, foul charge, drop ball) come
from the match's events (:class:`soccer_sim.rcg.recorder.RcgRecorder`).

**Players off the field.** rcssserver lists all 11 players of each side in every show line;
one that is not on the field (never connected, or sent off) is shown where the server parks
it (:func:`parking_spot`).
"""

from __future__ import annotations

from soccer_sim.state import HOME, PlayMode

SIDES = ("l", "r")
"""rcssserver's side letters of home (left) and away (right)."""

# rcssserver's player state flags (its types.h), as a show line prints them in hex.
STAND = 0x1
"""Any player on the field."""
KICK = 0x2
"""The player kicked the ball in this cycle."""
GOALIE = 0x8
CATCH = 0x10
"""The goalkeeper caught the ball in this cycle."""
DISCARD = 0x100
"""Set with the red card when a player is sent off (rcssserver's ``Player::discard``)."""
BALL_COLLIDE = 0x400
"""The ball bounced off the player's body in this cycle."""
TACKLE = 0x1000
"""The player tackled and its success draw came out; with TACKLE_FAULT: in reach, but the
draw failed. Up for the ``tackle_cycles`` cycles the tackler is frozen (one cycle for a foul
tackle that pushed the ball, which does not freeze it)."""
TACKLE_FAULT = 0x2000
"""The tackle failed (alone: the ball was out of reach)."""
FOUL_CHARGED = 0x20000
"""The player is frozen by an opponent's foul tackle (``foul_cycles`` cycles)."""
YELLOW_CARD = 0x40000
"""The player has a yellow card."""
RED_CARD = 0x80000
"""The player was sent off (shown with DISCARD and without STAND)."""

MAX_PLAYER = 11
"""Players per side that a show line lists (rcssserver's ``MAX_PLAYER``)."""
PARKING_SPACING = 3.0
"""Metres between the spots where rcssserver parks a side's absent players."""
PARKING_OFFSET = 3.0
"""How far beyond the touch line (rcssserver's y < 0 side) absent players are parked."""

VIEW = "(v h 120)"
"""A connected player's default view (high quality, normal width) as rcssserver 19 logs it;
soccer-sim's players see the whole field, which no view mode of the server expresses."""
FOCUS_POINT = "(fp 0 0)"
"""The focus point (distance, direction) of a player that never moved it (rcssserver 19)."""

_SET_PLAY_NAMES = {
    PlayMode.KICK_OFF: "kick_off",
    PlayMode.KICK_IN: "kick_in",
    PlayMode.CORNER_KICK: "corner_kick",
    PlayMode.GOAL_KICK: "goal_kick",
    PlayMode.GOALIE_HOLDS: "free_kick",   # rcssserver: a catch gives the keeper's team a free kick
}


def side(team: int) -> str:
    """The side letter of a team (home ``l``, away ``r``)."""
    return SIDES[0] if team == HOME else SIDES[1]


def parking_spot(side_letter: str, unum: int, half_width: float) -> tuple[float, float]:
    """Where rcssserver shows an absent player (``Player::disable``), in its frame:
    3 m per shirt number from the halfway line on the side's own half, 3 m beyond the
    touch line at y < 0."""
    sign = -1.0 if side_letter == SIDES[0] else 1.0
    return sign * PARKING_SPACING * unum, -(half_width + PARKING_OFFSET)


def play_mode_name(mode: PlayMode, team: int, free_kick: str = "indirect_free_kick") -> str:
    """rcssserver's name of the play mode ``mode`` of ``team`` (the state's ``mode_team``).

    ``free_kick``: what the server calls soccer-sim's FREE_KICK in this case: ``free_kick``
    after offside (rcssserver's restart after ``offside_X``), ``indirect_free_kick`` after a
    back pass or a goalkeeper holding the ball too long. AFTER_GOAL, whose team is the one
    to kick off, is ``goal_X`` of the other (scoring) team; GOALIE_HOLDS is the keeper's
    team's ``free_kick_X``, as rcssserver restarts after a catch."""
    if mode == PlayMode.PLAY_ON:
        return "play_on"
    if mode == PlayMode.TIME_OVER:
        return "time_over"
    if mode == PlayMode.AFTER_GOAL:
        return f"goal_{side(1 - team)}"
    if mode == PlayMode.FREE_KICK:
        return f"{free_kick}_{side(team)}"
    return f"{_SET_PLAY_NAMES[PlayMode(mode)]}_{side(team)}"
