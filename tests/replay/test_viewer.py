"""How a replay looks in the rerun viewer: +y drawn upwards, a pitch readable on light and dark
themes, formation meshes hidden until asked for. Read back from the .rrd files themselves."""

from __future__ import annotations

import numpy as np
import pytest

from soccer_sim import MatchConfig, run_match
from soccer_sim.config import FieldConfig
from soccer_sim.replay import RerunRecorder, read_blueprint, read_replay
from soccer_sim.replay.blueprint import MESH_PATHS
from soccer_sim.replay.field import GRASS_COLOUR

LIGHT_THEME = (255, 255, 255)
"""The background of the viewer's light theme, at its lightest."""


@pytest.fixture(scope="module")
def replays(tmp_path_factory):
    """A short match with a team that draws its formation, recorded with meshes hidden (the
    default) and shown."""
    folder = tmp_path_factory.mktemp("viewer")
    paths = {}
    for meshes in (False, True):
        paths[meshes] = folder / f"meshes-{meshes}.rrd"
        run_match("mmdr", "chaser", seed=2, config=MatchConfig(max_cycles=40),
                  recorders=[RerunRecorder(paths[meshes], formation_meshes=meshes)])
    return paths


def rgba(packed: int) -> tuple[int, int, int, int]:
    """rerun's packed 0xRRGGBBAA colour as (r, g, b, a)."""
    return tuple(int(packed) >> shift & 0xFF for shift in (24, 16, 8, 0))


def contrast(a, b) -> float:
    """The WCAG contrast ratio of two RGB colours (1: none, 21: black on white)."""

    def luminance(colour) -> float:
        c = np.asarray(colour[:3], dtype=float) / 255.0
        c = np.where(c <= 0.03928, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)
        return float(c @ [0.2126, 0.7152, 0.0722])

    high, low = sorted((luminance(a), luminance(b)), reverse=True)
    return (high + 0.05) / (low + 0.05)


def field_view(blueprint: dict) -> str:
    """The blueprint path of the 2-D field view."""
    (view,) = [path for path, values in blueprint.items()
               if values.get("ViewBlueprint:class_identifier") == [["2D"]]]
    return view


def test_world_plus_y_is_drawn_upwards_with_data_in_the_absolute_frame(replays) -> None:
    replay = read_replay(replays[False])
    scale = np.asarray(replay.static_values["/world"]["Transform3D:scale"][0][0])
    np.testing.assert_array_equal(scale, [1.0, -1.0, 1.0])
    # The view's origin is the root, so /world's transform applies (a view ignores the
    # transform of its own origin) and it shows /world.
    blueprint = read_blueprint(replays[False])
    view = field_view(blueprint)
    assert blueprint[view]["ViewBlueprint:space_origin"] == [["/"]]
    assert blueprint[f"{view}/ViewContents"]["ViewContents:query"] == [["/world/**"]]
    # World (+40, +25) in the view's frame; the 2-D view draws +x right and +y down, so a
    # negative y is above the centre: top right, as in the --png picture.
    x, y, _ = scale * [40.0, 25.0, 0.0]
    assert x > 0 and y < 0
    # The recorded positions themselves stay in the absolute frame.
    assert replay.players["home"][0][:, 0].mean() < 0 < replay.players["away"][0][:, 0].mean()


def test_pitch_is_green_under_white_lines_and_ball_on_both_themes(replays) -> None:
    from soccer_sim.replay.recorder import BALL_COLOUR, TEAM_COLOURS

    replay = read_replay(replays[False])
    values = replay.static_values
    grass = values["/world/field/grass"]
    fmt = grass["Image:format"][0][0]
    pixels = np.asarray(grass["Image:buffer"][0][0], dtype=np.uint8).reshape(fmt["height"], fmt["width"], 3)
    assert (pixels == GRASS_COLOUR).all()
    # The image (pixels 0..w, 0..h) stretched over the field and its margin.
    field = FieldConfig()
    low = np.asarray(grass["Transform3D:translation"][0][0][:2])
    size = np.asarray(grass["Transform3D:scale"][0][0][:2]) * [fmt["width"], fmt["height"]]
    half = [field.length / 2 + field.margin, field.width / 2 + field.margin]
    np.testing.assert_allclose(low, np.negative(half))
    np.testing.assert_allclose(low + size, half)
    assert grass["Image:draw_order"][0][0] < -10  # under any other image; lines and points draw above
    lines = [rgba(values[path]["LineStrips2D:colors"][0][0]) for path in ("/world/field/lines", "/world/field/goals")]
    ball = rgba(values["/world/ball"]["Points2D:colors"][0][0])
    assert ball[:3] == BALL_COLOUR
    for colour in lines + [ball]:
        assert contrast(colour, GRASS_COLOUR) >= 4.5, colour  # as for text
    for colour in TEAM_COLOURS:  # set apart by lightness too, not by hue alone (red on green)
        assert contrast(colour, GRASS_COLOUR) >= 1.5, colour
    # Without the grass, pale lines would vanish on the light theme: the grass is what keeps
    # them readable, and the view's background (beyond the margin) is the grass too.
    assert contrast(lines[0], LIGHT_THEME) < 1.5
    blueprint = read_blueprint(replays[False])
    background = blueprint[f"{field_view(blueprint)}/Background"]
    assert rgba(background["Background:color"][0][0])[:3] == GRASS_COLOUR
    assert background["Background:kind"] == [[3]]  # a solid colour, not the theme's


def test_formation_meshes_are_recorded_but_hidden_unless_asked_for(replays) -> None:
    for shown, path in replays.items():
        replay = read_replay(path)
        assert "/world/home/roles/triangulation" in replay.temporal_paths  # recorded either way
        blueprint = read_blueprint(path)
        view = field_view(blueprint)
        hidden = {entity for entity in MESH_PATHS
                  if blueprint.get(f"{view}/ViewContents/overrides{entity}/visualizers", {})
                  .get("EntityBehavior:visible") == [[False]]}
        assert hidden == (set() if shown else set(MESH_PATHS))
        # Nothing else is hidden: players, ball, targets and assignment lines show.
        assert sum(values.get("EntityBehavior:visible") == [[False]] for values in blueprint.values()) == len(hidden)


def test_read_blueprint_refuses_other_files(tmp_path) -> None:
    from soccer_sim.replay import ReplayError

    with pytest.raises(ReplayError, match="no such replay file"):
        read_blueprint(tmp_path / "missing.rrd")
    junk = tmp_path / "junk.rrd"
    junk.write_bytes(b"not a recording")
    with pytest.raises(ReplayError, match="junk.rrd: not a rerun recording"):
        read_blueprint(junk)
