"""The partial-observation model of a match: every player's :class:`~.views.PlayerViews` row each
cycle, and the say/hear channel between the players.

Per cycle ``t`` (:meth:`Observer.observe`, before the teams decide), in the absolute frame:

1. **Body directions** of all players (:func:`~.see.body_directions`, the simulator's one
   model) and the **sensed velocities** (:func:`~.localise.sensed_velocity`).
2. **Self-localisation.** Each player's belief about its own position is advanced by its sensed
   velocity over the player's decay (``pos(t) = pos(t-1) + vel(t) / player_decay``: the
   movement of the last cycle, which every rcssserver client dead-reckons), and replaced by the
   flag estimate (:func:`~.localise.localise`) on cycles with a see. A player starts the match
   knowing where it stands (as a client knows where it moved itself).
3. **Sees** for the players whose see arrives in cycle ``t`` (:func:`~.params.see_cycles`; each
   player's see phase, ``offset_ms`` in ``[0, send_step)``, is drawn at the start of the match,
   as rcssserver's clients connect at different moments): :func:`~.see.see` over the ball and
   all players on the pitch (players sent off are neither seen nor see); the reported polar
   coordinates are turned into positions with the player's own belief.
4. **Hear**: the messages said at ``t - 1`` (:class:`~.audio.AudioChannel`).

Each player looks along its face, the body direction plus its neck angle (:mod:`.neck`: 0 at
the start, so a player that never turns its neck looks along its body), with the cone and the
pace of sees of its view width (:mod:`.view_width`: ``normal`` at the start). After the teams
decide, :meth:`Observer.say` records their messages with the positions at ``t``, and
:meth:`Observer.turn_necks` and :meth:`Observer.change_views` their ``turn_neck`` and
``change_view``, which the sees from ``t + 1`` on look through. All randomness (see phases,
identity drops, the hearing order) comes from the one
generator the match gives the observer, in a fixed order, so a match stays a pure function of
its inputs. Nothing here runs under full observation.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from soccer_sim.perception.audio import AudioChannel
from soccer_sim.perception.config import ObservationConfig
from soccer_sim.perception.kernels import ObserverRows, Perception, TrueBodies, perceive, see_record, senses_into
from soccer_sim.perception.localise import DEFAULT_FLAGS
from soccer_sim.perception.neck import turned_necks
from soccer_sim.perception.view_width import KEEP, NORMAL, SeeTimer, view_angles
from soccer_sim.perception.params import see_cycles
from soccer_sim.perception.views import HeardLog, PlayerViews
from soccer_sim.state import WorldState


class Observer:
    """Builds both teams' :class:`PlayerViews` each cycle of a partially observed match.

    ``sizes``: (home, away) players; ``decay``: (P,) each player row's ``player_decay`` (its
    player type's); ``type_ids``: (P,) each row's player type; ``rng``: the observer's own
    generator."""

    def __init__(self, config: ObservationConfig, sizes: tuple[int, int], team_names: tuple[str, str],
                 decay: np.ndarray, inertia: np.ndarray, type_ids: np.ndarray, rng: np.random.Generator) -> None:
        self.params = params = config.see
        self.sizes = sizes
        total = sizes[0] + sizes[1]
        self._total = total
        self._rng = rng
        self._prm = see_record(params)
        self.offsets_ms = rng.integers(0, int(params.send_step), total)
        """(P,) each player's see phase (ms)."""
        send, sim = int(params.send_step), int(params.simulator_step)
        period = math.lcm(send, sim) // sim
        self._see_table = see_cycles(np.arange(period)[:, None], params, self.offsets_ms[None, :])
        self.channel = AudioChannel(sizes, team_names, config.audio)
        team = np.repeat(np.array([0, 1], dtype=np.int64), sizes)
        self._constants = ObserverRows(inertia=np.ascontiguousarray(inertia, dtype=np.float64),
                                       decay=np.ascontiguousarray(decay, dtype=np.float64), team=team,
                                       first=np.where(team == 0, 0, sizes[0]).astype(np.int64))
        """Each player row's constants for :func:`~.kernels.perceive`."""
        self._belief = np.zeros((total, 2))
        self.necks = np.zeros(total)
        """(P,) each player's neck angle (degrees relative to its body; :meth:`turn_necks`)."""
        self.half_angles = np.full(total, params.visible_angle / 2.0)
        """(P,) half of each player's view cone (degrees; its view width's, :meth:`change_views`)."""
        self._timer: SeeTimer | None = None
        """The players' see timers once a player has changed its view width (until then every
        player sees at ``normal``'s pace, the table above)."""
        self._started = False
        self._half = 0
        k = max(total - 1, 0)
        # The views' arrays: written in place every cycle (team frames), windows per team below.
        self._out = out = dict(
            stamina=np.empty(total), effort=np.empty(total), capacity=np.empty(total),
            frozen=np.empty(total, dtype=np.int64), cards=np.zeros(total, dtype=np.int64),
            present=np.empty(total, dtype=bool),
            holds_ball=np.zeros(total, dtype=bool), position=np.empty((total, 2)), velocity=np.empty((total, 2)),
            body_direction=np.empty(total), neck_angle=np.empty(total),
            view_width=np.full(total, NORMAL, dtype=np.int64), localised=np.empty(total, dtype=bool),
            saw=np.empty(total, dtype=bool),
            ball_seen=np.empty(total, dtype=bool), ball=np.empty((total, 2)), ball_distance=np.empty(total),
            ball_direction=np.empty(total), seen_count=np.empty(total, dtype=np.int64),
            seen_position=np.empty((total, k, 2)), seen_distance=np.empty((total, k)),
            seen_direction=np.empty((total, k)), seen_side=np.empty((total, k), dtype=np.int8),
            seen_number=np.empty((total, k), dtype=np.int8))
        self.seen_rows = np.empty((total, k), dtype=np.int64)
        """(P, K) the player row of each player seen in the last cycle's lists (-1 padding): the
        truth behind the views, for tests and statistics."""
        self._perception = Perception(seen_rows=self.seen_rows,
                                      **{name: out[name] for name in Perception._fields if name != "seen_rows"})
        """The arrays :func:`~.kernels.perceive` writes each cycle."""
        rows = self._rows = (slice(0, sizes[0]), slice(sizes[0], total))
        """Each team's rows (home, away)."""
        self.views = tuple(PlayerViews(player_types=np.asarray(type_ids[r]).copy(),
                                       **{name: array[r] for name, array in out.items()}) for r in rows)
        """(home, away) views; :meth:`observe` refreshes them."""

    # ------------------------------------------------------------------------------------
    def observe(self, state: WorldState) -> tuple[PlayerViews, PlayerViews]:
        """Every player's perception at ``state.cycle`` (module docstring), as (home, away) views."""
        out = self._out
        if state.half != self._half:
            self._half = state.half
            self.channel.reset_capacity()
        present = state.present
        seeing = out["saw"]
        if self._timer is None:
            np.logical_and(self._see_table[state.cycle % len(self._see_table)], present, out=seeing)
        else:
            np.logical_and(self._timer.sees(state.cycle, seeing), present, out=seeing)
        if not self._started:
            self._belief[:] = state.pos  # a player knows where it starts
        uniforms = self._rng.random((2, int(np.count_nonzero(seeing)), self._total + 1))
        perceive(TrueBodies(state.pos, state.vel, state.ball, present, self.necks, self.half_angles), seeing, uniforms,
                 self._started, float(state.home_attacks), self._constants, DEFAULT_FLAGS, self._prm, self._belief,
                 self._perception)
        self._started = True
        senses_into(state.stamina, state.effort, state.capacity, state.frozen, present, int(state.ball_holder),
                    out["stamina"], out["effort"], out["capacity"], out["frozen"], out["present"], out["holds_ball"])
        out["cards"][:] = state.cards
        _, heard, messages = self.channel.deliver(state.cycle, self._rng)
        score = state.score.tolist()
        for team, view in enumerate(self.views):
            r, other = self._rows[team], self._rows[1 - team]
            view.cycle, view.half, view.play_mode = state.cycle, state.half, state.play_mode
            view.mode_ours = state.mode_team == team
            view.score = (score[team], score[1 - team])
            view.heard_mates = HeardLog(heard[r, r], messages[r], named=True)
            view.heard_opponents = HeardLog(heard[r, other], messages[other], named=False)
        return self.views

    def say(self, cycle: int, messages: Sequence[Sequence[str | None]], positions: np.ndarray,
            checked: bool = False) -> None:
        """Record the messages both teams say at ``cycle`` (``messages[team][i]``, str or None),
        with the players' ``positions`` (P, 2) m at ``cycle``; a bad one is a ``TeamError``
        (``checked``: :meth:`AudioChannel.say`'s, the caller checked them)."""
        self.channel.say(cycle, messages, positions, checked)

    def turn_necks(self, moments: np.ndarray, present: np.ndarray) -> None:
        """Apply every player's ``(turn_neck MOMENT)`` of this cycle: ``moments`` (P,) degrees
        (NaN or 0: none), the players on the pitch (``present`` (P,)) only, by rcssserver's rule
        (:func:`~.neck.turned_necks`)."""
        turned = turned_necks(self.necks, moments, self.params)
        np.copyto(self.necks, turned, where=np.asarray(present, dtype=bool))

    def change_views(self, cycle: int, widths: np.ndarray, present: np.ndarray) -> None:
        """Apply every player's ``(change_view WIDTH)`` asked at ``cycle``: ``widths`` (P,) codes
        (:data:`~.view_width.KEEP` for none), the players on the pitch only; the cone and the
        pace of the sees change from cycle ``cycle + 1`` on (:mod:`.view_width`)."""
        asked = np.where(np.asarray(present, dtype=bool), widths, KEEP)
        if self._timer is None:
            if not ((asked != KEEP) & (asked != NORMAL)).any():
                return
            self._timer = SeeTimer(self.params, self.offsets_ms, cycle + 1)
        self._timer.change(asked, cycle + 1)
        self._out["view_width"][:] = self._timer.widths
        self.half_angles[:] = view_angles(self._timer.widths, self.params) / 2.0
