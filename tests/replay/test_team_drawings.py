"""The optional ``drawing()`` hook: a replay draws what a Drawable team returns, and a team whose
hook misbehaves gets a TeamError naming it."""

from __future__ import annotations

import numpy as np
import pytest

from soccer_sim import MatchConfig, TeamError, run_match
from soccer_sim.replay import RerunRecorder, read_replay
from soccer_sim.team_hooks import Drawable, Drawing
from soccer_sim.trivial_teams import ChaserTeam

N = 11
TARGETS = np.column_stack([np.linspace(-40.0, 40.0, N), np.linspace(-20.0, 20.0, N)])
"""Role targets in the team's frame (it attacks +x)."""
OUTFIELD = np.arange(1, N)
TRIANGLES = np.array([[0, 1, 2], [1, 2, 3]], dtype=np.int32)


class DrawingChaser(ChaserTeam):
    """A chaser that draws fixed role targets, player i assigned role i, and a two-triangle mesh."""

    name = "drawer"

    def drawing(self) -> Drawing:
        return Drawing(targets=TARGETS, goals=TARGETS, outfield=OUTFIELD, role_of_player=OUTFIELD - 1,
                       assigned_targets=TARGETS[1:], formation_balls=TARGETS[:4],
                       formation_triangles=TRIANGLES)


def test_a_drawable_teams_targets_and_assignment_are_recorded(tmp_path) -> None:
    assert isinstance(DrawingChaser(), Drawable) and not isinstance(ChaserTeam(), Drawable)
    path = tmp_path / "drawn.rrd"
    trajectory = []

    class Positions:
        def on_start(self, match):
            self.on_cycle(match)

        def on_cycle(self, match):
            trajectory.append((match.state.pos.copy(), match.state.home_attacks))

        def on_end(self, match):
            pass

    run_match("idle", DrawingChaser(), seed=2, config=MatchConfig(max_cycles=30),
              recorders=[Positions(), RerunRecorder(path, flush_every=7)])
    replay = read_replay(path)
    assert "away" in replay.targets and "home" not in replay.targets  # only the Drawable team draws
    assert len(replay.targets["away"]) == len(replay.cycles) == 31
    for k in (0, 6, 7, 30):
        pos, home_attacks = trajectory[k]
        sign = -home_attacks  # the away team's frame to the absolute frame
        np.testing.assert_allclose(replay.targets["away"][k], (sign * TARGETS).astype(np.float32))
        lines = replay.lines["away"][k]  # (10, 2, 2): from each outfield player to its role's target
        np.testing.assert_allclose(lines[:, 0], pos[N + OUTFIELD].astype(np.float32), atol=1e-5)
        np.testing.assert_allclose(lines[:, 1], (sign * TARGETS[1:]).astype(np.float32), atol=1e-4)
    assert "/world/away/roles/triangulation" in replay.temporal_paths


class ChangingDrawer(ChaserTeam):
    """Draws targets that move by 1 m a cycle; from cycle ``fewer`` on only six roles, and
    assigned targets only from cycle ``assigned_from`` on (so buffers change shape mid-block)."""

    def __init__(self, name: str, fewer: int, assigned_from: int) -> None:
        self.name, self.fewer, self.assigned_from = name, fewer, assigned_from
        self.cycles = 0

    def act(self, view):
        self.cycles += 1
        return super().act(view)

    def targets(self, cycle: int) -> np.ndarray:
        return (TARGETS if cycle < self.fewer else TARGETS[:6]) + cycle

    def drawing(self) -> Drawing:
        targets = self.targets(self.cycles)
        assigned = targets[1:] if self.cycles >= self.assigned_from else None
        return Drawing(targets=targets, goals=targets, outfield=np.arange(1, len(targets)),
                       assigned_targets=assigned)


def test_drawings_that_change_shape_mid_block_are_recorded_cycle_by_cycle(tmp_path) -> None:
    home, away = ChangingDrawer("home-drawer", 9, 3), ChangingDrawer("away-drawer", 5, 12)
    path = tmp_path / "changing.rrd"
    result = run_match(home, away, seed=1, config=MatchConfig(max_cycles=20),
                       recorders=[RerunRecorder(path, flush_every=8)])
    replay = read_replay(path)
    attacks = {"home": 1.0, "away": -1.0} if result.state.home_attacks == 1 else {"home": -1.0, "away": 1.0}
    for key, team in (("home", home), ("away", away)):
        assert len(replay.targets[key]) == 21
        for cycle, drawn in enumerate(replay.targets[key]):
            np.testing.assert_allclose(drawn, (attacks[key] * team.targets(cycle)).astype(np.float32), rtol=1e-6)
        lines = replay.lines[key]
        assert [len(lines[c]) for c in range(21)] == [0 if c < team.assigned_from else len(team.targets(c)) - 1
                                                      for c in range(21)]


@pytest.mark.parametrize("drawn, message", [
    ({"targets": TARGETS, "outfield": OUTFIELD}, r"drawing\(\) must return a soccer_sim.team_hooks.Drawing, got dict"),
    (None, r"drawing\(\) must return a soccer_sim.team_hooks.Drawing, got NoneType"),
    (ValueError("no formation"), r"drawing\(\) failed with ValueError: no formation"),
])
def test_a_drawing_that_is_not_a_drawing_names_the_team(tmp_path, drawn, message) -> None:
    class Broken(ChaserTeam):
        name = "sketchy"

        def drawing(self):
            if isinstance(drawn, Exception):
                raise drawn
            return drawn

    with pytest.raises(TeamError, match=rf"team 'sketchy': {message}") as info:
        run_match(Broken(), "idle", config=MatchConfig(max_cycles=3), recorders=[RerunRecorder(tmp_path / "x.rrd")])
    assert info.value.team_name == "sketchy"


def test_drawings_can_be_left_out(tmp_path) -> None:
    path = tmp_path / "plain.rrd"
    run_match(DrawingChaser(), "idle", config=MatchConfig(max_cycles=5),
              recorders=[RerunRecorder(path, drawings=False)])
    assert read_replay(path).targets == {}


def test_a_drawing_holds_arrays_of_the_documented_shapes() -> None:
    drawing = Drawing(targets=[[1, 2], [3, 4]], goals=TARGETS, outfield=[1, 2], formation_triangles=TRIANGLES)
    assert drawing.targets.dtype == np.float64 and drawing.outfield.dtype.kind == "i"
    assert drawing.goals is TARGETS and drawing.formation_triangles is TRIANGLES  # arrays are kept, not copied
    assert drawing.assigned_targets is None and drawing.formation_balls is None
    with pytest.raises(ValueError, match=r"Drawing.targets must have shape \(n, 2\), got \(11, 3\)"):
        Drawing(targets=np.zeros((N, 3)), goals=TARGETS, outfield=OUTFIELD)
    with pytest.raises(ValueError, match=r"Drawing.formation_triangles must have shape \(n, 3\), got \(6,\)"):
        Drawing(targets=TARGETS, goals=TARGETS, outfield=OUTFIELD, formation_triangles=np.arange(6))
    with pytest.raises(ValueError, match="Drawing.goals is required"):
        Drawing(targets=TARGETS, goals=None, outfield=OUTFIELD)
