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
