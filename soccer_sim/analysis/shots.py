"""How shots end: in the goal, in the goalkeeper's hands, out, played on, or on a body.

A shot (a SHOT event of detail 0, :mod:`soccer_sim.analysis.plays`) ends at the first of the
following events after it: the next KICK or TACKLE (someone played the ball on), a TOUCH (the
ball bounced off a player's body: the shot was blocked), a CATCH, a GOAL or an OUT. Shots recorded for a goal (detail 1)
are left out: they are known to end in the goal. Read from the event log after the match.
"""

from __future__ import annotations

from soccer_sim.state import EventKind, EventLog

ENDINGS = {EventKind.KICK: "played on", EventKind.TACKLE: "played on", EventKind.TOUCH: "body",
           EventKind.CATCH: "caught", EventKind.GOAL: "goal", EventKind.OUT: "out"}
"""The events that end a shot, and what the ending is called."""


def shot_endings(events: EventLog) -> list[tuple[int, str]]:
    """For each shot (detail 0) in ``events``, in order: (the shooting team, how it ended: one of
    :data:`ENDINGS`' values, or ``"unfinished"`` when the match ended first)."""
    kinds, details, teams = events.kind, events.detail, events.team
    endings = []
    for i, kind in enumerate(kinds):
        if kind != EventKind.SHOT or details[i] != 0:
            continue
        ending = "unfinished"
        for later in kinds[i + 1:]:
            if later in ENDINGS:
                ending = ENDINGS[EventKind(later)]
                break
        endings.append((int(teams[i]), ending))
    return endings
